// SPDX-License-Identifier: MIT
#pragma once
/// Lubrication correction for two balls, or a ball and a plane wall, closer than the grid
/// resolves (issue 16; docs/method.md §5, Lubrication). Pure functions of the gap; dem_step.cpp
/// applies them implicitly inside the DEM sub-steps.
///
/// A lubrication force is a linear damper on the relative surface velocity, F = −c(h) v, with a
/// resistance c that diverges as the gap h closes. The forms (leading terms of the asymptotic
/// expansions for h ≪ a; a1, a2 the radii, a* = a1 a2/(a1 + a2) the reduced radius, a* = a1
/// for a wall):
///
///   3D normal      c_n = 6πμ a1 [g1/ξ + g2 ln(1/ξ)],   ξ = h/ā,  ā = (a1 + a2)/2
///                  two spheres, β = a2/a1: g1 = 2β²/(1+β)³, g2 = β(1+7β+β²)/(5(1+β)³)
///                  (Jeffrey 1982; Jeffrey & Onishi 1984, X^A_11). g1/ξ = a*²/(a1 h): the
///                  leading term is 6πμ a*²/h (Cox & Brenner 1967 for two spheres).
///                  wall: ξ = h/a1, g1 = 1, g2 = 1/5 (Cox & Brenner 1967, the limit of Brenner
///                  1961; Cooley & O'Neill 1969 add the constant 0.971 that is left out here).
///   3D tangential  c_t = 6πμ a1 g_t ln(1/ξ), two spheres g_t = 4β(2+β+2β²)/(15(1+β)³)
///                  (Jeffrey & Onishi 1984, Y^A_11; 1/6 for equal spheres), wall g_t = 8/15
///                  (Goldman, Cox & Brenner 1967, a sphere translating along a wall).
///   2D normal      c_n = 3√2 π μ (a*/h)^(3/2) per unit length. Derived here from Reynolds'
///                  lubrication equation for the gap h + x²/(2a*) (docs/method.md §5, Lubrication);
///                  it is the leading term given for a cylinder near a wall by Jeffrey & Onishi
///                  (1981, QJMAM 34) as recalled, not re-checked against the paper's text.
///   2D tangential  c_t = 2√2 π μ (a*/h)^(1/2) per unit length. Derived the same way for a
///                  cylinder translating (not rotating) along a wall; for two cylinders the
///                  reduced radius is used, an approximation (the exact split with the radius
///                  ratio, as the sphere's g_t has, is not derived).
///
/// What the grid resolves is subtracted (`lubrication.resolved`):
/// - `range`, Breugem (2010, 2012): the grid resolves the film down to a gap of about the
///   activation distance h_Δ (`range`) and no further, so only the part it misses is added:
///     c_corr(h) = c(max(h, h_σ)) − c(h_Δ)  for h < h_Δ,   0 for h ≥ h_Δ.
/// - `shells`, fddem's: the grid resolves the film between the bodies' outermost marker shells,
///   which lie s = s1 + s2 farther apart than the surfaces (s_i the depth of body i's outermost
///   marker shell below its surface, 0 for a wall; docs/method.md §5, "What the grid resolves"):
///     c_corr(h) = [c(max(h, h_σ)) − c(h + s)] − [c(h_Δ) − c(h_Δ + s)]  for h < h_Δ, else 0.
///   The bracket at h_Δ keeps it continuous there; it is small when h_Δ is a few s.
/// Both vanish continuously at h_Δ and are held at their value at the roughness length h_σ for
/// 0 < h < h_σ, where asperities touch (Breugem 2012, Costa et al. 2015 hold it at a
/// roughness length in the same way).
///
/// While the surfaces overlap (h ≤ 0, the contact model acting) the correction is switched off
/// by default (LubricationInContact::off): the film has been squeezed out, and the contact
/// model's damping, set for the dry restitution, already stands for the dissipation of the solid
/// contact. This is the split of Costa et al. (2015, PRE 92, 053012: the correction acts until
/// the solid surfaces touch), of Kempe & Fröhlich (2012) and Biegert,
/// Vowinckel & Meiburg (2017, JCP 340, eq. 5: lubrication for 0 < ζ_n ≤ 2h, contact for
/// ζ_n ≤ 0) and of waLBerla's lubrication correction (Rettinger & Rüde 2022: none for negative
/// gaps). `saturated` keeps it at c(h_σ) through the overlap, fddem's former behaviour: with a
/// collision stretched over N_c fluid steps it removes most of the impact energy
/// (docs/method.md §5, "Gondret's rebound").

namespace fddem {

/// What the correction does while the surfaces overlap (lubrication.in_contact).
enum class LubricationInContact {
    off,       ///< zero for h ≤ 0: the contact model alone acts (Costa et al. 2015)
    saturated, ///< held at c(h_σ), as for 0 < h < h_σ
};

/// What the grid is taken to resolve of the film (lubrication.resolved).
enum class LubricationResolved {
    range,  ///< the resistance up to h_Δ and no more (Breugem 2010, 2012)
    shells, ///< the resistance of the gap between the outermost marker shells, h + s
};

/// How the correction reaches a body that is near another or a wall but not in contact
/// (lubrication.coupling).
enum class LubricationCoupling {
    /// the body counts as in contact within the range: with the paper's coupling the DEM moves
    /// it, and the correction acts implicitly in the sub-steps (fddem's first coupling; the
    /// default until the thirty-sixth session: a light body beside another goes unstable under
    /// it, docs/method.md §5, "The default coupling of the film")
    dem,
    /// the body stays on eqs. (13)–(14), with the correction's damping on their left-hand sides
    /// and the bodies it joins solved together: the fluid's added mass and the film act together
    /// (coupling/lubrication_coupling.hpp); a body leaving a collision (its gap opening within
    /// the range after a touch) is the DEM's until it is out of the range, as with `dem` but
    /// without the held fluid force (the default)
    implicit,
};

/// How the DEM sub-steps apply the films of several gaps (lubrication.film_solve).
enum class LubricationFilmSolve {
    /// pair by pair in the neighbour list's order, each film on the velocities the ones before
    /// it left (film_step; a Gauss–Seidel pass: its result depends on that order)
    sweep,
    /// all films of a sub-step at once (contact/film_solve.hpp): order-free, stable at any
    /// stiffness, the sweep's bits for a film whose bodies have no other
    joint,
};

/// [lubrication] of a case, in SI units as the DEM uses it.
struct LubricationSettings {
    bool is_enabled = false; ///< off: the sub-steps are the dry DEM's, bit for bit
    double viscosity = 0.0;  ///< μ [Pa·s]
    double range = 0.0;      ///< activation gap h_Δ [m] (the case gives it in grid spacings)
    double roughness = 1e-3; ///< h_σ as a fraction of the smaller radius
    LubricationInContact in_contact = LubricationInContact::off;   ///< while overlapping
    LubricationResolved resolved = LubricationResolved::range;     ///< what the grid resolves
    LubricationCoupling coupling = LubricationCoupling::implicit;  ///< bodies not in contact
    LubricationFilmSolve film_solve = LubricationFilmSolve::sweep; ///< several gaps at once
};

/// Resistance coefficients of one gap [N·s/m] (2D: per unit length).
struct LubricationResistance {
    double normal = 0.0;     ///< c_n: F_n = −c_n × approach speed
    double tangential = 0.0; ///< c_t: F_t = −c_t × slip velocity
};

/// The full analytic resistance at gap `gap` > 0 between balls of radii `radius` and
/// `other_radius` (+∞: a plane wall) in a fluid of viscosity `viscosity`. Dim 2: disks
/// (cylinders, per unit length); Dim 3: spheres. Log terms are clamped at 0 for gaps beyond ā.
template <int Dim>
[[nodiscard]] LubricationResistance lubrication_resistance(double gap, double radius,
                                                           double other_radius, double viscosity);

/// The correction for h < h_Δ, else 0: c(max(h, h_σ)) − c(h_Δ) (settings.resolved `range`),
/// or [c(max(h, h_σ)) − c(h + s)] − [c(h_Δ) − c(h_Δ + s)] (`shells`, s = `shell_gap`, the sum
/// of the two bodies' outermost_shell_depth). h ≤ 0 (overlapping): 0, or held at h_σ if
/// settings.in_contact is `saturated`. h_σ = settings.roughness × the smaller radius.
template <int Dim>
[[nodiscard]] LubricationResistance
lubrication_correction(double gap, double radius, double other_radius,
                       const LubricationSettings& settings, double shell_gap = 0.0);

/// The correction's integral over the gap, G(h) = ∫_0^h c_corr(s) ds [N·s/m · m = N·s] (2D: per
/// unit length), normal and tangential, with the same arguments as lubrication_correction: its
/// impulse on a gap that moves from h0 to h1 is G(h0) − G(h1) along the approach, whatever the
/// speed on the way (F = −c_corr(h) ḣ). In closed form from the leading terms above (each is a
/// power of h or a logarithm); G is continuous, constant beyond h_Δ, linear below h_σ and, in
/// contact, linear with the held value (`saturated`) or flat (`off`).
template <int Dim>
[[nodiscard]] LubricationResistance
lubrication_correction_integral(double gap, double radius, double other_radius,
                                const LubricationSettings& settings, double shell_gap = 0.0);

/// The mean of c_corr over the gaps from `from` to `to`, [G(to) − G(from)]/(to − from) (Simpson's
/// rule over a travel below 1 % of the gap within one smooth piece, where G's two values agree
/// in most of their digits); c_corr(from) if they are equal.
template <int Dim>
[[nodiscard]] LubricationResistance
lubrication_correction_over(double from, double to, double radius, double other_radius,
                            const LubricationSettings& settings, double shell_gap = 0.0);

/// One gap's film over a (sub-)step `step` in which it moves at its damped rate: the new gap
/// rate ḣ1 solves ḣ1 = ḣ0 − K [G(h0 + step ḣ1) − G(h0)] (`inverse_mass` K: 1/m1 + 1/m2 along the
/// normal), i.e. backward Euler with the resistance averaged over the step's travel,
/// c̄ = [G(h1) − G(h0)]/(h1 − h0), h1 = h0 + step ḣ1. Its impulse is then exactly ∫ c_corr dh over
/// the travel the body makes with that rate, at any step: no under-integration as the gap
/// closes, and the passage through the roughness length into contact counted (docs/method.md §5,
/// "The film's own restitution"). The left side grows monotonically with ḣ1 (its slope is
/// 1 + K step c_corr ≥ 1), so the root is unique, lies between 0 and ḣ0 and keeps ḣ0's sign
/// (never reversed, for any stiffness): found by Newton's method kept inside that bracket.
struct FilmStep {
    double gap_rate = 0.0;       ///< ḣ1 [m/s]
    double normal_impulse = 0.0; ///< on the second body along n: G(h0) − G(h1) [N·s]
    double tangential = 0.0;     ///< c̄_t over the same travel (c_t(h0) if the gap stays) [N·s/m]
};

template <int Dim>
[[nodiscard]] FilmStep film_step(double gap, double gap_rate, double inverse_mass, double step,
                                 double radius, double other_radius,
                                 const LubricationSettings& settings, double shell_gap = 0.0);

/// The impulse on the pair's second body along w [N·s] of the backward-Euler update of a
/// relative velocity w under a linear damper c over Δt_i, w / (1 + c Δt_i/m*), with
/// `inverse_mass` the sum of the bodies' inverse (effective) masses (unconditionally stable: it
/// shrinks |w| and never reverses it): the change of w over the inverse mass,
/// −c Δt_i w / (1 + c Δt_i/m*), written so that it holds for bodies of
/// infinite mass too (inverse_mass = 0: both prescribed, fixed or a wall; then −c w Δt_i, the
/// force the film exerts at the kept velocity).
[[nodiscard]] inline double damping_impulse(double velocity, double resistance, double inverse_mass,
                                            double step)
{
    return -resistance * step * velocity / (1.0 + resistance * step * inverse_mass);
}

} // namespace fddem
