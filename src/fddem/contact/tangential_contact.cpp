// SPDX-License-Identifier: MIT
#include "fddem/contact/tangential_contact.hpp"

#include <algorithm>
#include <cmath>

namespace fddem {
namespace {

/// The rolling part of a relative angular velocity: in 2D ω is about z, normal to every
/// in-plane contact normal, so all of it rolls; in 3D the twist about n is removed.
template <int Dim>
AngularVec<Dim> rolling_part(const AngularVec<Dim>& omega, const Vec<Dim>& normal)
{
    if constexpr (Dim == 2) {
        return omega;
    } else {
        return omega - omega.dot(normal) * normal;
    }
}

} // namespace

template <int Dim>
Vec<Dim> tangential_force(const Vec<Dim>& normal, const Vec<Dim>& slip_velocity,
                          const ContactLaw& law, double friction, double step,
                          Vec<Dim>& displacement)
{
    // Keep the spring in the tangent plane as the contact turns, without changing its length.
    const double length = displacement.norm();
    Vec<Dim> xi = displacement - displacement.dot(normal) * normal;
    const double projected = xi.norm();
    if (projected > 0.0) {
        xi *= length / projected;
    }
    xi += step * slip_velocity;
    Vec<Dim> force = -law.tangential_stiffness * xi - law.tangential_damping * slip_velocity;
    const double limit = friction * std::max(law.normal_force, 0.0);
    const double size = force.norm();
    if (size > limit) {
        force *= limit / size;
        xi = law.tangential_stiffness > 0.0 ? Vec<Dim>(-force / law.tangential_stiffness)
                                            : Vec<Dim>(Vec<Dim>::Zero());
    }
    displacement = xi;
    return force;
}

template <int Dim>
AngularVec<Dim> rolling_torque(const AngularVec<Dim>& relative_omega, const Vec<Dim>& normal,
                               double normal_force, const ContactPair& pair, double step)
{
    const AngularVec<Dim> rolling = rolling_part<Dim>(relative_omega, normal);
    const double speed = magnitude<Dim>(rolling);
    const double full = pair.rolling_friction * pair.effective_radius * std::max(normal_force, 0.0);
    if (speed == 0.0 || full == 0.0) {
        return zero_angular<Dim>();
    }
    const double torque = std::min(full, pair.effective_inertia * speed / step);
    return AngularVec<Dim>(rolling * (-torque / speed));
}

template Vec<2> tangential_force<2>(const Vec<2>&, const Vec<2>&, const ContactLaw&, double, double,
                                    Vec<2>&);
template Vec<3> tangential_force<3>(const Vec<3>&, const Vec<3>&, const ContactLaw&, double, double,
                                    Vec<3>&);
template AngularVec<2> rolling_torque<2>(const AngularVec<2>&, const Vec<2>&, double,
                                         const ContactPair&, double);
template AngularVec<3> rolling_torque<3>(const AngularVec<3>&, const Vec<3>&, double,
                                         const ContactPair&, double);

} // namespace fddem
