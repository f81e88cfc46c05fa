// SPDX-License-Identifier: MIT
#include "fddem/contact/linear_spring_dashpot.hpp"

#include "fddem/core/errors.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace fddem {
namespace {

double damping_ratio(const LinearSpringDashpot::Params& p, double mass)
{
    return p.damping / (2.0 * std::sqrt(p.stiffness * mass));
}

} // namespace

LinearSpringDashpot::LinearSpringDashpot(const Params& params, double reference_mass)
    : params_(params)
{
    if (!(params.stiffness > 0.0)) {
        throw InputError("", 0, "contact.stiffness",
                         "must be > 0 (got " + std::to_string(params.stiffness) + ")");
    }
    if (!(params.damping >= 0.0)) {
        throw InputError("", 0, "contact.damping",
                         "must be >= 0 (got " + std::to_string(params.damping) + ")");
    }
    if (!(params.tangential_ratio > 0.0)) {
        throw InputError("", 0, "contact.tangential_stiffness_ratio",
                         "must be > 0 (got " + std::to_string(params.tangential_ratio) + ")");
    }
    if (damping_ratio(params, reference_mass) >= 1.0) {
        throw InputError("", 0, "contact.damping",
                         "overdamped: damping ratio c/(2 sqrt(k m)) = " +
                             std::to_string(damping_ratio(params, reference_mass)) +
                             " >= 1, the bodies would never separate");
    }
}

LinearSpringDashpot::Params LinearSpringDashpot::from_restitution(double restitution,
                                                                  double contact_time, double mass)
{
    if (!(restitution > 0.0 && restitution <= 1.0)) {
        throw InputError("", 0, "contact.restitution", "must be in (0, 1]");
    }
    if (!(contact_time > 0.0)) {
        throw InputError("", 0, "contact.contact_time", "must be > 0");
    }
    const double log_e = std::log(restitution);
    // −ln e ≥ 0, written |ln e| so that e = 1 gives +0 (not −0 in the printed damping)
    const double zeta =
        std::abs(log_e) / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
    const double omega_d = std::numbers::pi / contact_time;
    const double omega_0 = omega_d / std::sqrt(1.0 - zeta * zeta);
    const double stiffness = mass * omega_0 * omega_0;
    return {stiffness, 2.0 * zeta * std::sqrt(stiffness * mass)};
}

ContactLaw LinearSpringDashpot::law(NormalContact c, const ContactPair& /*pair*/) const noexcept
{
    return {normal_force(c), params_.tangential_ratio * params_.stiffness,
            std::sqrt(params_.tangential_ratio) * params_.damping};
}

double LinearSpringDashpot::elastic_collision_time(const ContactPair& pair,
                                                   double /*impact_speed*/) const
{
    return std::numbers::pi * std::sqrt(pair.effective_mass / params_.stiffness);
}

double LinearSpringDashpot::contact_time(double mass) const
{
    const double zeta = damping_ratio(params_, mass);
    const double omega_0 = std::sqrt(params_.stiffness / mass);
    return std::numbers::pi / (omega_0 * std::sqrt(1.0 - zeta * zeta));
}

double LinearSpringDashpot::restitution(double mass) const
{
    const double zeta = damping_ratio(params_, mass);
    return std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta));
}

} // namespace fddem
