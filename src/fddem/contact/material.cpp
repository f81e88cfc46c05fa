// SPDX-License-Identifier: MIT
#include "fddem/contact/material.hpp"

#include <cmath>

namespace fddem {
namespace {

double shear_modulus(const Material& m)
{
    return m.young_modulus / (2.0 * (1.0 + m.poisson_ratio));
}

} // namespace

ContactPair make_contact_pair(const PairSide& a, const PairSide& b)
{
    ContactPair p;
    p.effective_mass = 1.0 / (a.inverse_mass + b.inverse_mass);
    p.effective_inertia = 1.0 / (a.inverse_inertia + b.inverse_inertia);
    p.effective_radius = 1.0 / (a.curvature + b.curvature);
    const Material& i = a.material;
    const Material& j = b.material;
    if (i.young_modulus > 0.0 && j.young_modulus > 0.0) {
        p.young_modulus = 1.0 / ((1.0 - i.poisson_ratio * i.poisson_ratio) / i.young_modulus +
                                 (1.0 - j.poisson_ratio * j.poisson_ratio) / j.young_modulus);
        p.shear_modulus = 1.0 / ((2.0 - i.poisson_ratio) / shear_modulus(i) +
                                 (2.0 - j.poisson_ratio) / shear_modulus(j));
    }
    p.friction = std::sqrt(i.friction * j.friction);
    p.rolling_friction = std::sqrt(i.rolling_friction * j.rolling_friction);
    p.restitution = std::sqrt(i.restitution * j.restitution);
    return p;
}

PairSide ball_side(double mass, double inertia, double radius, const Material& material,
                   bool is_movable)
{
    return {is_movable ? 1.0 / mass : 0.0, is_movable ? 1.0 / inertia : 0.0, 1.0 / radius,
            material};
}

PairSide wall_side(const Material& material)
{
    return {0.0, 0.0, 0.0, material};
}

} // namespace fddem
