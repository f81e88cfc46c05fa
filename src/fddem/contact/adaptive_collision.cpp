// SPDX-License-Identifier: MIT
#include "fddem/contact/adaptive_collision.hpp"

#include "fddem/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace fddem {
namespace {

const AdaptiveCollision::Params& checked(const AdaptiveCollision::Params& p)
{
    if (!(p.restitution > 0.0 && p.restitution <= 1.0)) {
        throw InputError("", 0, "contact.restitution",
                         fmt::format("the adaptive model's dry restitution must be in (0, 1] "
                                     "(got {:g})",
                                     p.restitution));
    }
    if (p.collision_steps < 1) {
        throw InputError("", 0, "contact.collision_steps",
                         fmt::format("a collision must last at least one time step (got {})",
                                     p.collision_steps));
    }
    if (!(p.minimum_impact_speed > 0.0) || !std::isfinite(p.minimum_impact_speed)) {
        throw InputError(
            "", 0, "contact.minimum_impact_velocity",
            fmt::format("must be a finite number > 0 (got {:g})", p.minimum_impact_speed));
    }
    if (!(p.time_step > 0.0)) {
        throw InputError("", 0, "time.dt", "must be > 0");
    }
    if (!(p.tangential_ratio > 0.0)) {
        throw InputError("", 0, "contact.tangential_stiffness_ratio",
                         fmt::format("must be > 0 (got {:g})", p.tangential_ratio));
    }
    return p;
}

} // namespace

AdaptiveCollision::AdaptiveCollision(const Params& params)
    : params_(checked(params)), scaled_damping_(scaled_damping_for_restitution(params.restitution)),
      scaled_(scaled_hertz_damper_collision(scaled_damping_))
{
}

NormalCoefficients AdaptiveCollision::coefficients(const ContactPair& pair, double impact_speed,
                                                   double dt) const
{
    const double speed = std::max(impact_speed, params_.minimum_impact_speed);
    const double time_scale = params_.collision_steps * dt / scaled_.duration; // T
    const double mass = pair.effective_mass;
    // k_n L^{1/2} T² / m* = 1 with L = v T, and γ = d_n T / m* (hertz_damper_collision.hpp).
    return {mass / (std::sqrt(speed) * time_scale * time_scale * std::sqrt(time_scale)),
            scaled_damping_ * mass / time_scale};
}

ContactLaw AdaptiveCollision::law(NormalContact c, const ContactPair& /*pair*/,
                                  const NormalCoefficients& k) const noexcept
{
    const double root = std::sqrt(c.overlap); // α^{1/2}
    const double kappa = params_.tangential_ratio;
    return {k.stiffness * c.overlap * root + k.damping * c.overlap_rate,
            kappa * 1.5 * k.stiffness * root, std::sqrt(kappa) * k.damping};
}

double AdaptiveCollision::elastic_collision_time(const ContactPair& /*pair*/,
                                                 double /*impact_speed*/) const
{
    return params_.collision_steps * params_.time_step;
}

} // namespace fddem
