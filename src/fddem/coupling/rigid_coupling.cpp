// SPDX-License-Identifier: MIT
#include "fddem/coupling/rigid_coupling.hpp"

#include <algorithm>
#include <cassert>

namespace fddem {

template <int Dim>
RigidBalance<Dim> rigid_balance(const RigidUpdateInput<Dim>& in, std::span<const Vec<Dim>> offsets,
                                std::span<const double> volumes,
                                std::span<const Vec<Dim>> fluid_at_markers,
                                std::span<const Vec<Dim>> lambda_star)
{
    const double dt = in.dt;
    if (in.inner_fluid != nullptr) {
        // eqs. (13')–(14') of coupling/inner_fluid.hpp: the inner fluid's change over the
        // cells, the markers' λ* alone
        Vec<Dim> force = Vec<Dim>::Zero();
        AngularVec<Dim> moment = zero_angular<Dim>();
        for (std::size_t l = 0; l < offsets.size(); ++l) {
            force += volumes[l] * lambda_star[l];
            moment += volumes[l] * cross(offsets[l], lambda_star[l]);
        }
        const InnerFluid<Dim>& now = *in.inner_fluid;
        const InnerFluid<Dim>& before = *in.inner_fluid_n;
        return {in.body_density * in.volume * in.velocity_n / dt +
                    (in.body_density - in.fluid_density) * in.volume * in.gravity +
                    in.fluid_density * (Vec<Dim>(now.momentum - before.momentum) / dt - force) +
                    in.external_force,
                in.body_density * in.volume / dt,
                apply<Dim>(in.body_inertia, in.omega_n) / dt -
                    gyroscopic<Dim>(in.body_inertia, in.omega_n) +
                    in.fluid_density * (AngularVec<Dim>(now.moment - before.moment) / dt - moment) +
                    in.external_torque,
                in.body_inertia / dt};
    }
    Vec<Dim> momentum = Vec<Dim>::Zero();
    AngularVec<Dim> angular{};
    if constexpr (Dim == 3) {
        angular = Vec<3>::Zero();
    }
    for (std::size_t l = 0; l < offsets.size(); ++l) {
        const Vec<Dim> source = fluid_at_markers[l] / in.dt - lambda_star[l];
        momentum += volumes[l] * source;
        angular += volumes[l] * cross(offsets[l], source);
    }
    const double buoyant_mass = (in.body_density - in.fluid_density) * in.volume;
    const Inertia<Dim> excess = in.body_inertia - in.fluid_density * in.fluid_second_moment;
    return {buoyant_mass * (in.velocity_n / dt + in.gravity) + in.fluid_density * momentum +
                in.external_force,
            in.body_density * in.volume / dt,
            apply<Dim>(excess, in.omega_n) / dt - gyroscopic<Dim>(excess, in.omega_n) +
                in.fluid_density * angular + in.external_torque,
            in.body_inertia / dt};
}

template <int Dim>
RigidVelocity<Dim>
rigid_velocity(const RigidUpdateInput<Dim>& in, std::span<const Vec<Dim>> offsets,
               std::span<const double> volumes, std::span<const Vec<Dim>> fluid_at_markers,
               std::span<const Vec<Dim>> lambda_star)
{
    const RigidBalance<Dim> b =
        rigid_balance<Dim>(in, offsets, volumes, fluid_at_markers, lambda_star);
    return {b.impulse_rate / b.mass_rate, solve<Dim>(b.inertia_rate, b.moment_rate)};
}

template <int Dim>
double update_marker_force(const RigidVelocity<Dim>& motion, std::span<const Vec<Dim>> offsets,
                           std::span<const Vec<Dim>> fluid_at_markers,
                           std::span<const Vec<Dim>> lambda_star, double dt,
                           std::span<Vec<Dim>> lambda, std::span<const Vec<Dim>> gains)
{
    assert(gains.empty() || gains.size() == offsets.size());
    double defect = 0.0;
    for (std::size_t l = 0; l < offsets.size(); ++l) {
        const Vec<Dim> rigid = motion.velocity + cross(motion.omega, offsets[l]);
        const Vec<Dim> slip = rigid - fluid_at_markers[l];
        lambda[l] = lambda_star[l] + (gains.empty() ? Vec<Dim>(slip / dt)
                                                    : Vec<Dim>(slip.cwiseQuotient(gains[l]) / dt));
        defect = std::max(defect, slip.norm());
    }
    return defect;
}

template <int Dim>
double forcing_change(std::span<const Vec<Dim>> offsets, std::span<const double> volumes,
                      std::span<const Vec<Dim>> lambda, std::span<const Vec<Dim>> lambda_star,
                      double dt, double volume, double radius)
{
    Vec<Dim> force = Vec<Dim>::Zero();
    AngularVec<Dim> moment = zero_angular<Dim>();
    for (std::size_t l = 0; l < offsets.size(); ++l) {
        const Vec<Dim> change = volumes[l] * (lambda[l] - lambda_star[l]);
        force += change;
        moment += cross(offsets[l], change);
    }
    return dt * (force.norm() + 2.0 * magnitude<Dim>(moment) / radius) / volume;
}

template RigidBalance<2> rigid_balance<2>(const RigidUpdateInput<2>&, std::span<const Vec<2>>,
                                          std::span<const double>, std::span<const Vec<2>>,
                                          std::span<const Vec<2>>);
template RigidBalance<3> rigid_balance<3>(const RigidUpdateInput<3>&, std::span<const Vec<3>>,
                                          std::span<const double>, std::span<const Vec<3>>,
                                          std::span<const Vec<3>>);
template RigidVelocity<2> rigid_velocity<2>(const RigidUpdateInput<2>&, std::span<const Vec<2>>,
                                            std::span<const double>, std::span<const Vec<2>>,
                                            std::span<const Vec<2>>);
template RigidVelocity<3> rigid_velocity<3>(const RigidUpdateInput<3>&, std::span<const Vec<3>>,
                                            std::span<const double>, std::span<const Vec<3>>,
                                            std::span<const Vec<3>>);
template double update_marker_force<2>(const RigidVelocity<2>&, std::span<const Vec<2>>,
                                       std::span<const Vec<2>>, std::span<const Vec<2>>, double,
                                       std::span<Vec<2>>, std::span<const Vec<2>>);
template double update_marker_force<3>(const RigidVelocity<3>&, std::span<const Vec<3>>,
                                       std::span<const Vec<3>>, std::span<const Vec<3>>, double,
                                       std::span<Vec<3>>, std::span<const Vec<3>>);
template double forcing_change<2>(std::span<const Vec<2>>, std::span<const double>,
                                  std::span<const Vec<2>>, std::span<const Vec<2>>, double, double,
                                  double);
template double forcing_change<3>(std::span<const Vec<3>>, std::span<const double>,
                                  std::span<const Vec<3>>, std::span<const Vec<3>>, double, double,
                                  double);

} // namespace fddem
