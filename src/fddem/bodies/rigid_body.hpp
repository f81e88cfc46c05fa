// SPDX-License-Identifier: MIT
#pragma once
/// A rigid particle: shape, material, and the state eqs. (13)–(14) and (17) advance.

#include "fddem/bodies/ball.hpp"
#include "fddem/core/vec.hpp"

namespace fddem {

/// How a body moves: by the fluid and gravity (free), at a given velocity (prescribed, e.g. a
/// towed disk), or not at all (fixed).
enum class Motion { free, prescribed, fixed };

template <int Dim>
struct RigidBody {
    int id = 0;
    Ball<Dim> shape{1.0};
    double density = 1.0; ///< ρs [kg/m³]
    Motion motion = Motion::free;

    Vec<Dim> centre = Vec<Dim>::Zero();   ///< [m]
    double angle = 0.0;                   ///< orientation θ about z [rad] (2D)
    Vec<Dim> velocity = Vec<Dim>::Zero(); ///< U [m/s]
    AngularVec<Dim> omega{};              ///< ω [rad/s]
    Vec<Dim> force = Vec<Dim>::Zero();    ///< hydrodynamic force of the last step [N] (2D: N/m)
    AngularVec<Dim> torque{};             ///< hydrodynamic torque of the last step [N·m]

    [[nodiscard]] double volume() const noexcept { return shape.volume(); }
    [[nodiscard]] double mass() const noexcept { return density * shape.volume(); }
    /// Moment of inertia about the centre [kg·m²] (2D: per unit depth); a ball's is isotropic.
    [[nodiscard]] double inertia() const noexcept { return density * shape.second_moment(); }
};

} // namespace fddem
