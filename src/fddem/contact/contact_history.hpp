// SPDX-License-Identifier: MIT
#pragma once
/// The state of the contacts that persists from one sub-step and time step to the next: the
/// elastic tangential displacement ξ of each open contact (tangential_contact.hpp) and, for a
/// model that fixes them when a contact opens (the adaptive model), its normal constants, and
/// (lubrication.coupling = "implicit") the collisions still under way. Plain data, owned by the
/// caller (Simulation), so that a checkpoint can write and read it as it is. The DEM step
/// rebuilds the lists at every force evaluation: a spring or constants live exactly as long as
/// their contact, a rebound until the gap opens beyond the lubrication range.

#include "fddem/contact/contact_model.hpp"
#include "fddem/core/vec.hpp"

#include <algorithm>
#include <compare>
#include <vector>

namespace fddem {

/// Which two things touch: the body of id `first` and `second`, another body's id (the
/// larger) or, if negative, a wall: −1 − (2·axis + side), side 0 the low wall. Ids are stable
/// (bodies/particle.hpp), so a spring follows its contact when bodies enter, leave, migrate or
/// are stored in another order: the key does not depend on the order in which the DEM meets
/// the pair (pair_contact_key).
struct ContactKey {
    int first = 0;
    int second = 0;

    auto operator<=>(const ContactKey&) const = default;
    [[nodiscard]] bool is_wall() const noexcept { return second < 0; }
};

[[nodiscard]] inline ContactKey wall_contact_key(int body, int axis, int side) noexcept
{
    return {body, -1 - (2 * axis + side)};
}

/// The key of the contact between the bodies of ids a and b, met in either order.
[[nodiscard]] inline ContactKey pair_contact_key(int a, int b) noexcept
{
    return a < b ? ContactKey{a, b} : ContactKey{b, a};
}

/// +1 if the DEM meets a pair in its key's order (first body, then second), −1 if the other way
/// round: the stored ξ is then negated on reading and on writing.
[[nodiscard]] inline double key_orientation(int first_met, int second_met) noexcept
{
    return first_met < second_met ? 1.0 : -1.0;
}

template <int Dim>
struct TangentialSpring {
    ContactKey key;
    /// ξ of the key's second (the larger id, or the wall) relative to its first [m]
    Vec<Dim> displacement = Vec<Dim>::Zero();

    /// Lists the members for a checkpoint archive (io/checkpoint_archive.hpp).
    template <class Self, class Archive>
    static void visit(Self& s, Archive& archive)
    {
        archive("spring.first", s.key.first);
        archive("spring.second", s.key.second);
        archive("spring.displacement", s.displacement);
    }
};

/// The normal constants a PerContactModel fixed for one contact when it opened (contact_model.hpp).
struct PairCoefficients {
    ContactKey key;
    NormalCoefficients normal;

    /// Lists the members for a checkpoint archive (io/checkpoint_archive.hpp).
    template <class Self, class Archive>
    static void visit(Self& s, Archive& archive)
    {
        archive("coefficients.first", s.key.first);
        archive("coefficients.second", s.key.second);
        archive("coefficients.stiffness", s.normal.stiffness);
        archive("coefficients.damping", s.normal.damping);
    }
};

/// A contact that has touched and whose gap has not since opened beyond the lubrication range: a
/// collision still under way (lubrication.coupling = "implicit": a body leaving it within the
/// range is the DEM's, docs/method.md §5, "Implicit coupling of the film").
struct Rebound {
    ContactKey key;
    /// Lists the members for a checkpoint archive (io/checkpoint_archive.hpp).
    template <class Self, class Archive>
    static void visit(Self& s, Archive& archive)
    {
        archive("rebound.first", s.key.first);
        archive("rebound.second", s.key.second);
    }
};

/// The entry of `key` in `entries` (sorted by key), or nullptr.
template <class Entry>
[[nodiscard]] const Entry* find_by_key(const std::vector<Entry>& entries, const ContactKey& key)
{
    const auto at = std::lower_bound(entries.begin(), entries.end(), key,
                                     [](const Entry& e, const ContactKey& k) { return e.key < k; });
    return at != entries.end() && at->key == key ? &*at : nullptr;
}

template <int Dim>
struct ContactHistory {
    std::vector<TangentialSpring<Dim>> springs; ///< sorted by key, one per open contact
    std::vector<PairCoefficients> coefficients; ///< sorted by key, one per open contact
    /// sorted by key: the collisions under way (Rebound); kept only with lubrication.coupling =
    /// "implicit", empty otherwise
    std::vector<Rebound> rebounds;

    /// The spring of `key`, or nullptr if the contact has none (it just closed, or is
    /// frictionless).
    [[nodiscard]] const TangentialSpring<Dim>* find(const ContactKey& key) const
    {
        return find_by_key(springs, key);
    }
    /// The constants of `key`, or nullptr if the contact has none (it just opened, or its model
    /// fixes none).
    [[nodiscard]] const PairCoefficients* find_coefficients(const ContactKey& key) const
    {
        return find_by_key(coefficients, key);
    }
    /// Whether the contact of `key` has touched since its gap was last beyond the range.
    [[nodiscard]] bool is_rebounding(const ContactKey& key) const
    {
        return find_by_key(rebounds, key) != nullptr;
    }
};

} // namespace fddem
