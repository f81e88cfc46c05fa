// SPDX-License-Identifier: MIT
#pragma once
/// The paper's non-dimensional set-up (§3.1, eqs. (19)–(22)) turned into dimensional values.

namespace fddem {

/// Happel & Brenner (1965) wall factor K for a disk (cylinder) in a channel of width W = W*·D,
/// eq. (20): drag F = 4π K μ U per unit length at low Reynolds number (eq. 19).
[[nodiscard]] double happel_brenner_wall_factor(double width_ratio);

struct DerivedScales {
    double viscosity;    ///< μ = ρf U_c D / Re [Pa·s]
    double body_density; ///< ρs = ρr ρf [kg/m³]
    double gravity;      ///< |g| from eq. (21): U_c = D² (ρs − ρf) g / (16 K μ) [m/s²]
    double wall_factor;  ///< K
};

/// Dimensional values for Re, ρr, W*, with ρf, D and U_c given. Requires ρr ≠ 1.
[[nodiscard]] DerivedScales derive_scales(double reynolds, double density_ratio, double width_ratio,
                                          double fluid_density, double diameter, double velocity);

} // namespace fddem
