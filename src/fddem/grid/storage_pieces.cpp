// SPDX-License-Identifier: MIT
#include "fddem/grid/storage_pieces.hpp"

#include "fddem/grid/loops.hpp"

#include <algorithm>

namespace fddem {

template <int Dim>
Box<Dim> contributed_box(const MacGrid<Dim>& grid) noexcept
{
    Box<Dim> box = grid.owned_cells();
    const Box<Dim> storage = grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        if (grid.partition().coords[sd] == 0) {
            box.lo[sd] = storage.lo[sd];
        }
        if (grid.partition().coords[sd] + 1 == grid.partition().ranks[sd]) {
            box.hi[sd] = storage.hi[sd];
        }
    }
    return box;
}

template <int Dim>
Box<Dim> intersection(const Box<Dim>& a, const Box<Dim>& b) noexcept
{
    Box<Dim> common;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        common.lo[d] = std::max(a.lo[d], b.lo[d]);
        common.hi[d] = std::max(common.lo[d], std::min(a.hi[d], b.hi[d]));
    }
    return common;
}

template <int Dim>
std::size_t take_overlap(const MacGrid<Dim>& grid, const Box<Dim>& piece,
                         std::span<const double> values, GridArray<Dim>& part)
{
    const Box<Dim> common = intersection(piece, grid.storage_box());
    // The place of index i among the piece's values, x fastest.
    std::array<std::size_t, Dim> stride{};
    std::size_t n = 1;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        stride[d] = n;
        n *= static_cast<std::size_t>(piece.extent(static_cast<int>(d)));
    }
    std::size_t taken = 0;
    for_each_cell_in_vtk_order(common, [&](const Index<Dim>& i) {
        std::size_t k = 0;
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
            k += static_cast<std::size_t>(i[d] - piece.lo[d]) * stride[d];
        }
        part(i) = values[k];
        ++taken;
    });
    return taken;
}

template Box<2> contributed_box<2>(const MacGrid<2>&) noexcept;
template Box<3> contributed_box<3>(const MacGrid<3>&) noexcept;
template Box<2> intersection<2>(const Box<2>&, const Box<2>&) noexcept;
template Box<3> intersection<3>(const Box<3>&, const Box<3>&) noexcept;
template std::size_t take_overlap<2>(const MacGrid<2>&, const Box<2>&, std::span<const double>,
                                     GridArray<2>&);
template std::size_t take_overlap<3>(const MacGrid<3>&, const Box<3>&, std::span<const double>,
                                     GridArray<3>&);

} // namespace fddem
