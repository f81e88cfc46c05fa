// SPDX-License-Identifier: MIT
#pragma once
/// Narrow phase: the geometry of one contact between two balls or a ball and a box wall
/// (paper Fig. 2). Pure functions of the bodies' state.
///
/// For bodies i and j with centres x, radii r, velocities U and ω:
///   n = (x_j − x_i)/|x_j − x_i|            unit normal from i to j
///   α = r_i + r_j − |x_j − x_i|             overlap (> 0 in contact)
///   v = (U_j + ω_j × (−r_j n)) − (U_i + ω_i × (r_i n))   velocity of j relative to i at the
///                                          contact point
///   α̇ = −v · n                             overlap rate (> 0 while approaching)
///   v_t = v − (v · n) n                     tangential slip velocity (for friction models)
/// A wall is a body of infinite mass at rest; its normal points from the ball into the wall.

#include "fddem/core/vec.hpp"

#include <cmath>

namespace fddem {

template <int Dim>
struct ContactGeometry {
    Vec<Dim> normal = Vec<Dim>::Zero();        ///< from the first body to the second
    double overlap = 0.0;                      ///< α [m]
    double overlap_rate = 0.0;                 ///< α̇ [m/s]
    Vec<Dim> slip_velocity = Vec<Dim>::Zero(); ///< v_t of the second relative to the first
    Vec<Dim> lever_first = Vec<Dim>::Zero();   ///< contact point − first centre [m]
    Vec<Dim> lever_second = Vec<Dim>::Zero();  ///< contact point − second centre [m]
};

/// The kinematic state of a ball as the contact geometry needs it.
template <int Dim>
struct BallState {
    Vec<Dim> centre;
    double radius;
    Vec<Dim> velocity;
    AngularVec<Dim> omega;
};

/// Contact between balls a and b (a ≠ b in position; coincident centres get the normal +x).
template <int Dim>
[[nodiscard]] ContactGeometry<Dim> ball_ball_contact(const BallState<Dim>& a,
                                                     const BallState<Dim>& b)
{
    ContactGeometry<Dim> g;
    const Vec<Dim> d = b.centre - a.centre;
    const double distance = d.norm();
    g.normal = distance > 0.0 ? Vec<Dim>(d / distance) : Vec<Dim>(Vec<Dim>::Unit(0));
    g.overlap = a.radius + b.radius - distance;
    g.lever_first = a.radius * g.normal;
    g.lever_second = -b.radius * g.normal;
    const Vec<Dim> v = (b.velocity + cross(b.omega, g.lever_second)) -
                       (a.velocity + cross(a.omega, g.lever_first));
    const double normal_velocity = v.dot(g.normal);
    g.overlap_rate = -normal_velocity;
    g.slip_velocity = v - normal_velocity * g.normal;
    return g;
}

/// Contact between ball a and the plane wall x_axis = position, the box lying on the side
/// `side` = 0 (wall at the low end: the box is x_axis > position) or 1 (high end). The wall
/// is the second body.
template <int Dim>
[[nodiscard]] ContactGeometry<Dim> ball_wall_contact(const BallState<Dim>& a, int axis, int side,
                                                     double position)
{
    ContactGeometry<Dim> g;
    const double sign = side == 0 ? -1.0 : 1.0; // the normal points out of the box
    g.normal = sign * Vec<Dim>::Unit(axis);
    const double distance = sign * (position - a.centre[axis]);
    g.overlap = a.radius - distance;
    g.lever_first = a.radius * g.normal;
    g.lever_second = Vec<Dim>::Zero();
    const Vec<Dim> v = -(a.velocity + cross(a.omega, g.lever_first));
    const double normal_velocity = v.dot(g.normal);
    g.overlap_rate = -normal_velocity;
    g.slip_velocity = v - normal_velocity * g.normal;
    return g;
}

} // namespace fddem
