// SPDX-License-Identifier: MIT
#pragma once
/// A body's orientation and its update by eq. (17)'s rule for the angular motion: an angle θ
/// about z in 2D, a unit quaternion in 3D (issue 14). A ball's hydrodynamics do not depend on
/// it, but its markers turn with it, so that a marked sphere's rotation can be seen and a later
/// non-round shape is placed right.

#include "fddem/core/vec.hpp"

#include <Eigen/Geometry>

namespace fddem {

template <int Dim>
struct OrientationOf;
template <>
struct OrientationOf<2> {
    using type = double; ///< θ about z [rad]
};
template <>
struct OrientationOf<3> {
    using type = Eigen::Quaterniond; ///< unit quaternion, body frame → world frame
};
template <int Dim>
using Orientation = typename OrientationOf<Dim>::type;

/// The orientation of a body that has not turned.
template <int Dim>
[[nodiscard]] Orientation<Dim> unturned()
{
    if constexpr (Dim == 2) {
        return 0.0;
    } else {
        return Eigen::Quaterniond::Identity();
    }
}

/// A body-frame vector in the world frame.
template <int Dim>
[[nodiscard]] Vec<Dim> to_world(const Orientation<Dim>& orientation, const Vec<Dim>& r)
{
    if constexpr (Dim == 2) {
        const double cs = std::cos(orientation);
        const double sn = std::sin(orientation);
        return {cs * r.x() - sn * r.y(), sn * r.x() + cs * r.y()};
    } else {
        return orientation * r;
    }
}

/// The orientation after a step of `dt` [s] at the mean of ω^n and ω^{n+1} (world frame), the
/// angular counterpart of eq. (17): θ + Δt ω̄ in 2D; in 3D the rotation by the angle |ω̄| Δt
/// about ω̄ applied to q, exact for a constant ω̄ and renormalised, so that |q| stays 1 to
/// round-off over any number of steps.
template <int Dim>
[[nodiscard]] Orientation<Dim> turned(const Orientation<Dim>& orientation,
                                      const AngularVec<Dim>& mean_omega, double dt)
{
    if constexpr (Dim == 2) {
        return orientation + dt * mean_omega;
    } else {
        const double angle = mean_omega.norm() * dt;
        if (angle == 0.0) {
            return orientation;
        }
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, mean_omega.normalized()));
        return (turn * orientation).normalized();
    }
}

} // namespace fddem
