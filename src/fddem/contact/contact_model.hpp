// SPDX-License-Identifier: MIT
#pragma once
/// What a contact model must provide (STYLE.md §6). A model turns the normal state of one
/// contact and the pair's constants into the normal force and the tangential spring and dashpot
/// coefficients; the tangential spring's history, the Coulomb limit and the rolling resistance
/// are the same for every model (contact/tangential_contact.hpp). A model whose constants are
/// fixed per contact when it opens (PerContactModel: the adaptive model) also says how; the DEM
/// keeps them in the contact history while the contact stays open.

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

/// The normal constants a PerContactModel fixes for one contact when it opens.
struct NormalCoefficients {
    double stiffness = 0.0; ///< k_n [N/m^{3/2}] (2D: per unit depth)
    double damping = 0.0;   ///< d_n [N·s/m] (2D: per unit depth)
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

/// A model whose law depends on constants fixed when the contact opens, from the approach speed
/// and the fluid time step Δt then.
template <class M>
concept PerContactModel = requires(const M m, NormalContact c, ContactPair p, double speed,
                                   double dt, NormalCoefficients k)
{
    {
        m.coefficients(p, speed, dt)
        } -> std::same_as<NormalCoefficients>;
    {
        m.law(c, p, k)
        } -> std::same_as<ContactLaw>;
    {
        m.elastic_collision_time(p, speed)
        } -> std::same_as<double>; // the collision's duration [s]
    {
        m.restitution(p)
        } -> std::same_as<double>;
};

} // namespace fddem
