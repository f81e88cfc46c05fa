// SPDX-License-Identifier: MIT
#include "fddem/grid/halo_exchange.hpp"

#include "fddem/grid/loops.hpp"

namespace fddem {
namespace {

/// Calls f(layer, owner_layer) for every ghost layer of the periodic `axis`, low layers first,
/// each with the layer (storage box one index thick) and the index of the owned layer it is an
/// image of. One layer at a time: with fewer cells than ghost layers, several ghost layers
/// share an owner, and the order stays fixed.
template <int Dim, class F>
void for_each_ghost_layer(const MacGrid<Dim>& grid, int axis, F&& f)
{
    const auto ax = static_cast<std::size_t>(axis);
    const int n = grid.cells(axis);
    const Box<Dim> storage = grid.storage_box();
    for (int layer = storage.lo[ax]; layer < storage.hi[ax]; ++layer) {
        if (layer >= 0 && layer < n) {
            continue;
        }
        Box<Dim> box = storage;
        box.lo[ax] = layer;
        box.hi[ax] = layer + 1;
        f(box, ((layer % n) + n) % n);
    }
}

} // namespace

template <int Dim>
void HaloExchange<Dim>::fill(GridArray<Dim>& a) const
{
    for (int d = 0; d < Dim; ++d) {
        if (!grid_->is_periodic(d)) {
            continue;
        }
        for_each_ghost_layer(*grid_, d, [&](const Box<Dim>& layer, int owner) {
            for_each_index(layer, [&](const Index<Dim>& i) { a(i) = a(with_axis(i, d, owner)); });
        });
    }
}

template <int Dim>
void HaloExchange<Dim>::accumulate(GridArray<Dim>& a) const
{
    // The adjoint of fill's axis-by-axis copies: the same steps transposed, in reverse order.
    for (int d = Dim - 1; d >= 0; --d) {
        if (!grid_->is_periodic(d)) {
            continue;
        }
        for_each_ghost_layer(*grid_, d, [&](const Box<Dim>& layer, int owner) {
            for_each_index(layer, [&](const Index<Dim>& i) {
                a(with_axis(i, d, owner)) += a(i);
                a(i) = 0.0;
            });
        });
    }
}

template <int Dim>
void HaloExchange<Dim>::zero_ghosts(GridArray<Dim>& a) const
{
    for (int d = 0; d < Dim; ++d) {
        if (!grid_->is_periodic(d)) {
            continue;
        }
        for_each_ghost_layer(*grid_, d, [&](const Box<Dim>& layer, int /*owner*/) {
            for_each_index(layer, [&](const Index<Dim>& i) { a(i) = 0.0; });
        });
    }
}

template <int Dim>
void HaloExchange<Dim>::fill(FaceField<Dim>& u) const
{
    for (int a = 0; a < Dim; ++a) {
        fill(u[a]);
    }
}

template <int Dim>
void HaloExchange<Dim>::accumulate(FaceField<Dim>& u) const
{
    for (int a = 0; a < Dim; ++a) {
        accumulate(u[a]);
    }
}

template <int Dim>
void HaloExchange<Dim>::zero_ghosts(FaceField<Dim>& u) const
{
    for (int a = 0; a < Dim; ++a) {
        zero_ghosts(u[a]);
    }
}

template class HaloExchange<2>;
template class HaloExchange<3>;

} // namespace fddem
