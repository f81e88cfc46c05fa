// SPDX-License-Identifier: MIT
#pragma once
/// The force and torque the fluid exerts on a body over the step, from the fluid's momentum
/// balance over the body (the paper's eqs. (5a)–(5b) with λ the force density, as
/// rigid_coupling.hpp writes them): F_H = ρf V (U^{n+1} − U^n)/Δt − ρf Σ ΔV_l λ_l and T_H = ρf Σ
/// ΔV_l |r⊥|² (ω^{n+1} − ω^n)/Δt − ρf Σ ΔV_l r_l × λ_l. For output and diagnostics. With
/// time.scheme = "bdf2", Δt is Δt_e and U^n, ω^n are Ũ^n, ω̃^n (core/time_scheme.hpp), as in
/// eqs. (13)–(14). With coupling.inner_fluid = "volume" a free body's inner fluid is not taken
/// as rigid: ρf (∫_P u dx − ∫_P u^n dx)/Δt and ρf (∫_P r × u dx − ∫_P r × u^n dx)/Δt stand for
/// the two first terms (coupling/inner_fluid.hpp; coupling.inner_fluid and inner_fluid_n must
/// hold the step's end and start).

#include "fddem/bodies/particle.hpp"
#include "fddem/core/time_scheme.hpp"

#include <span>

namespace fddem {

/// Sets force and torque of every body from its λ and its velocity change over the step of
/// `levels` (Δt_e [s], and Ũ^n with BDF2); `fluid_density` ρf [kg/m³];
/// `is_inner_fluid_volume`: coupling.inner_fluid = "volume".
template <int Dim>
void measure_hydrodynamic_forces(std::span<Particle<Dim>> bodies, double fluid_density,
                                 const TimeLevels& levels, bool is_inner_fluid_volume = false);

} // namespace fddem
