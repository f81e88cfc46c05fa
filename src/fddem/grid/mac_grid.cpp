// SPDX-License-Identifier: MIT
#include "fddem/grid/mac_grid.hpp"

#include "fddem/core/errors.hpp"

#include <string>
#include <utility>

namespace fddem {

template <int Dim>
MacGrid<Dim>::MacGrid(const Index<Dim>& cells, const Vec<Dim>& origin, const Vec<Dim>& length,
                      const std::array<bool, Dim>& is_periodic)
    : MacGrid(cells, origin, length, is_periodic, whole_grid<Dim>(cells, is_periodic))
{
}

template <int Dim>
MacGrid<Dim>::MacGrid(const Index<Dim>& cells, const Vec<Dim>& origin, const Vec<Dim>& length,
                      const std::array<bool, Dim>& is_periodic, GridPartition<Dim> partition)
    : cells_(cells), origin_(origin), length_(length), is_periodic_(is_periodic),
      partition_(std::move(partition)), cell_volume_(1.0), storage_size_(1)
{
    for (int d = 0; d < Dim; ++d) {
        if (cells_[ax(d)] < 1 || !(length_[d] > 0.0)) {
            throw InternalError("MacGrid: axis " + std::to_string(d) +
                                " needs at least one cell and a positive length");
        }
        const auto& block = partition_.block;
        if (block.lo[ax(d)] < 0 || block.hi[ax(d)] > cells_[ax(d)] ||
            block.hi[ax(d)] <= block.lo[ax(d)]) {
            throw InternalError("MacGrid: the block does not lie in the grid along axis " +
                                std::to_string(d));
        }
        spacing_[d] = length_[d] / cells_[ax(d)];
        cell_volume_ *= spacing_[d];
    }
    const Box<Dim> storage = storage_box();
    storage_lo_ = storage.lo;
    for (int d = 0; d < Dim; ++d) {
        stride_[ax(d)] = static_cast<std::ptrdiff_t>(storage_size_);
        storage_size_ *= static_cast<std::size_t>(storage.extent(d));
    }
}

template <int Dim>
Vec<Dim> MacGrid<Dim>::cell_centre(const Index<Dim>& cell) const noexcept
{
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) {
        x[d] = origin_[d] + (cell[ax(d)] + 0.5) * spacing_[d];
    }
    return x;
}

template <int Dim>
Vec<Dim> MacGrid<Dim>::face_centre(int axis, const Index<Dim>& cell) const noexcept
{
    Vec<Dim> x = cell_centre(cell);
    x[axis] -= 0.5 * spacing_[axis];
    return x;
}

template class MacGrid<2>;
template class MacGrid<3>;

} // namespace fddem
