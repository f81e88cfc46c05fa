// SPDX-License-Identifier: MIT
#pragma once
/// The adaptive collision model of Kempe & Fröhlich (2012, J. Fluid Mech. 709, 445–489; its
/// normal part, "ACTM"): a collision is stretched to last a prescribed number N_c of fluid time
/// steps, T_c = N_c Δt (they use N_c = 10), and still rebounds with the dry restitution e_dry
/// given as input. Beyond the paper, which uses the linear spring–dashpot of eq. (18).
///
///   F_n = k_n α^{3/2} + d_n α̇              (a Hertz spring and a linear damper)
///
/// k_n and d_n are not material constants: they are chosen for each contact when it opens, from
/// the pair's effective mass m* and the approach speed v at that moment, so that the binary
/// collision m* α̈ + F_n = 0 lasts T_c and ends at −e_dry v (the restitution of a Hertz spring
/// with a linear damper depends on the impact speed, so no single pair of constants could hold
/// e_dry at every speed). Kempe & Fröhlich find k_n, d_n by an optimisation over the numerically
/// integrated collision. fddem uses the scaling of contact/hertz_damper_collision.hpp instead:
/// the collision depends on one parameter γ = d_n T / m*, so
///
///   γ = γ(e_dry)                        (solved once, when the model is built)
///   T = T_c / τ_c(γ)                    (τ_c: the scaled duration)
///   k_n = m* / (v^{1/2} T^{5/2}),   d_n = γ m* / T
///
/// exactly (to the ODE solution's 1e-9), with no iteration per contact. The constants are kept
/// in the contact history (contact_history.hpp) for as long as the contact stays open and
/// recomputed for the next one. The approach speed is the overlap rate α̇ at the first sub-step
/// that finds the pair overlapping: the DEM sub-steps detect the touch within Δt_i, after the
/// fluid (and the lubrication correction, if on) has slowed the approach; Kempe & Fröhlich,
/// who detect contact once per fluid step, take the speed when the gap falls below a threshold.
///
/// Slow approaches (fddem's choice): v is taken as at least v_min
/// (contact.minimum_impact_velocity). k_n grows as v^{−1/2}, so a contact that opens at rest (a
/// body placed touching, or settling onto a pile) would otherwise get an unbounded stiffness
/// and a period no sub-step resolves. A body of weight m g resting on constants fixed at v
/// oscillates at ω with (ωT)² = (3/2) (gT/v)^{1/3} (linearised about its static overlap
/// (m g/k_n)^{2/3}); at the default v_min = |g| T_c / 1000 its period is 0.61 T_c for e_dry = 1
/// and 0.57 T_c for 0.5, some 50 of the automatic sub-steps (80 per T_c), and it shortens only
/// as v_min^{1/6}. Impacts slower than v_min last longer than T_c and rebound less.
///
/// Tangential (with friction): k_t = κ S_n, S_n = dF_n/dα = (3/2) k_n α^{1/2}, c_t = √κ d_n,
/// κ = contact.tangential_stiffness_ratio (default 2/7, as the linear model), for the Coulomb
/// spring of contact/tangential_contact.hpp. Kempe & Fröhlich's own tangential model (a
/// critical impact angle separating rolling from sliding) is not implemented.
///
/// 2D: the same law per unit depth for a disk (its mass per unit depth), as the other models.

#include "fddem/contact/contact_model.hpp"
#include "fddem/contact/hertz_damper_collision.hpp"

namespace fddem {

class AdaptiveCollision {
public:
    /// v_min = |g| T_c / floor_ratio by default (see the file comment).
    static constexpr double floor_ratio = 1000.0;

    struct Params {
        double restitution = 1.0;            ///< e_dry, 0 < e ≤ 1
        int collision_steps = 10;            ///< N_c ≥ 1 (Kempe & Fröhlich 2012: 10)
        double minimum_impact_speed = 0.0;   ///< v_min > 0 [m/s]
        double time_step = 0.0;              ///< time.dt [s]: sets elastic_collision_time
        double tangential_ratio = 2.0 / 7.0; ///< κ = k_t / S_n
    };

    /// Throws InputError (naming the case key) if e ∉ (0, 1], N_c < 1, v_min ≤ 0, Δt ≤ 0 or
    /// κ ≤ 0; solves γ(e_dry).
    explicit AdaptiveCollision(const Params& params);

    /// k_n [N/m^{3/2}] and d_n [N·s/m] (2D: per unit depth) of a contact of `pair` that opens at
    /// approach speed `impact_speed` [m/s] during a fluid step `dt` [s] (T_c = N_c dt).
    [[nodiscard]] NormalCoefficients coefficients(const ContactPair& pair, double impact_speed,
                                                  double dt) const;
    /// F_n = k_n α^{3/2} + d_n α̇, k_t = κ (3/2) k_n α^{1/2}, c_t = √κ d_n.
    [[nodiscard]] ContactLaw law(NormalContact c, const ContactPair& pair,
                                 const NormalCoefficients& k) const noexcept;
    /// T_c = N_c time.dt, the duration of every collision at v ≥ v_min whatever the pair [s].
    [[nodiscard]] double elastic_collision_time(const ContactPair& pair, double impact_speed) const;
    /// e_dry, of every collision at v ≥ v_min.
    [[nodiscard]] double restitution(const ContactPair& /*pair*/) const noexcept
    {
        return params_.restitution;
    }
    /// γ = d_n T / m* of e_dry, and the scaled duration τ_c and largest overlap x_max of the
    /// collision (contact/hertz_damper_collision.hpp).
    [[nodiscard]] const ScaledCollision& scaled() const noexcept { return scaled_; }
    [[nodiscard]] double scaled_damping() const noexcept { return scaled_damping_; }
    [[nodiscard]] const Params& params() const noexcept { return params_; }

private:
    Params params_;
    double scaled_damping_; ///< γ(e_dry)
    ScaledCollision scaled_;
};

static_assert(PerContactModel<AdaptiveCollision>);

} // namespace fddem
