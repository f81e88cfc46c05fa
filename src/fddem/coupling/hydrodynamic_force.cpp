// SPDX-License-Identifier: MIT
#include "fddem/coupling/hydrodynamic_force.hpp"

namespace fddem {

template <int Dim>
void measure_hydrodynamic_forces(std::span<Particle<Dim>> bodies, double fluid_density, double dt)
{
    const double rho = fluid_density;
    for (Particle<Dim>& body : bodies) {
        const MarkerCoupling<Dim>& c = body.coupling;
        Vec<Dim> lambda_sum = Vec<Dim>::Zero();
        AngularVec<Dim> lambda_moment = zero_angular<Dim>();
        for (std::size_t l = 0; l < c.markers.size(); ++l) {
            lambda_sum += c.markers.volumes[l] * c.lambda[l];
            lambda_moment += c.markers.volumes[l] * cross(c.offsets[l], c.lambda[l]);
        }
        body.force =
            rho * body.volume() * (body.velocity - body.velocity_n) / dt - rho * lambda_sum;
        body.torque =
            rho * c.fluid_second_moment * (body.omega - body.omega_n) / dt - rho * lambda_moment;
    }
}

template void measure_hydrodynamic_forces<2>(std::span<Particle<2>>, double, double);
template void measure_hydrodynamic_forces<3>(std::span<Particle<3>>, double, double);

} // namespace fddem
