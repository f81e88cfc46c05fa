// SPDX-License-Identifier: MIT
#pragma once
/// Linear spring–dashpot, F = k α + c α̇ (paper, eq. (18) and the text after it).
///
/// For a binary collision of effective mass m (m₁m₂/(m₁+m₂), or m against a wall) the overlap
/// obeys m α̈ + c α̇ + k α = 0: a damped oscillator with ω₀ = √(k/m), ζ = c / (2√(k m)),
/// ω_d = ω₀√(1 − ζ²). Contact lasts half a period, t_c = π/ω_d, and the normal restitution
/// coefficient is e = exp(−ζπ/√(1 − ζ²)) (e.g. Schäfer, Dippel & Wolf 1996, eqs. 10–11).
/// In a 2D case k and c are per unit depth, like the masses.
///
/// Beyond the paper (which is frictionless): a tangential spring k_t = κ k with the normal
/// dashpot's damping ratio, c_t = c √κ, for Coulomb friction (contact/tangential_contact.hpp).
/// κ = 2/7 by default, the common choice (e.g. Silbert et al. 2001) that gives a solid sphere
/// the same normal and tangential oscillation periods.

#include "fddem/contact/contact_model.hpp"

namespace fddem {

class LinearSpringDashpot {
public:
    struct Params {
        double stiffness;                    ///< k [N/m]
        double damping;                      ///< c [N·s/m]
        double tangential_ratio = 2.0 / 7.0; ///< κ = k_t / k
    };

    /// Throws InputError if k ≤ 0, c < 0, κ ≤ 0, or the contact is overdamped (ζ ≥ 1: no
    /// rebound) for a collision of effective mass `reference_mass` [kg].
    explicit LinearSpringDashpot(const Params& params, double reference_mass);

    /// k and c that give restitution `restitution` (0 < e ≤ 1) and contact duration
    /// `contact_time` [s] for a collision of effective mass `mass` [kg].
    [[nodiscard]] static Params from_restitution(double restitution, double contact_time,
                                                 double mass);

    [[nodiscard]] double normal_force(NormalContact c) const noexcept
    {
        return params_.stiffness * c.overlap + params_.damping * c.overlap_rate;
    }
    /// F_n = kα + cα̇, k_t = κk, c_t = c√κ (the pair is not needed: k and c are global).
    [[nodiscard]] ContactLaw law(NormalContact c, const ContactPair& /*pair*/) const noexcept;
    /// t_c = π/ω_d for effective mass `mass` [s].
    [[nodiscard]] double contact_time(double mass) const;
    /// π √(m*/k): the undamped duration, independent of the impact speed [s].
    [[nodiscard]] double elastic_collision_time(const ContactPair& pair, double impact_speed) const;
    /// e = exp(−ζπ/√(1 − ζ²)) for effective mass `mass`.
    [[nodiscard]] double restitution(double mass) const;
    [[nodiscard]] double restitution(const ContactPair& pair) const
    {
        return restitution(pair.effective_mass);
    }
    [[nodiscard]] const Params& params() const noexcept { return params_; }

private:
    Params params_;
};

static_assert(ContactModel<LinearSpringDashpot>);

} // namespace fddem
