// SPDX-License-Identifier: MIT
#include "fddem/grid/halo_exchange.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/box_values.hpp"
#include "fddem/grid/loops.hpp"

#include <optional>
#include <vector>

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

// Along an axis split across ranks, with the block [lo, hi) and storage [lo − g, hi + 1 + g)
// (g = n_ghost), every array (cells and faces alike) has the same layers:
//
//   ghosts below  [lo − g, lo)      images of the rank below's   [hi' − g, hi')
//   ghosts above  [hi, hi + g + 1)  images of the rank above's   [lo', lo' + g + 1)
//
// (hi' of the rank below is lo; lo' of the rank above is hi; across a periodic side the two
// differ by n.) A face array normal to the axis owns face hi only at the domain's bounded high
// side, where there is no rank above. So fill sends [lo, lo + g + 1) down and [hi − g, hi) up,
// and accumulate sends the ghosts back and adds them there. Neighbours along an axis share
// their blocks' extent along the other axes, hence the same layer shape.
constexpr int layers_below = MacGrid<2>::n_ghost;
constexpr int layers_above = MacGrid<2>::n_ghost + 1;
static_assert(layers_above <= min_block_cells, "a halo must come from the nearest block");

enum Tag : int { fill_down = 11, fill_up = 12, sum_up = 13, sum_down = 14 };

/// The storage box cut to layers [first, first + count) along `axis`.
template <int Dim>
Box<Dim> layers(const MacGrid<Dim>& grid, int axis, int first, int count)
{
    Box<Dim> box = grid.storage_box();
    box.lo[static_cast<std::size_t>(axis)] = first;
    box.hi[static_cast<std::size_t>(axis)] = first + count;
    return box;
}

template <int Dim>
void add(GridArray<Dim>& a, const Box<Dim>& box, const std::vector<double>& buffer)
{
    std::size_t k = 0;
    for_each_cell_in_vtk_order(box, [&](const Index<Dim>& i) { a(i) += buffer[k++]; });
}

/// The four layer boxes of a split axis.
template <int Dim>
struct SplitLayers {
    Box<Dim> ghosts_below, ghosts_above, first_owned, last_owned;
};

template <int Dim>
SplitLayers<Dim> split_layers(const MacGrid<Dim>& grid, int axis)
{
    const auto& block = grid.owned_cells();
    const int lo = block.lo[static_cast<std::size_t>(axis)];
    const int hi = block.hi[static_cast<std::size_t>(axis)];
    return {layers(grid, axis, lo - layers_below, layers_below),
            layers(grid, axis, hi, layers_above), layers(grid, axis, lo, layers_above),
            layers(grid, axis, hi - layers_below, layers_below)};
}

/// The layers of fill_faces along `axis`: one ghost layer below and above the owned cells and
/// the owned layers they are images of, each over the owned cells' extent along the other axes.
template <int Dim>
SplitLayers<Dim> face_layers(const MacGrid<Dim>& grid, int axis)
{
    const Box<Dim>& block = grid.owned_cells();
    const auto ax = static_cast<std::size_t>(axis);
    const auto layer = [&](int at) {
        Box<Dim> box = block;
        box.lo[ax] = at;
        box.hi[ax] = at + 1;
        return box;
    };
    return {layer(block.lo[ax] - 1), layer(block.hi[ax]), layer(block.lo[ax]),
            layer(block.hi[ax] - 1)};
}

/// a(to) ← a(from), two boxes of the same shape (the periodic images of fill_faces_axis).
template <int Dim>
void copy_box(GridArray<Dim>& a, const Box<Dim>& from, const Box<Dim>& to)
{
    const Index<Dim> shift = from.lo - to.lo;
    for_each_cell_in_vtk_order(to, [&](const Index<Dim>& i) { a(i) = a(i + shift); });
}

/// Each rank sends `l.first_owned` down and `l.last_owned` up and receives its ghosts
/// `l.ghosts_above` and `l.ghosts_below` from the ranks there.
template <int Dim>
void exchange_layers(const MacGrid<Dim>& grid, int axis, const SplitLayers<Dim>& l,
                     GridArray<Dim>& a)
{
    const auto [below, above] = grid.partition().neighbours[static_cast<std::size_t>(axis)];
    const auto& comm = grid.communicator();
    std::vector<double> from_above(above == Communicator::no_rank ? 0 : l.ghosts_above.size());
    comm.exchange(pack(a, l.first_owned), below, from_above, above, fill_down);
    std::vector<double> from_below(below == Communicator::no_rank ? 0 : l.ghosts_below.size());
    comm.exchange(pack(a, l.last_owned), above, from_below, below, fill_up);
    if (above != Communicator::no_rank) {
        unpack(a, l.ghosts_above, from_above);
    }
    if (below != Communicator::no_rank) {
        unpack(a, l.ghosts_below, from_below);
    }
}

template <int Dim>
void fill_split_axis(const MacGrid<Dim>& grid, int axis, GridArray<Dim>& a)
{
    exchange_layers(grid, axis, split_layers(grid, axis), a);
}

template <int Dim>
void zero(GridArray<Dim>& a, const Box<Dim>& box)
{
    for_each_cell_in_vtk_order(box, [&](const Index<Dim>& i) { a(i) = 0.0; });
}

template <int Dim>
void accumulate_split_axis(const MacGrid<Dim>& grid, int axis, GridArray<Dim>& a)
{
    const auto [below, above] = grid.partition().neighbours[static_cast<std::size_t>(axis)];
    const auto& comm = grid.communicator();
    const SplitLayers<Dim> l = split_layers(grid, axis);
    // Both ghost regions are packed and cleared before anything is added: with a thin block
    // the owned layers they are added to overlap.
    std::vector<double> up;
    std::vector<double> down;
    if (above != Communicator::no_rank) {
        up = pack(a, l.ghosts_above);
        zero(a, l.ghosts_above);
    }
    if (below != Communicator::no_rank) {
        down = pack(a, l.ghosts_below);
        zero(a, l.ghosts_below);
    }
    std::vector<double> from_below(below == Communicator::no_rank ? 0 : l.first_owned.size());
    comm.exchange(up, above, from_below, below, sum_up);
    std::vector<double> from_above(above == Communicator::no_rank ? 0 : l.last_owned.size());
    comm.exchange(down, below, from_above, above, sum_down);
    if (below != Communicator::no_rank) {
        add(a, l.first_owned, from_below);
    }
    if (above != Communicator::no_rank) {
        add(a, l.last_owned, from_above);
    }
}

template <int Dim>
void zero_split_axis(const MacGrid<Dim>& grid, int axis, GridArray<Dim>& a)
{
    const auto [below, above] = grid.partition().neighbours[static_cast<std::size_t>(axis)];
    const SplitLayers<Dim> l = split_layers(grid, axis);
    if (above != Communicator::no_rank) {
        zero(a, l.ghosts_above);
    }
    if (below != Communicator::no_rank) {
        zero(a, l.ghosts_below);
    }
}

/// Every ghost across the periodic sides of `axis` takes its owner's value (one process along
/// that axis). With a `plane` (an index along Dim − 1), only the ghosts of that slice, serially:
/// a wavefront refreshes one slice on one thread while the others wait.
template <int Dim>
void copy_periodic_images(const MacGrid<Dim>& grid, int axis, GridArray<Dim>& a,
                          std::optional<int> plane)
{
    for_each_ghost_layer(grid, axis, [&](Box<Dim> layer, int owner) {
        const auto copy = [&](const Index<Dim>& i) { a(i) = a(with_axis(i, axis, owner)); };
        if (!plane) {
            for_each_index(layer, copy);
            return;
        }
        constexpr auto outer = static_cast<std::size_t>(Dim - 1);
        layer.lo[outer] = *plane;
        layer.hi[outer] = *plane + 1;
        for_each_cell_in_vtk_order(layer, copy);
    });
}

} // namespace

template <int Dim>
void HaloExchange<Dim>::fill(GridArray<Dim>& a) const
{
    for (int d = 0; d < Dim; ++d) {
        fill_axis(a, d);
    }
}

template <int Dim>
void HaloExchange<Dim>::fill_faces(GridArray<Dim>& a) const
{
    for (int d = 0; d < Dim; ++d) {
        fill_faces_axis(a, d);
    }
}

template <int Dim>
void HaloExchange<Dim>::fill_faces_axis(GridArray<Dim>& a, int d) const
{
    const SplitLayers<Dim> l = face_layers(*grid_, d);
    if (grid_->is_split(d)) {
        exchange_layers(*grid_, d, l, a);
        return;
    }
    if (grid_->is_periodic(d)) {
        // One process along d: its owned layers are the whole axis, their images in place.
        copy_box(a, l.last_owned, l.ghosts_below);
        copy_box(a, l.first_owned, l.ghosts_above);
    }
}

template <int Dim>
bool HaloExchange<Dim>::keeps_slices_apart() const
{
    for (int d = 0; d < Dim - 1; ++d) {
        if (grid_->is_split(d)) {
            return false;
        }
    }
    return true;
}

template <int Dim>
void HaloExchange<Dim>::fill_plane(GridArray<Dim>& a, int plane) const
{
    if (!keeps_slices_apart()) {
        throw InternalError("HaloExchange::fill_plane: a slice's images are on other ranks");
    }
    for (int d = 0; d < Dim - 1; ++d) {
        if (grid_->is_periodic(d)) {
            copy_periodic_images(*grid_, d, a, plane);
        }
    }
}

template <int Dim>
void HaloExchange<Dim>::fill_axis(GridArray<Dim>& a, int d) const
{
    if (grid_->is_split(d)) {
        fill_split_axis(*grid_, d, a);
        return;
    }
    if (grid_->is_periodic(d)) {
        copy_periodic_images(*grid_, d, a, std::nullopt);
    }
}

template <int Dim>
void HaloExchange<Dim>::accumulate(GridArray<Dim>& a) const
{
    // The adjoint of fill's axis-by-axis copies: the same steps transposed, in reverse order.
    for (int d = Dim - 1; d >= 0; --d) {
        if (grid_->is_split(d)) {
            accumulate_split_axis(*grid_, d, a);
            continue;
        }
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
        if (grid_->is_split(d)) {
            zero_split_axis(*grid_, d, a);
            continue;
        }
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
