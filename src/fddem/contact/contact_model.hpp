// SPDX-License-Identifier: MIT
#pragma once
/// What a contact model must provide (STYLE.md §6). A model turns the normal state of one
/// contact and the pair's constants into the normal force and the tangential spring and dashpot
/// coefficients; the tangential spring's history, the Coulomb limit and the rolling resistance
/// are the same for every model (contact/tangential_contact.hpp).

#include "fddem/contact/material.hpp"

#include <concepts>

namespace fddem {

/// The normal state of one contact: α > 0 when the bodies overlap; α̇ > 0 while they approach.
struct NormalContact {
    double overlap;      ///< α [m]
    double overlap_rate; ///< α̇ [m/s]
};

/// The force law of one contact at its current overlap (2D: all per unit depth).
struct ContactLaw {
    double normal_force = 0.0;         ///< F_n along the normal, repulsive > 0 [N]
    double tangential_stiffness = 0.0; ///< k_t [N/m]
    double tangential_damping = 0.0;   ///< c_t [N·s/m]
};

template <class M>
concept ContactModel = requires(const M m, NormalContact c, ContactPair p, double speed)
{
    {
        m.law(c, p)
        } -> std::same_as<ContactLaw>;
    {
        m.elastic_collision_time(p, speed)
        } -> std::same_as<double>; // undamped binary collision at impact speed `speed` [s]
    {
        m.restitution(p)
        } -> std::same_as<double>; // normal restitution of a binary collision
};

} // namespace fddem
