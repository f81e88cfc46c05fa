// SPDX-License-Identifier: MIT
#pragma once
/// Narrow phase: the geometry of one contact between two balls or a ball and a box wall
/// (paper Fig. 2). Pure functions of the bodies' state.
///
/// For bodies i and j with centres x, radii r, velocities U and ω:
///   n = (x_j − x_i)/|x_j − x_i|            unit normal from i to j
///   α = r_i + r_j − |x_j − x_i|             overlap (> 0 in contact)
///   c = x_i + (r_i − α/2) n = x_j − (r_j − α/2) n   contact point, the middle of the overlap
///   v = (U_j + ω_j × (c − x_j)) − (U_i + ω_i × (c − x_i))   velocity of j relative to i at c
///   α̇ = −v · n                             overlap rate (> 0 while approaching)
///   v_t = v − (v · n) n                     tangential slip velocity (friction)
///   ω_r = ω_i − ω_j                         relative angular velocity (rolling resistance)
/// Both bodies' lever arms end at the same point c, so a pair of opposite forces there has no
/// net moment about any point: a collision conserves angular momentum exactly.
/// A wall is a body of infinite mass that does not turn and may slide along itself (a lid);
/// its normal points from the ball into the wall.

#include "fddem/core/periodic_domain.hpp"
#include "fddem/core/vec.hpp"

#include <cmath>

namespace fddem {

template <int Dim>
struct ContactGeometry {
    Vec<Dim> normal = Vec<Dim>::Zero();        ///< from the first body to the second
    double overlap = 0.0;                      ///< α [m]
    double overlap_rate = 0.0;                 ///< α̇ [m/s]
    Vec<Dim> slip_velocity = Vec<Dim>::Zero(); ///< v_t of the second relative to the first
    AngularVec<Dim> rolling_omega = zero_angular<Dim>(); ///< ω_first − ω_second [rad/s]
    Vec<Dim> lever_first = Vec<Dim>::Zero();             ///< contact point − first centre [m]
    Vec<Dim> lever_second = Vec<Dim>::Zero();            ///< contact point − second centre [m]
};

/// The kinematic state of a ball as the contact geometry needs it.
template <int Dim>
struct BallState {
    Vec<Dim> centre;
    double radius;
    Vec<Dim> velocity;
    AngularVec<Dim> omega;
};

/// Normal rate and slip from the relative velocity v of the second body at the contact point.
template <int Dim>
void set_relative_velocity(ContactGeometry<Dim>& g, const Vec<Dim>& v)
{
    const double normal_velocity = v.dot(g.normal);
    g.overlap_rate = -normal_velocity;
    g.slip_velocity = v - normal_velocity * g.normal;
}

/// Contact between balls a and b whose centres are `separation` = x_b − x_a apart: across a
/// periodic boundary, the nearest image's (PeriodicDomain::minimum_image); the normal and the
/// lever arms follow from it, the centres themselves are not read.
template <int Dim>
[[nodiscard]] ContactGeometry<Dim>
ball_ball_contact(const BallState<Dim>& a, const BallState<Dim>& b, const Vec<Dim>& separation)
{
    ContactGeometry<Dim> g;
    const Vec<Dim>& d = separation;
    const double distance = d.norm();
    g.normal = distance > 0.0 ? Vec<Dim>(d / distance) : Vec<Dim>(Vec<Dim>::Unit(0));
    g.overlap = a.radius + b.radius - distance;
    g.lever_first = (a.radius - 0.5 * g.overlap) * g.normal;
    g.lever_second = -(b.radius - 0.5 * g.overlap) * g.normal;
    set_relative_velocity<Dim>(g, (b.velocity + cross(b.omega, g.lever_second)) -
                                      (a.velocity + cross(a.omega, g.lever_first)));
    g.rolling_omega = a.omega - b.omega;
    return g;
}

/// Contact between balls a and b (a ≠ b in position; coincident centres get the normal +x).
template <int Dim>
[[nodiscard]] ContactGeometry<Dim> ball_ball_contact(const BallState<Dim>& a,
                                                     const BallState<Dim>& b)
{
    return ball_ball_contact(a, b, Vec<Dim>(b.centre - a.centre));
}

/// Contact between balls a and b in a box with periodic axes: between their nearest images.
template <int Dim>
[[nodiscard]] ContactGeometry<Dim> ball_ball_contact(const BallState<Dim>& a,
                                                     const BallState<Dim>& b,
                                                     const PeriodicDomain<Dim>& domain)
{
    return ball_ball_contact(a, b, domain.minimum_image(b.centre - a.centre));
}

/// Contact between ball a and the plane wall x_axis = position, the box lying on the side
/// `side` = 0 (wall at the low end: the box is x_axis > position) or 1 (high end). The wall
/// is the second body; it moves at `wall_velocity` (tangential: a sliding wall).
template <int Dim>
[[nodiscard]] ContactGeometry<Dim>
ball_wall_contact(const BallState<Dim>& a, int axis, int side, double position,
                  const Vec<Dim>& wall_velocity = Vec<Dim>::Zero())
{
    ContactGeometry<Dim> g;
    const double sign = side == 0 ? -1.0 : 1.0; // the normal points out of the box
    g.normal = sign * Vec<Dim>::Unit(axis);
    const double distance = sign * (position - a.centre[axis]);
    g.overlap = a.radius - distance;
    g.lever_first = (a.radius - 0.5 * g.overlap) * g.normal;
    g.lever_second = Vec<Dim>::Zero();
    set_relative_velocity<Dim>(g, wall_velocity - (a.velocity + cross(a.omega, g.lever_first)));
    g.rolling_omega = a.omega;
    return g;
}

} // namespace fddem
