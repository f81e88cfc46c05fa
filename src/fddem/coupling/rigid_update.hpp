// SPDX-License-Identifier: MIT
#pragma once
/// The fictitious-domain stage of one SIMPLE outer iteration, for every body (paper §2.3):
///   I:        u_l = I(u) at each marker;
///   eqs. (13)–(14): U, ω of a free body from ∫_P (u/Δt − λ*) and its level-n motion; with
///                   coupling.inner_fluid = "volume" eqs. (13')–(14') of coupling/inner_fluid.hpp,
///                   ∫_P u over the cells now and at the step's start instead;
///   eq. (15): λ = λ* + (U + ω × r − u_l)/Δt;
///   eq. (16): u ← u + Δt D(λ − λ*), then λ* ← λ.
/// The per-body formulas are in rigid_coupling.hpp; this file applies them to the grid.
///
/// With time.scheme = "bdf2" every Δt here is Δt_e and every level-n body velocity the
/// extrapolated Ũ^n, ω̃^n of core/time_scheme.hpp, the same as in the momentum equations:
/// - eqs. (15)–(16): the momentum equation answers a change δλ of the force with
///   δu = Δt_e δλ (its time coefficient in a_P is ρf ΔV/Δt_e), so eq. (15) divides the slip by
///   Δt_e and eq. (16) adds Δt_e D(λ − λ*). With Euler's Δt there, the next momentum solve
///   would move the fluid inside the body only 2/3 of the way to rigid motion (constant step)
///   while eq. (16) had moved it all the way: the body would be rigid only once the outer
///   iterations converge, which the step's test (on the bodies' change) does not require.
/// - eqs. (13)–(14) are the fluid's BDF2 momentum balance integrated over the body plus the
///   body's own BDF2 equation of motion, ρs V (U^{n+1} − Ũ^n)/Δt_e = F_H + (ρs − ρf) V g:
///   the same formulas with (Δt, U^n) → (Δt_e, Ũ^n), so free bodies are second order too
///   (docs/method.md §4, "Second-order time stepping").

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/fields.hpp"

#include <span>

namespace fddem {

template <int Dim>
struct RigidUpdateSettings {
    double fluid_density;  ///< ρf [kg/m³]
    Vec<Dim> gravity;      ///< g [m/s²]
    double dt;             ///< Δt_e [s] (core/time_scheme.hpp): Δt with implicit Euler
    bool is_paper_contact; ///< contact.coupling = "paper": a body in contact moves as DEM says
    /// w of core/time_scheme.hpp: the level-n motion of eqs. (13)–(14) is
    /// Ũ^n = U^n + w (U^n − U^{n−1}) (likewise ω); 0 for implicit Euler
    double history_weight = 0.0;
    /// coupling.markers_off_at_walls: markers closer than wall_marker_reach to a wall (a
    /// non-periodic side) take no part (λ = 0; their u_l in (13)–(14) the body's own motion)
    bool is_wall_marker_off = false;
    /// coupling.body_sweep = "simultaneous": every body's I(u) from the same u and the
    /// corrections of eq. (16) added together (one sum over ranks and one halo exchange per
    /// call); false: body after body, each reading the fluid the ones before left
    bool is_simultaneous = false;
    /// coupling.adjoint_at_walls: the boundary conditions whose ghost fill eq. (16)'s spreading
    /// is folded back through (fold_wall_ghosts), so that D is the adjoint of I beside a wall;
    /// null: what is spread into a wall's ghosts is dropped
    const BoundaryConditions<Dim>* adjoint_walls = nullptr;
    /// lubrication.coupling = "implicit": a body's lubrication links (ContactState) enter its
    /// eqs. (13)–(14) as an implicit damping (coupling/lubrication_coupling.hpp)
    bool is_lubrication_implicit = false;
    /// coupling.inner_fluid = "volume": eqs. (13')–(14') of coupling/inner_fluid.hpp, the fluid
    /// inside a free body integrated over the cells it covers (its level-n value set at the
    /// step's start, coupling.inner_fluid_n), not taken from its markers
    bool is_inner_fluid_volume = false;
    /// With is_wall_marker_off: how close to a wall [cells of that side's axis] a marker is off;
    /// 0: default_wall_marker_reach of the kernel (its support radius + 1/2). With
    /// is_body_marker_off the same reach from a midplane, in spacings along its normal
    /// (coupling/body_midplanes.hpp, reach_along).
    double wall_marker_reach = 0.0;
    /// coupling.markers_off_between_bodies: markers closer than the reach to the plane midway
    /// between their body's surface and a neighbour's (coupling/body_midplanes.hpp) take no part,
    /// as those beside a wall do
    bool is_body_marker_off = false;
};

/// Whether eqs. (13)–(14) give the body's motion in an outer iteration: a free body, unless the
/// paper's contact coupling hands it to the DEM while it is in contact (§2.3), when its motion
/// is given for the step, as a prescribed body's is.
template <int Dim>
[[nodiscard]] bool is_moved_by_fluid(const Particle<Dim>& body, bool is_paper_contact) noexcept
{
    return body.is_free() && !(is_paper_contact && body.contact.is_in_contact);
}

/// Eqs. (13)–(16) for every body, in the order of the store (or all at once, with
/// settings.is_simultaneous); `u` needs its ghosts filled.
/// Sets each body's velocity and ω, its λ (= λ*) and coupling.forcing_change, and adds the
/// correction to `u` (accumulated across periodic sides, whose ghosts are then filled; those
/// across walls are left as they were, or with settings.adjoint_walls folded back onto the
/// fluid they are images of and filled again). Returns the largest rigid-motion defect
/// max |U + ω×r − I(u)| [m/s].
template <int Dim>
double update_rigid_bodies(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                           const AnyKernel& kernel, const RigidUpdateSettings<Dim>& settings,
                           FaceField<Dim>& u);

} // namespace fddem
