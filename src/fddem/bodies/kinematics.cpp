// SPDX-License-Identifier: MIT
#include "fddem/bodies/kinematics.hpp"

namespace fddem {

template <int Dim>
void move_bodies(std::span<Particle<Dim>> bodies, double dt, bool is_paper_contact)
{
    for (Particle<Dim>& body : bodies) {
        if (body.motion == Motion::fixed) {
            continue;
        }
        if (is_paper_contact && body.contact.is_in_contact) {
            body.centre = body.contact.centre;
        } else {
            body.centre += 0.5 * dt * (body.velocity + body.velocity_n); // eq. (17)
        }
        const AngularVec<Dim> mean_omega = 0.5 * (body.omega + body.omega_n);
        body.orientation = turned<Dim>(body.orientation, mean_omega, dt);
    }
}

template <int Dim>
void wrap_centres(std::span<Particle<Dim>> bodies, const PeriodicDomain<Dim>& domain)
{
    for (Particle<Dim>& body : bodies) {
        body.centre = domain.wrap(body.centre);
    }
}

template void move_bodies<2>(std::span<Particle<2>>, double, bool);
template void move_bodies<3>(std::span<Particle<3>>, double, bool);
template void wrap_centres<2>(std::span<Particle<2>>, const PeriodicDomain<2>&);
template void wrap_centres<3>(std::span<Particle<3>>, const PeriodicDomain<3>&);

} // namespace fddem
