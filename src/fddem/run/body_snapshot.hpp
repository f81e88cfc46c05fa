// SPDX-License-Identifier: MIT
#pragma once
/// What the outputs show of each body (particles.csv, particles/*.vtp, summary.json), copied out
/// of the simulation in one place: how the simulation stores its bodies is known here only.

#include "fddem/core/vec.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cstddef>
#include <vector>

namespace fddem {

template <int Dim>
struct BodySnapshot {
    int id = 0;
    double radius = 0.0;                            ///< [m]
    Vec<Dim> centre = Vec<Dim>::Zero();             ///< [m]
    Vec<Dim> velocity = Vec<Dim>::Zero();           ///< U [m/s]
    AngularVec<Dim> omega = zero_angular<Dim>();    ///< ω [rad/s]
    Orientation<Dim> orientation = unturned<Dim>(); ///< θ [rad] (2D), q (3D)
    Vec<Dim> force = Vec<Dim>::Zero();              ///< hydrodynamic, last step [N]
    AngularVec<Dim> torque = zero_angular<Dim>();   ///< hydrodynamic, last step [N·m]
    /// Dry contact (spring–dashpot, friction, rolling resistance), mean over the DEM sub-steps
    Vec<Dim> contact_force = Vec<Dim>::Zero();            ///< [N]
    AngularVec<Dim> contact_torque = zero_angular<Dim>(); ///< [N·m]
    /// Lubrication correction (contact/lubrication.hpp), mean over the DEM sub-steps
    Vec<Dim> lubrication_force = Vec<Dim>::Zero();            ///< [N]
    AngularVec<Dim> lubrication_torque = zero_angular<Dim>(); ///< [N·m]
};

/// Every body of `sim`, in the simulation's order (2D forces and torques per unit depth).
template <int Dim>
[[nodiscard]] std::vector<BodySnapshot<Dim>> body_snapshots(const Simulation<Dim>& sim);

/// How many bodies `sim` has.
template <int Dim>
[[nodiscard]] std::size_t body_count(const Simulation<Dim>& sim);

/// Markers of the first body (summary.json); 0 without bodies.
template <int Dim>
[[nodiscard]] std::size_t markers_per_body(const Simulation<Dim>& sim);

} // namespace fddem
