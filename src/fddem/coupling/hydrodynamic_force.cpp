// SPDX-License-Identifier: MIT
#include "fddem/coupling/hydrodynamic_force.hpp"

namespace fddem {

template <int Dim>
void measure_hydrodynamic_forces(std::span<Particle<Dim>> bodies, double fluid_density,
                                 const TimeLevels& levels, bool is_inner_fluid_volume)
{
    const double rho = fluid_density;
    const double dt = levels.dt_effective;
    for (Particle<Dim>& body : bodies) {
        const MarkerCoupling<Dim>& c = body.coupling;
        Vec<Dim> lambda_sum = Vec<Dim>::Zero();
        AngularVec<Dim> lambda_moment = zero_angular<Dim>();
        for (std::size_t l = 0; l < c.markers.size(); ++l) {
            lambda_sum += c.markers.volumes[l] * c.lambda[l];
            lambda_moment += c.markers.volumes[l] * cross(c.offsets[l], c.lambda[l]);
        }
        if (is_inner_fluid_volume && body.is_free()) {
            body.force = rho * Vec<Dim>(c.inner_fluid.momentum - c.inner_fluid_n.momentum) / dt -
                         rho * lambda_sum;
            body.torque =
                rho * AngularVec<Dim>(c.inner_fluid.moment - c.inner_fluid_n.moment) / dt -
                rho * lambda_moment;
            continue;
        }
        const Vec<Dim> velocity_n = levels.history(body.velocity_n, body.velocity_nm1);
        const AngularVec<Dim> omega_n = levels.history(body.omega_n, body.omega_nm1);
        body.force = rho * body.volume() * (body.velocity - velocity_n) / dt - rho * lambda_sum;
        body.torque =
            rho * c.fluid_second_moment * (body.omega - omega_n) / dt - rho * lambda_moment;
    }
}

template void measure_hydrodynamic_forces<2>(std::span<Particle<2>>, double, const TimeLevels&,
                                             bool);
template void measure_hydrodynamic_forces<3>(std::span<Particle<3>>, double, const TimeLevels&,
                                             bool);

} // namespace fddem
