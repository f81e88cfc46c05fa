// SPDX-License-Identifier: MIT
#pragma once
/// The binary collision of a Hertz spring with a linear damper, the normal force of Kempe &
/// Fröhlich's adaptive collision model (2012, J. Fluid Mech. 709, 445–489):
///
///   m α̈ + d α̇ + k α^{3/2} = 0,   α(0) = 0,  α̇(0) = v,   until α returns to 0,
///
/// m the pair's effective mass, α the overlap. With the length L = v T and the time T chosen so
/// that k L^{1/2} T² / m = 1, i.e. L = (m v² / k)^{2/5}, the overlap x = α / L obeys, in the time
/// τ = t / T,
///
///   x'' + γ x' + x^{3/2} = 0,   x(0) = 0,  x'(0) = 1,   γ = d T / m,
///
/// a problem of the one parameter γ (as Ray, Kempe & Fröhlich 2015, Int. J. Multiphase Flow 76,
/// found by the same scaling). Its restitution e(γ) = −x'(τ_c) and duration τ_c(γ) fix every
/// dimensional collision: t_c = T τ_c, exit speed e v. e falls from 1 at γ = 0 to 0 at
/// γ* ≈ 1.128; beyond γ* the overlap creeps back to 0 without ever reaching it (near α = 0 the
/// damper outweighs the vanishing spring), so no rebound is possible. The force is not clipped
/// at zero (it pulls, weakly, near the end of the contact), as in the DEM sub-steps.
///
/// Solved numerically (no closed form is known): classical Runge–Kutta with a fixed step of
/// 1e-3 (x^{3/2} is smooth inside the contact; the error in e and τ_c is below 1e-9, measured
/// against steps of 3e-4), the exit located by cubic Hermite interpolation within the last step.

namespace fddem {

/// The scaled collision of x'' + γ x' + x^{3/2} = 0, x(0) = 0, x'(0) = 1.
struct ScaledCollision {
    double restitution = 0.0; ///< e = −x'(τ_c); 0 if x does not return to 0 (γ ≥ γ*)
    double duration = 0.0;    ///< τ_c, with x > 0 on (0, τ_c); +∞ if x does not return
    double max_overlap = 0.0; ///< max x
};

/// The scaled collision for damping γ ≥ 0. A collision still open at τ = 100 counts as one
/// that never ends (restitution 0, duration +∞): below γ* it would end with e < 1e-20.
[[nodiscard]] ScaledCollision scaled_hertz_damper_collision(double damping);

/// γ with e(γ) = `restitution` (0 < e ≤ 1), by bisection on [0, γ*] to round-off; e = 1 gives
/// exactly 0.
[[nodiscard]] double scaled_damping_for_restitution(double restitution);

} // namespace fddem
