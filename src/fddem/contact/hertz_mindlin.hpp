// SPDX-License-Identifier: MIT
#pragma once
/// Hertz–Mindlin contact: Hertz's elastic normal force with a dashpot that gives a chosen
/// restitution coefficient, and Mindlin's tangential stiffness (no-slip form). Beyond the
/// paper, which uses the linear spring–dashpot of eq. (18).
///
///   F_n = k_H α^{3/2} + c_n α̇,   k_H = (4/3) E* √R*            (Hertz; Johnson 1985, ch. 4)
///   c_n = A √(m* k_H) α^{1/4}                         (the form of Tsuji, Tanaka & Ishida 1992)
///   A = √5 ζ,  ζ = −ln e / √(π² + ln² e)                           (Antypov & Elliott 2011)
///   k_t = 8 G* √(R* α)                                        (Mindlin 1949; the "no-slip" form)
///   c_t = c_n √(k_t / S_n),  S_n = dF_n/dα = 2 E* √(R* α)   (the normal dashpot's damping ratio)
///
/// Why A = √5 ζ: with δ = A_p x^{4/5}, A_p = (5/4)^{2/5}, the phase-plane equation of
/// m δ̈ + A√(m k_H) δ^{1/4} δ̇ + k_H δ^{3/2} = 0 becomes exactly that of a linear oscillator
/// with damping ratio A/√5, so e = exp(−πζ/√(1 − ζ²)) at every impact speed (the restitution of
/// this dashpot does not depend on the impact speed, as Tsuji et al. found numerically).
/// Like the linear model's, the normal force is not clipped at zero: near the end of a damped
/// contact it is slightly attractive, as in the analysis that gives e.
///
/// Undamped collision: α_max = (5 m* v²/(4 k_H))^{2/5} and t_c = 2 I α_max / v with
/// I = ∫₀¹ (1 − u^{5/2})^{−1/2} du = √π Γ(7/5)/Γ(9/10) = 1.4716, i.e.
/// t_c = 2.868 (m*²/(R* E*² v))^{1/5} (Johnson 1985, ch. 11: 2.87).
///
/// 2D: a disk of mass per unit depth m is given the sphere law above, the force then being
/// taken per unit depth (a disk of unit depth whose contact behaves as a sphere's). The exact 2D
/// law (a line contact) has no closed force–overlap relation: the overlap depends on the
/// logarithm of the contact width and so on the body's size (Johnson 1985, the contact of
/// cylinders). The sphere
/// law keeps the nonlinearity α^{3/2}, the velocity-independent restitution and the weak
/// v^{−1/5} dependence of the duration. E is then a modulus per unit depth ([Pa/m]: the modulus
/// of a disk one length unit deep), a stiffness parameter to be chosen for the wanted duration
/// or overlap, as k is in the linear model.

#include "fddem/contact/contact_model.hpp"

namespace fddem {

class HertzMindlin {
public:
    /// A of c_n = A √(m* k_H) α^{1/4} giving restitution e (0 < e ≤ 1).
    [[nodiscard]] static double damping_constant(double restitution);
    /// k_H = (4/3) E* √R* [N/m^{3/2}].
    [[nodiscard]] static double hertz_stiffness(const ContactPair& pair);

    /// F_n, k_t and c_t at overlap α > 0 (see the file comment); needs E* > 0. Static: every
    /// constant is the pair's.
    [[nodiscard]] static ContactLaw law(NormalContact c, const ContactPair& pair);
    /// The undamped duration at impact speed v > 0 [s].
    [[nodiscard]] static double elastic_collision_time(const ContactPair& pair,
                                                       double impact_speed);
    /// e of the pair (independent of the impact speed).
    [[nodiscard]] static double restitution(const ContactPair& pair) { return pair.restitution; }
};

static_assert(ContactModel<HertzMindlin>);

} // namespace fddem
