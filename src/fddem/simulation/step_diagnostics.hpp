// SPDX-License-Identifier: MIT
#pragma once
/// Measures of the flow that the time step reports and tests against: the velocity scale of the
/// residuals, the Courant number and rate of change of a step, and where a blown-up flow first
/// stops being finite.

#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <algorithm>
#include <string>

namespace fddem {

/// U_ref [m/s]: the largest fluid or wall speed (at least the smallest normal double, which
/// only avoids 0/0 for a fluid entirely at rest: all residuals are then zero).
template <int Dim>
[[nodiscard]] double reference_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                        const FaceField<Dim>& u);

/// The largest speed per cell of the fluid, max_d max |u_d| / h_d [1/s] (Courant number / Δt).
template <int Dim>
[[nodiscard]] double max_speed_per_cell(const MacGrid<Dim>& grid, const FaceField<Dim>& u);

/// A residual `value` ≥ 0 [m/s] relative to the velocity scale. A fluid at rest (the scale at
/// reference_velocity()'s floor) under a force has a residual before it has a velocity: it
/// then counts as 1, not as value/2.2e-308, which overflowed into a false blow-up (a periodic
/// channel driven by fluid.body_force = 1000 from rest, Δt = 0.01). Where the residual is
/// below the scale, as whenever the iterations near convergence, this is value/scale.
[[nodiscard]] inline double relative_to(double value, double scale)
{
    return value / std::max(scale, value);
}

/// What a finished step changed: the Courant number max_d max |u_d| Δt / h_d of u, and the
/// largest change max |u − u^n| [m/s].
struct StepChange {
    double courant = 0.0;
    double largest_change = 0.0;
};
template <int Dim>
[[nodiscard]] StepChange measure_change(const MacGrid<Dim>& grid, const FluidState<Dim>& state,
                                        double dt);

/// Where the velocity (or, failing that, the body force or the pressure) first stops being
/// finite, in storage order; if all are finite, where the fastest fluid is. For the blow-up
/// message.
template <int Dim>
[[nodiscard]] std::string locate_non_finite(const MacGrid<Dim>& grid, const FluidState<Dim>& state);

} // namespace fddem
