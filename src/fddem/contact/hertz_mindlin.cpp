// SPDX-License-Identifier: MIT
#include "fddem/contact/hertz_mindlin.hpp"

#include <cmath>
#include <numbers>

namespace fddem {

double HertzMindlin::damping_constant(double restitution)
{
    const double log_e = std::log(restitution);
    // −ln e ≥ 0, written |ln e| so that e = 1 gives +0 (not −0 in the printed damping)
    const double zeta =
        std::abs(log_e) / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
    return std::sqrt(5.0) * zeta;
}

double HertzMindlin::hertz_stiffness(const ContactPair& pair)
{
    return 4.0 / 3.0 * pair.young_modulus * std::sqrt(pair.effective_radius);
}

ContactLaw HertzMindlin::law(NormalContact c, const ContactPair& pair)
{
    const double k_hertz = hertz_stiffness(pair);
    const double root = std::sqrt(c.overlap); // α^{1/2}
    const double normal_damping = damping_constant(pair.restitution) *
                                  std::sqrt(pair.effective_mass * k_hertz) * std::sqrt(root);
    const double contact_radius = std::sqrt(pair.effective_radius * c.overlap); // a = √(R* α)
    const double normal_tangent_stiffness = 2.0 * pair.young_modulus * contact_radius; // S_n
    const double tangential_stiffness = 8.0 * pair.shear_modulus * contact_radius;
    return {k_hertz * c.overlap * root + normal_damping * c.overlap_rate, tangential_stiffness,
            normal_damping * std::sqrt(tangential_stiffness / normal_tangent_stiffness)};
}

double HertzMindlin::elastic_collision_time(const ContactPair& pair, double impact_speed)
{
    const double max_overlap = std::pow(
        1.25 * pair.effective_mass * impact_speed * impact_speed / hertz_stiffness(pair), 0.4);
    const double integral = std::sqrt(std::numbers::pi) * std::tgamma(1.4) / std::tgamma(0.9);
    return 2.0 * integral * max_overlap / impact_speed;
}

} // namespace fddem
