// SPDX-License-Identifier: MIT
#include "fddem/simulation/contact_model_input.hpp"

namespace fddem {

ContactModelInput contact_model_input(const CaseConfig& c)
{
    const ContactConfig& contact = c.contact;
    const ContactDerived& derived = contact.derived;
    ContactModelInput input;
    input.linear = {derived.stiffness, derived.damping, contact.tangential_stiffness_ratio};
    input.reference_mass = derived.reference_mass;
    input.adaptive = {contact.surface.restitution.value_or(1.0), contact.collision_steps,
                      derived.minimum_impact_velocity, c.time.dt,
                      contact.tangential_stiffness_ratio};
    return input;
}

} // namespace fddem
