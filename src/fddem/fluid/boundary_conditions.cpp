// SPDX-License-Identifier: MIT
#include "fddem/fluid/boundary_conditions.hpp"

#include "fddem/grid/loops.hpp"

namespace fddem {
namespace {

/// The storage box with axis `axis` restricted to [lo, hi).
template <int Dim>
Box<Dim> slab(const MacGrid<Dim>& grid, int axis, int lo, int hi)
{
    Box<Dim> box = grid.storage_box();
    box.lo[static_cast<std::size_t>(axis)] = lo;
    box.hi[static_cast<std::size_t>(axis)] = hi;
    return box;
}

/// Periodic images along `axis`: every index outside [0, n) takes the value at index mod n.
template <int Dim>
void wrap_periodic(const MacGrid<Dim>& grid, int axis, GridArray<Dim>& a)
{
    const int n = grid.cells(axis);
    const Box<Dim> storage = grid.storage_box();
    const auto ax = static_cast<std::size_t>(axis);
    const auto copy = [&](const Index<Dim>& i) {
        const int m = ((i[ax] % n) + n) % n;
        a(i) = a(with_axis(i, axis, m));
    };
    for_each_index(slab(grid, axis, storage.lo[ax], 0), copy);
    for_each_index(slab(grid, axis, n, storage.hi[ax]), copy);
}

} // namespace

template <int Dim>
void fill_velocity_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          FaceField<Dim>& u)
{
    const Box<Dim> storage = grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        const auto ax = static_cast<std::size_t>(d);
        const int n = grid.cells(d);
        for (int a = 0; a < Dim; ++a) {
            GridArray<Dim>& ua = u[a];
            if (bc.periodic(d)) {
                wrap_periodic(grid, d, ua);
                continue;
            }
            const double low = bc.wall(d, 0)[a];
            const double high = bc.wall(d, 1)[a];
            if (a == d) {
                // Normal component: the wall face carries the wall's normal velocity; ghost
                // faces are odd images about the wall.
                for_each_index(slab(grid, d, 0, 1), [&](const Index<Dim>& i) { ua(i) = low; });
                for_each_index(slab(grid, d, n, n + 1), [&](const Index<Dim>& i) { ua(i) = high; });
                for_each_index(slab(grid, d, storage.lo[ax], 0), [&](const Index<Dim>& i) {
                    ua(i) = 2.0 * low - ua(with_axis(i, d, -i[ax]));
                });
                for_each_index(slab(grid, d, n + 1, storage.hi[ax]), [&](const Index<Dim>& i) {
                    ua(i) = 2.0 * high - ua(with_axis(i, d, 2 * n - i[ax]));
                });
            } else {
                // Tangential component: the first ghost continues the quadratic through the
                // wall value and two interior values; further ghosts are odd images.
                for_each_index(slab(grid, d, -1, 0), [&](const Index<Dim>& i) {
                    ua(i) =
                        (8.0 * low - 6.0 * ua(with_axis(i, d, 0)) + ua(with_axis(i, d, 1))) / 3.0;
                });
                for_each_index(slab(grid, d, n, n + 1), [&](const Index<Dim>& i) {
                    ua(i) = (8.0 * high - 6.0 * ua(with_axis(i, d, n - 1)) +
                             ua(with_axis(i, d, n - 2))) /
                            3.0;
                });
                for_each_index(slab(grid, d, storage.lo[ax], -1), [&](const Index<Dim>& i) {
                    ua(i) = 2.0 * low - ua(with_axis(i, d, -1 - i[ax]));
                });
                for_each_index(slab(grid, d, n + 1, storage.hi[ax]), [&](const Index<Dim>& i) {
                    ua(i) = 2.0 * high - ua(with_axis(i, d, 2 * n - 1 - i[ax]));
                });
            }
        }
    }
}

template <int Dim>
void fill_cell_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      CellField<Dim>& phi)
{
    const Box<Dim> storage = grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        const auto ax = static_cast<std::size_t>(d);
        const int n = grid.cells(d);
        if (bc.periodic(d)) {
            wrap_periodic(grid, d, phi);
            continue;
        }
        for_each_index(slab(grid, d, storage.lo[ax], 0),
                       [&](const Index<Dim>& i) { phi(i) = phi(with_axis(i, d, -1 - i[ax])); });
        for_each_index(slab(grid, d, n, storage.hi[ax]), [&](const Index<Dim>& i) {
            phi(i) = phi(with_axis(i, d, 2 * n - 1 - i[ax]));
        });
    }
}

template <int Dim>
void fill_periodic_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          GridArray<Dim>& a)
{
    for (int d = 0; d < Dim; ++d) {
        if (bc.periodic(d)) {
            wrap_periodic(grid, d, a);
        }
    }
}

template void fill_periodic_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                      GridArray<2>&);
template void fill_periodic_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                      GridArray<3>&);
template void fill_velocity_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                      FaceField<2>&);
template void fill_velocity_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                      FaceField<3>&);
template void fill_cell_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&, CellField<2>&);
template void fill_cell_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&, CellField<3>&);

} // namespace fddem
