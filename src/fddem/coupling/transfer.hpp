// SPDX-License-Identifier: MIT
#pragma once
/// The transfer operators of paper §2.2, per velocity component at that component's own face
/// positions (face (axis, i) at x_{i−1/2} along axis, cell centres across):
///   I: f_L(X_l) = Σ_faces f_E(x) δ_h(x − X_l),
///   D: f_E(x) += Σ_l f_L(X_l) δ_h(x − X_l) ΔV_l / ΔV_cell   (ΔV_l* of the paper),
/// with δ_h the product of 1-D kernel weights. D is the adjoint of I under the ΔV weighting.
/// Points must keep the kernel support inside the storage box (ghosts included): the caller
/// checks it with `fits_in_storage`. Spreading is serial: markers of one body may share faces.

#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/grid/fields.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace fddem {

/// True if the support of Kernel around x fits in `box` (of the grid's indices) for every
/// component: the grid's storage_box() for this process's arrays, or whole_storage_box() for a
/// check that gives the same answer on every rank.
template <int Dim, DeltaKernel Kernel>
[[nodiscard]] bool fits_in_box(const MacGrid<Dim>& grid, const Box<Dim>& box, const Vec<Dim>& x);

/// True if the support of Kernel around x fits in the grid's storage for every component.
template <int Dim, DeltaKernel Kernel>
[[nodiscard]] bool fits_in_storage(const MacGrid<Dim>& grid, const Vec<Dim>& x)
{
    return fits_in_box<Dim, Kernel>(grid, grid.storage_box(), x);
}

/// I for one component: the field `a` (component `axis`) at point x.
template <int Dim, DeltaKernel Kernel>
[[nodiscard]] double interpolate_component(const MacGrid<Dim>& grid, const GridArray<Dim>& a,
                                           int axis, const Vec<Dim>& x);

/// D for one component: adds value · δ_h(x_face − x) · h^Dim-normalised weight to `a`, i.e.
/// a_face += value · w_face; the caller passes value = f_l ΔV_l / ΔV_cell.
template <int Dim, DeltaKernel Kernel>
void spread_component(const MacGrid<Dim>& grid, GridArray<Dim>& a, int axis, const Vec<Dim>& x,
                      double value);

/// I for the whole velocity.
template <int Dim, DeltaKernel Kernel>
[[nodiscard]] Vec<Dim> interpolate_velocity(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                                            const Vec<Dim>& x)
{
    Vec<Dim> result;
    for (int a = 0; a < Dim; ++a) {
        result[a] = interpolate_component<Dim, Kernel>(grid, u[a], a, x);
    }
    return result;
}

/// D for a vector quantity f at x with marker volume ΔV_l: u += f ΔV_l / ΔV_cell δ-weighted.
template <int Dim, DeltaKernel Kernel>
void spread_vector(const MacGrid<Dim>& grid, FaceField<Dim>& u, const Vec<Dim>& x,
                   const Vec<Dim>& f, double marker_volume)
{
    const double scale = marker_volume / grid.cell_volume();
    for (int a = 0; a < Dim; ++a) {
        spread_component<Dim, Kernel>(grid, u[a], a, x, f[a] * scale);
    }
}

/// The part of this rank's storage box that the spreading of markers at `positions`, and the
/// boundary ghosts filled from what it changes, can reach: the cells of the kernel supports,
/// grown by one cell, and along an axis whose side it comes within the ghost fill's reach of
/// (the ghost layers and the two interior rows a ghost is filled from), out to the storage's
/// end, so that the ghosts of edges and corners, filled from other sides' ghosts, are in it.
/// Along a periodic axis the whole extent. (A rank's halo needs nothing more: the neighbour
/// whose faces receive what was spread into the halo finds them in its own window.)
template <int Dim, class Kernel>
[[nodiscard]] Box<Dim> support_window(const MacGrid<Dim>& grid, std::span<const Vec<Dim>> positions)
{
    const Box<Dim> storage = grid.storage_box();
    Box<Dim> window = storage;
    if (positions.empty()) {
        return window;
    }
    for (int d = 0; d < Dim; ++d) {
        const auto ax = static_cast<std::size_t>(d);
        if (grid.is_periodic(d)) {
            continue; // what is spread across the seam lands at the other end: all of it
        }
        double low = positions.front()[d];
        double high = low;
        for (const Vec<Dim>& x : positions) {
            low = std::min(low, x[d]);
            high = std::max(high, x[d]);
        }
        const double h = grid.spacing()[d];
        const int reach = Kernel::half_width + 1;
        int lo = static_cast<int>(std::floor((low - grid.origin()[d]) / h)) - reach;
        int hi = static_cast<int>(std::floor((high - grid.origin()[d]) / h)) + reach + 1;
        const int fill_reach = MacGrid<Dim>::n_ghost + 3;
        if (lo <= fill_reach) {
            lo = storage.lo[ax];
        }
        if (hi >= grid.cells(d) - fill_reach) {
            hi = storage.hi[ax];
        }
        window.lo[ax] = std::clamp(lo, storage.lo[ax], storage.hi[ax]);
        window.hi[ax] = std::clamp(hi, window.lo[ax], storage.hi[ax]);
    }
    return window;
}

} // namespace fddem
