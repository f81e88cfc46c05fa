// SPDX-License-Identifier: MIT
#pragma once
/// What a normal contact model must provide (STYLE.md §6).

#include <concepts>

namespace fddem {

/// The normal state of one contact: α > 0 when the bodies overlap; α̇ > 0 while they approach.
struct NormalContact {
    double overlap;      ///< α [m]
    double overlap_rate; ///< α̇ [m/s]
};

template <class M>
concept ContactModel = requires(const M m, NormalContact c, double mass)
{
    {
        m.normal_force(c)
        } -> std::same_as<double>; // along the normal, repulsive > 0 [N]
    {
        m.contact_time(mass)
        } -> std::same_as<double>; // duration of a binary collision [s]
};

} // namespace fddem
