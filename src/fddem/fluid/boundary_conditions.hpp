// SPDX-License-Identifier: MIT
#pragma once
/// Boundary conditions of the box: no-slip walls (possibly sliding, e.g. a lid), periodic
/// pairs, a prescribed-velocity inflow and a zero-gradient outflow, and the ghost-layer filling
/// that carries them to the stencils.
///
/// Inflow: the normal velocity on the boundary faces is the inflow profile (uniform, or the
/// parabola of a channel that vanishes on the walled transverse sides), the tangential velocity
/// zero; for the tangential components it is a wall at rest.
/// Outflow: zero normal gradient for every component. The outflow faces' normal velocity is
/// not an unknown of the momentum equations: set_outflow_velocity() extrapolates it from the
/// last interior faces and adds one uniform correction so that the outflow carries exactly
/// the inflow's volume flux. The pressure correction then keeps its zero normal gradient on
/// every side (docs/method.md §1, "Inflow and outflow").

#include "fddem/core/vec.hpp"
#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <algorithm>
#include <array>

namespace fddem {

/// What one side of a non-periodic axis is.
enum class BoundaryKind { wall, inflow, outflow };

/// The inflow's normal velocity: `speed` [m/s] everywhere (uniform), or speed × Π 4 s (1 − s)
/// over the walled transverse axes, s the fraction across the box (parabolic: `speed` is the
/// centre-line maximum; the mean is 2/3 of it in 2D).
enum class InflowShape { uniform, parabolic };

struct InflowProfile {
    InflowShape shape = InflowShape::uniform;
    double speed = 0.0; ///< [m/s], into the box
};

template <int Dim>
struct BoundaryConditions {
    /// is_periodic[axis]: both sides of that axis are one periodic pair.
    std::array<bool, Dim> is_periodic{};
    /// wall_velocity[axis][side] (side 0 = low, 1 = high) [m/s]; only the tangential
    /// components may be non-zero (a sliding wall); ignored on periodic axes.
    std::array<std::array<Vec<Dim>, 2>, Dim> wall_velocity{};
    /// kind[axis][side]; ignored on periodic axes.
    std::array<std::array<BoundaryKind, 2>, Dim> kind{};
    InflowProfile inflow{};

    [[nodiscard]] bool periodic(int axis) const noexcept
    {
        return is_periodic[static_cast<std::size_t>(axis)];
    }
    [[nodiscard]] const Vec<Dim>& wall(int axis, int side) const noexcept
    {
        return wall_velocity[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)];
    }

    [[nodiscard]] BoundaryKind side_kind(int axis, int side) const noexcept
    {
        return kind[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)];
    }
    /// Whether any side is an outflow.
    [[nodiscard]] bool has_outflow() const noexcept
    {
        for (int d = 0; d < Dim; ++d) {
            if (!periodic(d) && (side_kind(d, 0) == BoundaryKind::outflow ||
                                 side_kind(d, 1) == BoundaryKind::outflow)) {
                return true;
            }
        }
        return false;
    }

    /// All axes walled, walls at rest.
    [[nodiscard]] static BoundaryConditions closed_box()
    {
        BoundaryConditions bc;
        for (auto& axis : bc.wall_velocity) {
            for (auto& side : axis) {
                side = Vec<Dim>::Zero();
            }
        }
        return bc;
    }
};

/// The faces of component `axis` that are unknowns of the momentum equations: the owned faces
/// except those lying on the boundary (wall: the wall's normal velocity, zero; inflow: the
/// profile; outflow: set_outflow_velocity). On a periodic axis every owned face is an unknown
/// (face n is the image of face 0, a ghost). `bc` must agree with the grid on periodic axes.
template <int Dim>
[[nodiscard]] Box<Dim> unknown_faces(const MacGrid<Dim>& grid,
                                     [[maybe_unused]] const BoundaryConditions<Dim>& bc,
                                     int axis) noexcept
{
    Box<Dim> box = grid.owned_faces(axis);
    if (!grid.is_periodic(axis)) {
        const auto ax = static_cast<std::size_t>(axis);
        box.lo[ax] = std::max(box.lo[ax], 1);
        box.hi[ax] = std::min(box.hi[ax], grid.cells(axis));
    }
    return box;
}

/// Sets the normal velocity on wall and inflow faces and fills every ghost layer of `u`:
/// periodic images across periodic axes (the grid's HaloExchange::fill); across a wall or an
/// inflow, tangential ghosts such that the quadratic through the wall value and the first two
/// interior values is continued (u_g = (8 u_w − 6 u_0 + u_1)/3), which makes the wall treatment
/// exact for quadratic profiles (Poiseuille); outer ghost layers mirror the interior (odd about the
/// wall). Across an outflow every ghost repeats the last interior value (zero gradient), and the
/// outflow faces themselves are left as set_outflow_velocity() set them.
template <int Dim>
void fill_velocity_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          FaceField<Dim>& u, const Box<Dim>* window = nullptr);

/// fill_velocity_ghosts for one component `component` (= u's axis) of a field whose other
/// components' ghosts are already filled: after a solve that changed only that component.
template <int Dim>
void fill_component_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                           int component, GridArray<Dim>& ua);

/// `window` (fill_velocity_ghosts, zero_wall_ghosts, fold_wall_ghosts): if given (a part of
/// the storage box), only the sides it reaches (out to the storage's end along their axis), and
/// on those only the ghosts and boundary faces within it along the other axes: for a change
/// confined to it (a body's spreading, coupling/rigid_update.cpp), the values of whole sides,
/// bit for bit. The periodic and rank ghosts are filled whole.

/// Zeroes the ghosts across the non-periodic sides of every velocity component (those that
/// fill_velocity_ghosts fills from the boundary conditions); periodic and rank ghosts are the
/// HaloExchange's. Before spreading into a field whose ghosts hold the boundary conditions'
/// values, so that they hold only what was spread.
template <int Dim>
void zero_wall_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      FaceField<Dim>& f, const Box<Dim>* window = nullptr);

/// The transpose of fill_velocity_ghosts at the non-periodic sides: what was spread into a ghost
/// there is added to the entries that ghost is filled from, with the fill's own coefficients,
/// and the ghost is zeroed (a wall's tangential first ghost, (8 u_w − 6 u_0 + u_1)/3: −2 onto
/// u_0 and 1/3 onto u_1; an outer or normal ghost, an odd image: −1 onto its mirror; across an
/// outflow: +1 onto the entry it repeats). Spreading followed by this is the exact adjoint of
/// interpolating from a ghost-filled field, so that a marker beside a wall is coupled to the
/// fluid through a symmetric, non-negative I·D (coupling.adjoint_at_walls; docs/method.md §5).
/// What lands on a wall or inflow face itself is left there: those faces are not unknowns, and
/// fill_velocity_ghosts sets them again. Call it before HaloExchange::accumulate (the fill runs
/// the exchange first, so its transpose runs it last).
template <int Dim>
void fold_wall_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      FaceField<Dim>& f, const Box<Dim>* window = nullptr);

/// The inflow's normal velocity component at a point `x` of the boundary face (axis, side),
/// signed along +axis (into the box: positive on the low side, negative on the high side).
template <int Dim>
[[nodiscard]] double inflow_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                     int axis, int side, const Vec<Dim>& x) noexcept;

/// Outflow faces: the normal velocity of the last interior face (zero gradient) plus one
/// uniform correction over all outflow faces so that the net volume flux through the boundary
/// is zero. Then Σ ∇·u over the box vanishes and the pressure-correction equation with a zero
/// normal gradient on every side is compatible (its right-hand side has zero mean).
/// Returns the correction added [m/s]. Does nothing without an outflow.
template <int Dim>
double set_outflow_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                            FaceField<Dim>& u);

/// Net volume flux into the box through its inflow faces and out of it through its outflow
/// faces [m²/s in 2D, m³/s in 3D]: {inflow, outflow}.
template <int Dim>
[[nodiscard]] std::array<double, 2> boundary_fluxes(const MacGrid<Dim>& grid,
                                                    const BoundaryConditions<Dim>& bc,
                                                    const FaceField<Dim>& u);

/// Fills the ghost layers of a cell field: periodic images, or a zero normal gradient at
/// walls, inflows and outflows (the pressure-correction condition wherever the normal velocity
/// is not corrected: walls and inflows prescribe it, outflows extrapolate it).
template <int Dim>
void fill_cell_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      CellField<Dim>& phi);

} // namespace fddem
