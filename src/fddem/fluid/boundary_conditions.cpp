// SPDX-License-Identifier: MIT
#include "fddem/fluid/boundary_conditions.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <array>

namespace fddem {
namespace {

/// `window` (the storage box, or a part of it) with axis `axis` restricted to [lo, hi).
template <int Dim>
Box<Dim> slab(const Box<Dim>& window, int axis, int lo, int hi)
{
    Box<Dim> box = window;
    box.lo[static_cast<std::size_t>(axis)] = lo;
    box.hi[static_cast<std::size_t>(axis)] = hi;
    return box;
}

/// Calls f(o, x) for every point of `box`: o its offset in the grid's storage, x its index along
/// `axis`. A ghost fill reads the entries at o + (m − x)·stride(axis) for the rows m it is filled
/// from, so the rows along axis 0 run with unit stride and without an index computation per point
/// (a per-point Index cost 10–15 % of a 3D fluid step in the ghost fills alone).
template <int Dim, class F>
void for_each_offset(const MacGrid<Dim>& grid, const Box<Dim>& box, int axis, F&& f)
{
    for_each_row(box, [&](const Index<Dim>& row) {
        const std::ptrdiff_t base = grid.offset(row) - box.lo[0];
        const int across = row[static_cast<std::size_t>(axis)];
        for (int i = box.lo[0]; i < box.hi[0]; ++i) {
            f(base + i, axis == 0 ? i : across);
        }
    });
}

/// Whether `window` reaches side `side` of `axis`, i.e. its ghost rows: only such a side is
/// zeroed, folded or filled within a window. A side the window stops short of keeps its ghosts
/// (they are filled from interior rows the window's change did not reach), and so do its edges
/// and corners with other sides: filling those from one side within the window would write them
/// in another order than the whole fill, whose last side wins.
template <int Dim>
bool reaches_side(const MacGrid<Dim>& grid, const Box<Dim>& window, int axis, int side)
{
    const Box<Dim> storage = grid.storage_box();
    const auto ax = static_cast<std::size_t>(axis);
    return side == 0 ? window.lo[ax] <= storage.lo[ax] : window.hi[ax] >= storage.hi[ax];
}

/// The grid and the boundary conditions must agree on the periodic axes: the grid's halo
/// exchange fills the ghosts across them, the boundary conditions those across every other side.
template <int Dim>
void check_periodic_axes(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc)
{
    if (grid.periodic_axes() != bc.is_periodic) {
        throw InternalError("the grid and the boundary conditions disagree on the periodic axes");
    }
}

/// The boundary faces of `axis` on `side` this process owns: the face slab at index 0 or n,
/// transverse extent the owned cells; empty on a block that does not reach that side.
template <int Dim>
Box<Dim> boundary_faces(const MacGrid<Dim>& grid, int axis, int side)
{
    Box<Dim> box = grid.owned_cells();
    const auto ax = static_cast<std::size_t>(axis);
    box.lo[ax] = side == 0 ? 0 : grid.cells(axis);
    box.hi[ax] = grid.touches_side(axis, side) ? box.lo[ax] + 1 : box.lo[ax];
    return box;
}

/// The rows of one side of `axis` that its ghost fill (and the fold, its transpose) works with,
/// each over the whole storage extent of the other axes.
template <int Dim>
struct SideRows {
    int n = 0;              ///< cells along the axis
    int face = 0;           ///< the normal component's boundary face: 0 or n
    Box<Dim> normal_ghosts; ///< the normal component's ghosts beyond that face
    int first = 0;          ///< tangential components: the last interior row
    int second = 0;         ///< and the one before it
    int ghost = 0;          ///< the first ghost row
    Box<Dim> outer;         ///< the ghost rows beyond it
    Box<Dim> all_ghosts;    ///< every ghost row

    /// The normal component's image of ghost row i about the boundary face.
    [[nodiscard]] int normal_mirror(int i) const noexcept { return 2 * face - i; }
    /// A tangential component's image of ghost row i about the wall, at row −1/2 or n − 1/2.
    [[nodiscard]] int tangential_mirror(int i) const noexcept
    {
        return face == 0 ? -1 - i : 2 * n - 1 - i;
    }
};

template <int Dim>
SideRows<Dim> side_rows(const MacGrid<Dim>& grid, int axis, int side, const Box<Dim>& window)
{
    const Box<Dim> storage = grid.storage_box();
    const auto ax = static_cast<std::size_t>(axis);
    const int n = grid.cells(axis);
    const bool low = side == 0;
    SideRows<Dim> r;
    r.n = n;
    r.face = low ? 0 : n;
    r.normal_ghosts =
        low ? slab(window, axis, storage.lo[ax], 0) : slab(window, axis, n + 1, storage.hi[ax]);
    r.first = low ? 0 : n - 1;
    r.second = low ? 1 : n - 2;
    r.ghost = low ? -1 : n;
    r.outer =
        low ? slab(window, axis, storage.lo[ax], -1) : slab(window, axis, n + 1, storage.hi[ax]);
    r.all_ghosts =
        low ? slab(window, axis, storage.lo[ax], 0) : slab(window, axis, n, storage.hi[ax]);
    return r;
}

/// Normal component `axis` on `side` of that axis: the boundary face (except at an outflow,
/// which set_outflow_velocity sets) and the ghost faces beyond it.
template <int Dim>
void fill_normal_side(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                      int side, GridArray<Dim>& ua, const Box<Dim>& window)
{
    if (!grid.touches_side(axis, side)) {
        return; // an inner block side: its ghosts come from the halo exchange
    }
    const SideRows<Dim> rows = side_rows(grid, axis, side, window);
    const BoundaryKind kind = bc.side_kind(axis, side);
    const int face = rows.face;
    const Box<Dim> face_slab = slab(window, axis, face, face + 1);
    double* a = ua.data();
    const std::ptrdiff_t s = grid.stride(axis);
    if (kind == BoundaryKind::wall) {
        const double wall = bc.wall(axis, side)[axis];
        for_each_offset(grid, face_slab, axis, [&](std::ptrdiff_t o, int) { a[o] = wall; });
    } else if (kind == BoundaryKind::inflow) {
        for_each_index(face_slab, [&](const Index<Dim>& i) {
            ua(i) = inflow_velocity(grid, bc, axis, side, grid.face_centre(axis, i));
        });
    }
    const bool is_outflow = kind == BoundaryKind::outflow;
    for_each_offset(grid, rows.normal_ghosts, axis, [&](std::ptrdiff_t o, int x) {
        const double boundary = a[o + (face - x) * s];
        // Outflow: zero gradient; wall and inflow: odd images about the boundary value.
        a[o] = is_outflow ? boundary : 2.0 * boundary - a[o + (rows.normal_mirror(x) - x) * s];
    });
}

/// Tangential component on `side` of `axis`: the ghosts across that side.
template <int Dim>
void fill_tangential_side(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                          int side, int component, GridArray<Dim>& ua, const Box<Dim>& window)
{
    if (!grid.touches_side(axis, side)) {
        return;
    }
    const SideRows<Dim> rows = side_rows(grid, axis, side, window);
    const int first = rows.first;
    const int second = rows.second;
    const int ghost = rows.ghost;
    double* a = ua.data();
    const std::ptrdiff_t s = grid.stride(axis);
    if (bc.side_kind(axis, side) == BoundaryKind::outflow) {
        for_each_offset(grid, rows.all_ghosts, axis,
                        [&](std::ptrdiff_t o, int x) { a[o] = a[o + (first - x) * s]; });
        return;
    }
    // Wall or inflow (whose tangential velocity is zero): the first ghost continues the
    // quadratic through the wall value and two interior values; further ghosts are odd images.
    const double wall = bc.wall(axis, side)[component];
    const std::ptrdiff_t to_first = (first - ghost) * s;
    const std::ptrdiff_t to_second = (second - ghost) * s;
    for_each_offset(grid, slab(window, axis, ghost, ghost + 1), axis, [&](std::ptrdiff_t o, int) {
        a[o] = (8.0 * wall - 6.0 * a[o + to_first] + a[o + to_second]) / 3.0;
    });
    for_each_offset(grid, rows.outer, axis, [&](std::ptrdiff_t o, int x) {
        a[o] = 2.0 * wall - a[o + (rows.tangential_mirror(x) - x) * s];
    });
}

/// The transpose of fill_normal_side's ghosts (not of its boundary face, which is set, not
/// filled from the interior): each ghost's value goes to the entry it is filled from.
template <int Dim>
void fold_normal_side(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                      int side, GridArray<Dim>& fa, const Box<Dim>& window)
{
    if (!grid.touches_side(axis, side)) {
        return;
    }
    const auto ax = static_cast<std::size_t>(axis);
    const SideRows<Dim> rows = side_rows(grid, axis, side, window);
    const int face = rows.face;
    const bool is_outflow = bc.side_kind(axis, side) == BoundaryKind::outflow;
    for_each_index(rows.normal_ghosts, [&](const Index<Dim>& i) {
        // Outflow: u_g = u_face; wall and inflow: u_g = 2 u_face − u_mirror, u_face set.
        if (is_outflow) {
            fa(with_axis(i, axis, face)) += fa(i);
        } else {
            fa(with_axis(i, axis, rows.normal_mirror(i[ax]))) -= fa(i);
        }
        fa(i) = 0.0;
    });
}

/// The transpose of fill_tangential_side, in the reverse order of its fill.
template <int Dim>
void fold_tangential_side(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                          int side, GridArray<Dim>& fa, const Box<Dim>& window)
{
    if (!grid.touches_side(axis, side)) {
        return;
    }
    const auto ax = static_cast<std::size_t>(axis);
    const SideRows<Dim> rows = side_rows(grid, axis, side, window);
    const int first = rows.first;
    const int second = rows.second;
    const int ghost = rows.ghost;
    if (bc.side_kind(axis, side) == BoundaryKind::outflow) {
        for_each_index(rows.all_ghosts, [&](const Index<Dim>& i) {
            fa(with_axis(i, axis, first)) += fa(i);
            fa(i) = 0.0;
        });
        return;
    }
    for_each_index(rows.outer, [&](const Index<Dim>& i) {
        fa(with_axis(i, axis, rows.tangential_mirror(i[ax]))) -= fa(i);
        fa(i) = 0.0;
    });
    for_each_index(slab(window, axis, ghost, ghost + 1), [&](const Index<Dim>& i) {
        fa(with_axis(i, axis, first)) += -2.0 * fa(i);
        fa(with_axis(i, axis, second)) += fa(i) / 3.0;
        fa(i) = 0.0;
    });
}

} // namespace

template <int Dim>
double inflow_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                       int side, const Vec<Dim>& x) noexcept
{
    double speed = bc.inflow.speed;
    if (bc.inflow.shape == InflowShape::parabolic) {
        for (int t = 0; t < Dim; ++t) {
            if (t == axis || bc.periodic(t)) {
                continue;
            }
            const double s = (x[t] - grid.origin()[t]) / grid.length()[t];
            speed *= 4.0 * s * (1.0 - s);
        }
    }
    return side == 0 ? speed : -speed;
}

namespace {

/// The ghosts of velocity component `component` across the non-periodic sides `box` reaches,
/// axis by axis, low side then high, each over the whole extent of `box` along the other axes
/// (so that an edge or corner ghost is the last side's). A component's ghosts read only that
/// component, so the components can be filled in any order.
template <int Dim>
void fill_wall_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int component,
                      GridArray<Dim>& ua, const Box<Dim>& box)
{
    for (int d = 0; d < Dim; ++d) {
        if (bc.periodic(d)) {
            continue;
        }
        for (int side = 0; side < 2; ++side) {
            if (!reaches_side(grid, box, d, side)) {
                continue;
            }
            if (component == d) {
                fill_normal_side(grid, bc, d, side, ua, box);
            } else {
                fill_tangential_side(grid, bc, d, side, component, ua, box);
            }
        }
    }
}

} // namespace

template <int Dim>
void fill_velocity_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          FaceField<Dim>& u, const Box<Dim>* window)
{
    check_periodic_axes(grid, bc);
    const Box<Dim> box = window != nullptr ? *window : grid.storage_box();
    // Periodic images first, then the walled sides over the whole storage extent of the other
    // axes (the values are those of filling axis by axis in any order: a wall's ghosts depend
    // only on their own row, which a periodic image repeats).
    HaloExchange<Dim>(grid).fill(u);
    for (int a = 0; a < Dim; ++a) {
        fill_wall_ghosts(grid, bc, a, u[a], box);
    }
}

template <int Dim>
void fill_component_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                           int component, GridArray<Dim>& ua)
{
    check_periodic_axes(grid, bc);
    HaloExchange<Dim>(grid).fill(ua);
    fill_wall_ghosts(grid, bc, component, ua, grid.storage_box());
}

template <int Dim>
void zero_wall_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      FaceField<Dim>& f, const Box<Dim>* window)
{
    check_periodic_axes(grid, bc);
    const Box<Dim> box = window != nullptr ? *window : grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        if (bc.periodic(d)) {
            continue;
        }
        for (int side = 0; side < 2; ++side) {
            if (!grid.touches_side(d, side) || !reaches_side(grid, box, d, side)) {
                continue;
            }
            const SideRows<Dim> rows = side_rows(grid, d, side, box);
            for (int a = 0; a < Dim; ++a) {
                // The normal component's ghosts start beyond its boundary face, the others' at
                // once.
                GridArray<Dim>& fa = f[a];
                for_each_index(a == d ? rows.normal_ghosts : rows.all_ghosts,
                               [&](const Index<Dim>& i) { fa(i) = 0.0; });
            }
        }
    }
}

template <int Dim>
void fold_wall_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      FaceField<Dim>& f, const Box<Dim>* window)
{
    check_periodic_axes(grid, bc);
    const Box<Dim> box = window != nullptr ? *window : grid.storage_box();
    // fill_velocity_ghosts goes axis by axis, component by component, low side then high,
    // each step over the whole storage extent of the other axes (edges and corners included);
    // its transpose goes through the same steps in the reverse order.
    for (int d = Dim - 1; d >= 0; --d) {
        if (bc.periodic(d)) {
            continue;
        }
        for (int a = Dim - 1; a >= 0; --a) {
            for (int side = 1; side >= 0; --side) {
                if (!reaches_side(grid, box, d, side)) {
                    continue;
                }
                if (a == d) {
                    fold_normal_side(grid, bc, d, side, f[a], box);
                } else {
                    fold_tangential_side(grid, bc, d, side, f[a], box);
                }
            }
        }
    }
}

template <int Dim>
std::array<double, 2> boundary_fluxes(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                      const FaceField<Dim>& u)
{
    std::array<double, 2> flux{}; // {in through inflows, out through outflows}
    for (int d = 0; d < Dim; ++d) {
        if (bc.periodic(d)) {
            continue;
        }
        const double area = grid.cell_volume() / grid.spacing(d);
        for (int side = 0; side < 2; ++side) {
            const BoundaryKind kind = bc.side_kind(d, side);
            if (kind == BoundaryKind::wall) {
                continue;
            }
            const double outward = side == 0 ? -1.0 : 1.0;
            const double out = outward * area *
                               sum_over(grid.communicator(), boundary_faces(grid, d, side),
                                        [&](const Index<Dim>& i) { return u[d](i); });
            if (kind == BoundaryKind::inflow) {
                flux[0] -= out;
            } else {
                flux[1] += out;
            }
        }
    }
    return flux;
}

template <int Dim>
double set_outflow_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                            FaceField<Dim>& u)
{
    if (!bc.has_outflow()) {
        return 0.0;
    }
    // Zero gradient: each outflow face takes the normal velocity of the face one cell inside.
    double outflow_area = 0.0;
    for (int d = 0; d < Dim; ++d) {
        for (int side = 0; side < 2; ++side) {
            if (bc.periodic(d) || bc.side_kind(d, side) != BoundaryKind::outflow) {
                continue;
            }
            const int inside = side == 0 ? 1 : grid.cells(d) - 1;
            const Box<Dim> faces = boundary_faces(grid, d, side);
            for_each_index(faces,
                           [&](const Index<Dim>& i) { u[d](i) = u[d](with_axis(i, d, inside)); });
            outflow_area +=
                static_cast<double>(faces.size()) * grid.cell_volume() / grid.spacing(d);
        }
    }
    outflow_area = grid.communicator().sum(outflow_area);
    // Global mass conservation: one uniform outward correction over all outflow faces. A
    // uniform addition (rather than scaling) also works from a fluid at rest.
    const auto [inflow, outflow] = boundary_fluxes(grid, bc, u);
    const double correction = (inflow - outflow) / outflow_area;
    for (int d = 0; d < Dim; ++d) {
        for (int side = 0; side < 2; ++side) {
            if (bc.periodic(d) || bc.side_kind(d, side) != BoundaryKind::outflow) {
                continue;
            }
            const double outward = side == 0 ? -1.0 : 1.0;
            GridArray<Dim>& ud = u[d];
            for_each_index(boundary_faces(grid, d, side),
                           [&](const Index<Dim>& i) { ud(i) += outward * correction; });
            fill_normal_side(grid, bc, d, side, ud, grid.storage_box());
        }
    }
    return correction;
}

template <int Dim>
void fill_cell_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      CellField<Dim>& phi)
{
    check_periodic_axes(grid, bc);
    HaloExchange<Dim>(grid).fill(phi);
    const Box<Dim> storage = grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        const auto ax = static_cast<std::size_t>(d);
        const int n = grid.cells(d);
        if (bc.periodic(d)) {
            continue;
        }
        double* a = phi.data();
        const std::ptrdiff_t s = grid.stride(d);
        if (grid.touches_side(d, 0)) {
            for_each_offset(grid, slab(storage, d, storage.lo[ax], 0), d,
                            [&](std::ptrdiff_t o, int x) { a[o] = a[o + (-1 - 2 * x) * s]; });
        }
        if (grid.touches_side(d, 1)) {
            for_each_offset(
                grid, slab(storage, d, n, storage.hi[ax]), d,
                [&](std::ptrdiff_t o, int x) { a[o] = a[o + (2 * n - 1 - 2 * x) * s]; });
        }
    }
}

template void fill_velocity_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                      FaceField<2>&, const Box<2>*);
template void fill_velocity_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                      FaceField<3>&, const Box<3>*);
template void fill_component_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&, int,
                                       GridArray<2>&);
template void fill_component_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&, int,
                                       GridArray<3>&);
template double inflow_velocity<2>(const MacGrid<2>&, const BoundaryConditions<2>&, int, int,
                                   const Vec<2>&) noexcept;
template double inflow_velocity<3>(const MacGrid<3>&, const BoundaryConditions<3>&, int, int,
                                   const Vec<3>&) noexcept;
template double set_outflow_velocity<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                        FaceField<2>&);
template double set_outflow_velocity<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                        FaceField<3>&);
template void zero_wall_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&, FaceField<2>&,
                                  const Box<2>*);
template void zero_wall_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&, FaceField<3>&,
                                  const Box<3>*);
template void fold_wall_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&, FaceField<2>&,
                                  const Box<2>*);
template void fold_wall_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&, FaceField<3>&,
                                  const Box<3>*);
template std::array<double, 2> boundary_fluxes<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                                  const FaceField<2>&);
template std::array<double, 2> boundary_fluxes<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                                  const FaceField<3>&);
template void fill_cell_ghosts<2>(const MacGrid<2>&, const BoundaryConditions<2>&, CellField<2>&);
template void fill_cell_ghosts<3>(const MacGrid<3>&, const BoundaryConditions<3>&, CellField<3>&);

} // namespace fddem
