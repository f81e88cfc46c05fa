// SPDX-License-Identifier: MIT
#pragma once
/// Whether a body with a shallow marker ring is close enough to a wall for the resolved force
/// there not to be a converged quantity (docs/method.md §5, "The retracted ring beside a wall"):
/// `fddem run` warns once when it happens.

#include "fddem/bodies/particles.hpp"
#include "fddem/core/periodic_domain.hpp"
#include "fddem/core/vec.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/simulation/case_config.hpp"

#include <optional>
#include <string>

namespace fddem {

/// A ring retracted less than this [cells] below the surface (coupling.marker_retraction with
/// the retracted or surface layout): 0.3 h and 0.5 h drift with Δt beside a wall, 0.7 h does
/// not (cases/verification/disk_wall_squeeze). The paper's layout is not counted: its ring
/// depth follows bodies.n_rings and was measured only at 0.8 h.
inline constexpr double shallow_ring_depth = 0.6;

/// Closer to a wall than this [cells]: at half a cell the retracted sphere's force doubles from
/// Δt = 2e-4 to 5e-5 s (Gondret St 27's), and the 2D disk's drifts from 0.75 h on (254, 486,
/// 1198 μU at the squeeze case's three Δt): the warning comes late rather than early. Both
/// were measured at Re 30 with νΔt/h² = 0.009–0.07; in Stokes flow (the sphere–wall approach,
/// νΔt/h² = 50, within 4.5 % of Brenner down to 0.4 h) the drift was not measured, and the
/// warning there is a caution, not a measurement.
inline constexpr double near_wall_gap = 0.5;

/// The gap between a ball of `radius` at `centre` and the nearest wall or inflow side of the box
/// `domain` (an outflow copies the fluid and squeezes nothing; periodic axes have no side), in
/// cells of that side's axis (`spacing`); negative if it overlaps it, +∞ if there is none. Pure.
template <int Dim>
[[nodiscard]] double
gap_to_walls(const Vec<Dim>& centre, double radius, const PeriodicDomain<Dim>& domain,
             const BoundaryConditions<Dim>& bc, const Vec<Dim>& spacing) noexcept;

/// Whether the layout puts the outermost ring less than shallow_ring_depth cells deep and the
/// wall markers stay on (coupling.markers_off_at_walls off, or its reach below the kernel's
/// default_wall_marker_reach). Pure.
[[nodiscard]] bool has_shallow_ring_at_walls(const CouplingConfig& coupling) noexcept;

/// The warning's text at time `time` [s] for the first body closer than near_wall_gap cells to a
/// wall, if has_shallow_ring_at_walls; none otherwise. Pure.
template <int Dim>
[[nodiscard]] std::optional<std::string>
wall_ring_warning(const Particles<Dim>& bodies, const PeriodicDomain<Dim>& domain,
                  const BoundaryConditions<Dim>& bc, const Vec<Dim>& spacing,
                  const CouplingConfig& coupling, double time);

} // namespace fddem
