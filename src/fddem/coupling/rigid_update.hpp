// SPDX-License-Identifier: MIT
#pragma once
/// The fictitious-domain stage of one SIMPLE outer iteration, for every body (paper §2.3):
///   I:        u_l = I(u) at each marker;
///   eqs. (13)–(14): U, ω of a free body from ∫_P (u/Δt − λ*) and its level-n motion;
///   eq. (15): λ = λ* + (U + ω × r − u_l)/Δt;
///   eq. (16): u ← u + Δt D(λ − λ*), then λ* ← λ.
/// The per-body formulas are in rigid_coupling.hpp; this file applies them to the grid.

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/grid/fields.hpp"

#include <span>

namespace fddem {

template <int Dim>
struct RigidUpdateSettings {
    double fluid_density;  ///< ρf [kg/m³]
    Vec<Dim> gravity;      ///< g [m/s²]
    double dt;             ///< Δt [s]
    bool is_paper_contact; ///< contact.coupling = "paper": a body in contact moves as DEM says
};

/// Eqs. (13)–(16) for every body, in the order of the store; `u` needs its ghosts filled.
/// Sets each body's velocity and ω, its λ (= λ*) and coupling.forcing_change, and adds the
/// correction to `u` (accumulated across periodic sides, whose ghosts are then filled; those
/// across walls are left as they were). Returns the largest rigid-motion defect
/// max |U + ω×r − I(u)| [m/s].
template <int Dim>
double update_rigid_bodies(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                           const AnyKernel& kernel, const RigidUpdateSettings<Dim>& settings,
                           FaceField<Dim>& u);

} // namespace fddem
