// SPDX-License-Identifier: MIT
// Lubrication correction (contact/lubrication.hpp): the sphere–wall normal resistance against
// Brenner's (1961) exact series at small gaps, the two-sphere coefficients of Jeffrey & Onishi
// (1984) for equal spheres, the disks' power laws, the Breugem correction (zero at and beyond
// the range, held below the roughness, zero while overlapping unless in_contact = saturated),
// the marker-shell correction (resolved = shells) and its premise against Brenner,
// equal and opposite pair impulses in the sub-steps, the implicit damping's stability with
// c Δt_i / m far above 1, and an adaptive collision through the film that keeps e_dry.

#include "fddem/contact/adaptive_collision.hpp"
#include "fddem/contact/dem_step.hpp"
#include "fddem/contact/lubrication.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double wall = std::numeric_limits<double>::infinity();

/// κ = F / (6πμaU) of the model for a sphere approaching a wall at gap δ = ratio × a.
double kappa(double ratio)
{
    return lubrication_resistance<3>(ratio, 1.0, wall, 1.0).normal / (6.0 * pi);
}

TEST(Lubrication, SphereWallNormalFollowsBrennerAtSmallGaps)
{
    // κ of Brenner's exact series, computed (shared/reference/sphere_wall_brenner.csv; agrees
    // with the 400-term table of Basilisk's sphere-towards-wall test to all printed digits).
    // The model keeps a/δ + (1/5) ln(a/δ) (Cox & Brenner 1967) and leaves out the constant
    // 0.97128 of Cooley & O'Neill (1969): the remainder must be that constant, to 2e-2 (the
    // next terms are O((δ/a) ln(δ/a)): 0.0154 off at δ/a = 0.05, less below).
    const std::array<std::array<double, 2>, 3> brenner{
        {{0.05, 21.585820}, {0.025, 41.717597}, {0.01, 101.896172}}};
    for (const auto& [ratio, exact] : brenner) {
        EXPECT_NEAR(exact - kappa(ratio), 0.97128, 2e-2) << "δ/a = " << ratio;
    }
    // So the ratio to the exact force tends to 1: within 1 % at δ/a = 0.01.
    EXPECT_NEAR(kappa(0.01) / 101.896172, 1.0, 0.01);
    // The leading term alone: κ δ/a → 1.
    EXPECT_NEAR(kappa(1e-6) * 1e-6, 1.0, 2e-5);
}

TEST(Lubrication, EqualSpheresHaveJeffreyOnishiCoefficients)
{
    // X^A_11 = (1/4) ξ⁻¹ + (9/40) ln ξ⁻¹, Y^A_11 = (1/6) ln ξ⁻¹ in units of 6πμa, ξ = h/a.
    const double a = 0.5;
    const double mu = 2.0;
    const double gap = 1e-3 * a;
    const LubricationResistance c = lubrication_resistance<3>(gap, a, a, mu);
    const double log_term = std::log(a / gap);
    EXPECT_NEAR(c.normal / (6.0 * pi * mu * a), 0.25 * a / gap + 9.0 / 40.0 * log_term, 1e-9);
    EXPECT_NEAR(c.tangential / (6.0 * pi * mu * a), log_term / 6.0, 1e-12);
    // The leading term is 6πμ a*²/h with a* = a/2.
    const double tiny = 1e-9 * a;
    EXPECT_NEAR(lubrication_resistance<3>(tiny, a, a, mu).normal * tiny /
                    (6.0 * pi * mu * 0.25 * a * a),
                1.0, 1e-6);
    // The wall's coefficients are the limit of a large second sphere (tangential 8/15 of
    // Goldman et al., normal log 1/5 of Cox & Brenner): the slopes against ln(1/h) agree, the
    // logs' arguments differ (ξ = 2h/(a1 + a2) against h/a1), which is O(1), as is what both
    // leave out.
    const auto slope = [&](double other) {
        const LubricationResistance c1 = lubrication_resistance<3>(gap, a, other, mu);
        const LubricationResistance c2 = lubrication_resistance<3>(2.0 * gap, a, other, mu);
        return std::array<double, 2>{(c1.normal - c2.normal - 6.0 * pi * mu * a * a / (2.0 * gap)) /
                                         std::log(2.0),
                                     (c1.tangential - c2.tangential) / std::log(2.0)};
    };
    const std::array<double, 2> big = slope(1e8 * a);
    const std::array<double, 2> flat = slope(wall);
    EXPECT_NEAR(big[0] / flat[0], 1.0, 1e-3); // a* of the big sphere is a(1 − 1e-8)
    EXPECT_NEAR(big[1] / flat[1], 1.0, 1e-6);
    EXPECT_NEAR(flat[0], 6.0 * pi * mu * a / 5.0, 1e-9);
    EXPECT_NEAR(flat[1], 6.0 * pi * mu * a * 8.0 / 15.0, 1e-9);
    // Symmetric in the radii.
    const LubricationResistance ab = lubrication_resistance<3>(gap, a, 3.0 * a, mu);
    const LubricationResistance ba = lubrication_resistance<3>(gap, 3.0 * a, a, mu);
    EXPECT_NEAR(ab.normal / ba.normal, 1.0, 1e-12);
    EXPECT_NEAR(ab.tangential / ba.tangential, 1.0, 1e-12);
}

TEST(Lubrication, DisksFollowReynoldsPowerLaws)
{
    // Per unit length: c_n = 3√2 π μ (a*/h)^(3/2), c_t = 2√2 π μ (a*/h)^(1/2).
    const double a = 0.25;
    const double mu = 0.1;
    for (double gap : {1e-4, 1e-3, 1e-2}) {
        const LubricationResistance flat = lubrication_resistance<2>(gap, a, wall, mu);
        EXPECT_NEAR(flat.normal / std::pow(a / gap, 1.5), 3.0 * std::sqrt(2.0) * pi * mu, 1e-9);
        EXPECT_NEAR(flat.tangential / std::sqrt(a / gap), 2.0 * std::sqrt(2.0) * pi * mu, 1e-12);
        const LubricationResistance pair = lubrication_resistance<2>(gap, a, a, mu);
        EXPECT_NEAR(pair.normal / std::pow(0.5 * a / gap, 1.5), 3.0 * std::sqrt(2.0) * pi * mu,
                    1e-9);
    }
}

template <int Dim>
void check_correction()
{
    const double a = 0.1;
    const LubricationSettings s{true, 1e-3, 0.02, 1e-3}; // range 0.2 a, roughness 1e-4 m
    const auto normal = [&](double gap) {
        return lubrication_correction<Dim>(gap, a, a, s).normal;
    };
    EXPECT_EQ(normal(0.02), 0.0);
    EXPECT_EQ(normal(0.05), 0.0);
    EXPECT_LT(normal(0.02 * (1.0 - 1e-9)), 1e-6 * normal(0.001)); // continuous at the range
    // Below the roughness it is held at its value there, down to the touch.
    EXPECT_EQ(normal(0.5e-4), normal(1e-4));
    EXPECT_EQ(normal(1e-12), normal(1e-4));
    EXPECT_GT(normal(1e-4), normal(1e-3));
    // Overlapping (h ≤ 0): none by default (in_contact = off), normal and tangential; held at
    // the roughness's value under in_contact = saturated.
    for (const double overlap : {0.0, 1e-6, 1e-3}) {
        EXPECT_EQ(normal(-overlap), 0.0) << overlap;
        EXPECT_EQ(lubrication_correction<Dim>(-overlap, a, a, s).tangential, 0.0) << overlap;
        EXPECT_EQ(lubrication_correction<Dim>(-overlap, a, wall, s).normal, 0.0) << overlap;
    }
    LubricationSettings held = s;
    held.in_contact = LubricationInContact::saturated;
    EXPECT_EQ(lubrication_correction<Dim>(-1e-3, a, a, held).normal, normal(1e-4));
    EXPECT_EQ(lubrication_correction<Dim>(-1e-3, a, a, held).tangential,
              lubrication_correction<Dim>(1e-4, a, a, s).tangential);
    EXPECT_GT(lubrication_correction<Dim>(-1e-3, a, a, held).tangential, 0.0);
    // It is the full force minus the part the grid resolves.
    const double full = lubrication_resistance<Dim>(1e-3, a, a, 1e-3).normal;
    const double resolved = lubrication_resistance<Dim>(0.02, a, a, 1e-3).normal;
    EXPECT_NEAR(normal(1e-3), full - resolved, 1e-12 * full);
    // Off: nothing.
    LubricationSettings off = s;
    off.is_enabled = false;
    EXPECT_EQ(lubrication_correction<Dim>(1e-3, a, a, off).normal, 0.0);
    EXPECT_EQ(lubrication_correction<Dim>(1e-3, a, a, off).tangential, 0.0);
}

TEST(Lubrication, CorrectionVanishesAtRangeAndSaturatesAtRoughness)
{
    check_correction<2>();
    check_correction<3>();
}

template <int Dim>
void check_shells()
{
    // resolved = shells: [c(h) − c(h + s)] − [c(h_Δ) − c(h_Δ + s)] below h_Δ, s the marker
    // shells' depths (docs/method.md §5, "What the grid resolves").
    const double a = 0.1;
    LubricationSettings s{true, 1e-3, 0.05, 1e-3}; // range 0.5 a, roughness 1e-4 m
    s.resolved = LubricationResolved::shells;
    const double shell = 0.006; // 0.3 h of each of two spheres at h = a/4 (d/h = 8)
    const auto c = [&](double gap) { return lubrication_resistance<Dim>(gap, a, a, 1e-3); };
    const auto corr = [&](double gap, double depth) {
        return lubrication_correction<Dim>(gap, a, a, s, depth);
    };
    for (const double gap : {1e-3, 0.01, 0.03}) {
        const LubricationResistance expected{c(gap).normal - c(gap + shell).normal -
                                                 c(0.05).normal + c(0.05 + shell).normal,
                                             c(gap).tangential - c(gap + shell).tangential -
                                                 c(0.05).tangential + c(0.05 + shell).tangential};
        EXPECT_NEAR(corr(gap, shell).normal, expected.normal, 1e-12 * c(gap).normal) << gap;
        EXPECT_NEAR(corr(gap, shell).tangential, expected.tangential,
                    1e-12 * c(gap).tangential + 1e-15)
            << gap;
    }
    // Zero at and beyond the range, continuous there, and none without shells (the film the
    // grid resolves is then the gap itself).
    EXPECT_EQ(corr(0.05, shell).normal, 0.0);
    EXPECT_LT(corr(0.05 * (1.0 - 1e-9), shell).normal, 1e-6 * corr(1e-3, shell).normal);
    EXPECT_EQ(corr(1e-3, 0.0).normal, 0.0);
    // Deeper shells: the grid resolves less, so more is added; the Breugem correction with the
    // same range subtracts c(h_Δ), which is less than c(h + s) for h + s < h_Δ.
    EXPECT_GT(corr(1e-3, 2.0 * shell).normal, corr(1e-3, shell).normal);
    LubricationSettings breugem = s;
    breugem.resolved = LubricationResolved::range;
    EXPECT_LT(corr(1e-3, shell).normal, lubrication_correction<Dim>(1e-3, a, a, breugem).normal);
    // Held below the roughness, and none while overlapping (in_contact = off).
    EXPECT_EQ(corr(1e-12, shell).normal, corr(1e-4, shell).normal);
    EXPECT_EQ(corr(-1e-6, shell).normal, 0.0);
}

TEST(Lubrication, ShellsSubtractTheFilmBetweenTheMarkerShells)
{
    check_shells<2>();
    check_shells<3>();
}

TEST(Lubrication, ShellsModelRestoresBrennerWhereTheGridSeesTheGapWidened)
{
    // The premise of resolved = shells: the grid's force on a sphere near a wall is the exact
    // force at the gap widened by the shell depth s. Given that (Brenner's exact κ at δ + s,
    // shared/reference/sphere_wall_brenner.csv), the total with the correction is Brenner's at
    // δ up to what the leading terms leave out between δ and δ + s: within 0.5 % (0.03-0.25 %
    // computed) for s = 0.1 a (0.4 h at d/h = 8) and a range of 2 a, at δ/a = 0.1 … 0.4.
    const std::array<double, 5> brenner{11.459157, 6.340887, 4.610720, 3.735617, 3.205390};
    LubricationSettings s{true, 1.0, 2.0, 1e-3}; // μ = 1, a = 1, range 2 a
    s.resolved = LubricationResolved::shells;
    for (std::size_t i = 0; i + 1 < brenner.size(); ++i) {
        const double ratio = 0.1 * static_cast<double>(i + 1); // δ/a = 0.1 … 0.4
        const double added =
            lubrication_correction<3>(ratio, 1.0, wall, s, 0.1).normal / (6.0 * pi);
        EXPECT_NEAR((brenner[i + 1] + added) / brenner[i], 1.0, 5e-3) << "δ/a = " << ratio;
    }
}

template <int Dim>
void check_integral(double a, double other, LubricationResolved resolved,
                    LubricationInContact in_contact)
{
    // G(h) = ∫_0^h c_corr: its central difference is c_corr at gaps in contact, below the
    // roughness, through the film and beyond the range (to 1e-6 relative: the difference's
    // truncation and round-off), and it is continuous where its pieces meet. With a = 1.5 mm
    // the range (2 mm) reaches beyond ā, where the sphere forms' log terms are clamped at 0.
    LubricationSettings s{true, 0.7, 0.002, 1e-3, in_contact, resolved};
    const double shell_gap = resolved == LubricationResolved::shells ? 0.4e-3 : 0.0;
    const auto big_g = [&](double h) {
        return lubrication_correction_integral<Dim>(h, a, other, s, shell_gap);
    };
    const double roughness = 1e-3 * std::min(a, other);
    for (const double h :
         {-3e-6, -1e-7, 2e-6, 9e-6, 1.2e-5, 3e-5, 1e-4, 4e-4, 1e-3, 1.9e-3, 2.5e-3, 0.05}) {
        const double dh = 1e-4 * std::min(std::abs(h), 1e-3);
        const LubricationResistance c = lubrication_correction<Dim>(h, a, other, s, shell_gap);
        const double normal = (big_g(h + dh).normal - big_g(h - dh).normal) / (2.0 * dh);
        const double tangential =
            (big_g(h + dh).tangential - big_g(h - dh).tangential) / (2.0 * dh);
        EXPECT_NEAR(normal, c.normal, 1e-6 * c.normal + 1e-9) << Dim << "D, h " << h;
        EXPECT_NEAR(tangential, c.tangential, 1e-6 * c.tangential + 1e-9) << Dim << "D, h " << h;
    }
    for (const double joint : {0.0, roughness, s.range}) {
        const double eps = 1e-12 * s.range;
        EXPECT_NEAR(big_g(joint - eps).normal, big_g(joint + eps).normal,
                    1e-9 * big_g(s.range).normal)
            << Dim << "D at " << joint;
    }
    EXPECT_EQ(big_g(0.0).normal, 0.0);
    EXPECT_GT(big_g(s.range).normal, big_g(0.5 * s.range).normal);
    EXPECT_EQ(big_g(s.range).normal, big_g(1.0).normal); // nothing beyond the range
}

TEST(Lubrication, TheCorrectionsIntegralHasItAsItsDerivative)
{
    for (const auto resolved : {LubricationResolved::range, LubricationResolved::shells}) {
        for (const auto in_contact : {LubricationInContact::off, LubricationInContact::saturated}) {
            for (const double other : {wall, 0.01, 0.005}) {
                check_integral<2>(0.01, other, resolved, in_contact);
                check_integral<3>(0.01, other, resolved, in_contact);
            }
            check_integral<3>(0.0015, wall, resolved, in_contact);
            check_integral<3>(0.0015, 0.0015, resolved, in_contact);
        }
    }
}

template <int Dim>
void check_film_step(double other, LubricationResolved resolved, LubricationInContact in_contact)
{
    const double a = 1.5e-3;
    LubricationSettings s{true, 0.03, 0.5 * a, 1e-3, in_contact, resolved};
    const double shell_gap = resolved == LubricationResolved::shells ? 0.1 * a : 0.0;
    const auto big_g = [&](double h) {
        return lubrication_correction_integral<Dim>(h, a, other, s, shell_gap);
    };
    for (const double inverse_mass : {0.0, 1.0, 1e3, 1e6, 1e9}) {
        for (const double rate : {-0.5, -1e-3, 0.2}) {
            for (const double gap : {-1e-6, 1e-6, 2e-5, 3e-4, 0.74e-3}) {
                const double step = 1e-4;
                const FilmStep f =
                    film_step<Dim>(gap, rate, inverse_mass, step, a, other, s, shell_gap);
                const double end = gap + step * f.gap_rate;
                const std::string where = std::to_string(Dim) + "D, K " +
                                          std::to_string(inverse_mass) + ", rate " +
                                          std::to_string(rate) + ", gap " + std::to_string(gap);
                // G's values share most of their digits over a short travel, and where the
                // film is stiff G(h1) moves by c Δt per unit of the rate's own round-off: the
                // bound is those two (c at most its held value c(h_σ)).
                const LubricationResistance taken{big_g(end).normal - big_g(gap).normal,
                                                  big_g(end).tangential - big_g(gap).tangential};
                const LubricationResistance held =
                    lubrication_correction<Dim>(1e-3 * std::min(a, other), a, other, s, shell_gap);
                const double rounding = 1e-14 * step * std::abs(f.gap_rate);
                EXPECT_NEAR(f.normal_impulse, -taken.normal,
                            1e-9 * std::abs(f.normal_impulse) +
                                1e-14 * std::abs(big_g(gap).normal) + held.normal * rounding)
                    << where;
                if (end != gap) { // the slip's resistance: the mean over the same travel
                    EXPECT_NEAR(f.tangential * (end - gap), taken.tangential,
                                1e-9 * std::abs(taken.tangential) +
                                    1e-14 * std::abs(big_g(gap).tangential) +
                                    held.tangential * rounding)
                        << where;
                }
                EXPECT_NEAR(f.gap_rate, rate + inverse_mass * f.normal_impulse,
                            1e-12 * std::abs(rate))
                    << where;
                EXPECT_GE(f.gap_rate * rate, 0.0) << "reversed: " << where;
                EXPECT_LE(std::abs(f.gap_rate), std::abs(rate)) << where;
                if (inverse_mass == 0.0) {
                    EXPECT_EQ(f.gap_rate, rate) << where;
                }
            }
        }
    }
    // Stiff (c(h_σ) Δt K ≈ 1e8 for the sphere at the wall): the gap stops short of contact,
    // above the roughness length.
    if (std::isinf(other) && resolved == LubricationResolved::range) {
        const FilmStep stiff = film_step<Dim>(2e-5, -0.5, 1e9, 1e-4, a, other, s);
        EXPECT_GT(2e-5 + 1e-4 * stiff.gap_rate, 1e-3 * a) << Dim << "D";
    }
}

TEST(Lubrication, AFilmStepTakesTheIntegralOverItsTravel)
{
    // film_step: the new gap rate solves ḣ1 = ḣ0 − K [G(h0 + Δt ḣ1) − G(h0)] to round-off, its
    // impulse is G(h0) − G(h1) and the slip's resistance the mean over the same travel, the
    // rate keeps its sign at any stiffness, and a body of infinite mass (K = 0) keeps its rate
    // and feels the integral over its own travel: disks and spheres, a wall and a pair, both
    // `resolved` rules, both `in_contact` rules.
    for (const auto resolved : {LubricationResolved::range, LubricationResolved::shells}) {
        for (const auto in_contact : {LubricationInContact::off, LubricationInContact::saturated}) {
            for (const double other : {wall, 1.5e-3, 0.75e-3}) {
                check_film_step<2>(other, resolved, in_contact);
                check_film_step<3>(other, resolved, in_contact);
            }
        }
    }
}

TEST(Lubrication, DefaultIsOffAndNoneInContact)
{
    const DemSettings settings{HertzMindlin{}, 0.0, 1};
    EXPECT_FALSE(settings.lubrication.is_enabled);
    EXPECT_FALSE(LubricationSettings{}.is_enabled);
    EXPECT_EQ(LubricationSettings{}.in_contact, LubricationInContact::off);
    EXPECT_EQ(LubricationSettings{}.resolved, LubricationResolved::range);
}

/// DEM settings with a contact model that never acts here (the bodies stay apart) and
/// lubrication on.
DemSettings lubricated(double viscosity, double range, int substeps,
                       LubricationFilmSolve film_solve = LubricationFilmSolve::sweep)
{
    DemSettings settings{LinearSpringDashpot({1e3, 0.0}, 1.0), 0.0, substeps};
    settings.lubrication = {true, viscosity, range, 1e-3};
    settings.lubrication.film_solve = film_solve;
    // the film in the DEM's sub-steps, which these tests check (the default, "implicit", puts a
    // body within the range on eqs. (13)–(14) instead: LubricationCoupling)
    settings.lubrication.coupling = LubricationCoupling::dem;
    return settings;
}

void check_pair_impulses(LubricationFilmSolve film_solve)
{
    // Two spheres closing obliquely inside the range: linear and angular momentum kept to
    // round-off, and both the approach and the slip slowed.
    SCOPED_TRACE(film_solve == LubricationFilmSolve::joint ? "joint" : "sweep");
    const double a = 0.01;
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>(0.05, 0.05, 0.05), Vec<3>(0.01, 0.003, 0.0), a, 2000.0),
        test::ball<3>(Vec<3>(0.0705, 0.05, 0.05), Vec<3>(-0.02, -0.001, 0.002), a, 1000.0)};
    const DemWalls<3> open{Vec<3>::Zero(), Vec<3>(0.1, 0.1, 0.1), {false, false, false}};
    const DemSettings settings = lubricated(1.0, 0.002, 10, film_solve);
    CellList<3> cells(open.origin, open.length, 0.03);
    ContactHistory<3> history;
    const auto momentum = [&] {
        return Vec<3>(bodies[0].mass() * bodies[0].velocity +
                      bodies[1].mass() * bodies[1].velocity);
    };
    const auto angular = [&] {
        Vec<3> total = Vec<3>::Zero();
        for (const Particle<3>& b : bodies) {
            total += b.mass() * b.centre.cross(b.velocity) + b.inertia() * b.omega;
        }
        return total;
    };
    const Vec<3> p0 = momentum();
    const Vec<3> l0 = angular();
    const double approach0 = (bodies[0].velocity - bodies[1].velocity).x();
    test::step_dem<3>(bodies, open, settings, 1e-3, cells, history);
    EXPECT_LT((momentum() - p0).norm(), 1e-14 * p0.norm() + 1e-18);
    EXPECT_LT((angular() - l0).norm(), 1e-12 * l0.norm() + 1e-18);
    EXPECT_LT((bodies[0].velocity - bodies[1].velocity).x(), approach0);
    EXPECT_GT((bodies[0].velocity - bodies[1].velocity).x(), 0.0);
    EXPECT_NE(bodies[0].omega.norm(), 0.0); // the slip damping turned them
    // The mean forces are opposite.
    EXPECT_LT((bodies[0].contact.mean_force + bodies[1].contact.mean_force).norm(),
              1e-12 * bodies[0].contact.mean_force.norm());
}

TEST(Lubrication, PairImpulsesAreEqualAndOpposite)
{
    check_pair_impulses(LubricationFilmSolve::sweep);
    check_pair_impulses(LubricationFilmSolve::joint);
}

template <int Dim>
void check_stiff_approach(LubricationFilmSolve film_solve)
{
    SCOPED_TRACE(film_solve == LubricationFilmSolve::joint ? "joint" : "sweep");
    // A ball a = 1 cm (ρ = 2000) moving at 1 cm/s toward the floor from 2 roughness lengths
    // (20 µm) in a fluid of 10 Pa·s, range 2 mm, with Δt_i = 0.5 ms: c Δt_i / m ≫ 1, where an
    // explicit update of the damping would reverse and grow the velocity at every sub-step.
    const double a = 0.01;
    const double roughness = 1e-3 * a;
    const double mu = 10.0;
    const double range = 0.002;
    Vec<Dim> centre = Vec<Dim>::Constant(0.05);
    centre[Dim - 1] = a + 2.0 * roughness;
    Vec<Dim> velocity = Vec<Dim>::Zero();
    velocity[Dim - 1] = -0.01;
    std::vector<Particle<Dim>> bodies{test::ball<Dim>(centre, velocity, a, 2000.0)};
    std::array<bool, Dim> walled{};
    walled[Dim - 1] = true;
    const DemWalls<Dim> floor = test::box<Dim>(Vec<Dim>::Constant(0.1), walled);
    const double step = 5e-4;
    const DemSettings settings = lubricated(mu, range, 1, film_solve);
    const double stiffness =
        lubrication_correction<Dim>(2.0 * roughness, a, wall, settings.lubrication).normal * step /
        bodies[0].mass();
    EXPECT_GT(stiffness, 10.0);
    CellList<Dim> cells(floor.origin, floor.length, 2.0 * a + range + 0.5 * a);
    ContactHistory<Dim> history;
    double speed = 0.01;
    double gap = 2.0 * roughness;
    for (int s = 0; s < 200; ++s) {
        test::step_dem<Dim>(bodies, floor, settings, step, cells, history);
        const double v = bodies[0].velocity[Dim - 1];
        const double new_gap = bodies[0].centre[Dim - 1] - a;
        EXPECT_LE(v, 1e-15 * 0.01) << "sub-step " << s;          // never reverses
        EXPECT_LE(-v, speed + 1e-15 * 0.01) << "sub-step " << s; // decelerates monotonically
        EXPECT_LE(new_gap, gap);
        EXPECT_GT(new_gap, roughness) << "sub-step " << s; // stops above the roughness
        speed = -v;
        gap = new_gap;
    }
    EXPECT_LT(speed, 1e-6);
}

TEST(Lubrication, BodiesWithinRangeCountAsInContact)
{
    // A sphere 1 mm above the floor, range 2 mm: moved by the DEM for the step (paper coupling)
    // with lubrication on through the DEM (lubrication.coupling = "dem"); untouched, as
    // before, with it off.
    const double a = 0.01;
    for (const bool is_on : {true, false}) {
        std::vector<Particle<3>> bodies{
            test::ball<3>(Vec<3>(0.05, 0.05, a + 1e-3), Vec<3>(0.0, 0.0, -0.001), a, 2000.0)};
        const DemWalls<3> floor = test::box<3>(Vec<3>::Constant(0.1), {false, false, true});
        DemSettings settings = lubricated(1.0, 0.002, 10);
        settings.lubrication.is_enabled = is_on;
        CellList<3> cells(floor.origin, floor.length, 0.03);
        ContactHistory<3> history;
        test::step_dem<3>(bodies, floor, settings, 1e-3, cells, history);
        EXPECT_EQ(bodies[0].contact.is_in_contact, is_on);
        EXPECT_EQ(bodies[0].contact.mean_force.z() > 0.0, is_on);
        // Not touching: all of the contact force is lubrication, reported apart (particles.csv's
        // lubrication_f columns).
        EXPECT_EQ(bodies[0].contact.lubrication_force, bodies[0].contact.mean_force);
        EXPECT_EQ(bodies[0].contact.lubrication_torque, bodies[0].contact.mean_torque);
    }
}

TEST(Lubrication, UnderTheDefaultCouplingABodyWithinRangeIsLinkedNotInContact)
{
    // The default coupling ("implicit") leaves the sphere of the test above to eqs. (13)–(14):
    // not in contact, and one link to the floor with the correction for them (the sub-steps'
    // film force is then dropped by the step: drop_substep_lubrication).
    const double a = 0.01;
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>(0.05, 0.05, a + 1e-3), Vec<3>(0.0, 0.0, -0.001), a, 2000.0)};
    const DemWalls<3> floor = test::box<3>(Vec<3>::Constant(0.1), {false, false, true});
    DemSettings settings = lubricated(1.0, 0.002, 10);
    settings.lubrication.coupling = LubricationSettings{}.coupling;
    EXPECT_EQ(settings.lubrication.coupling, LubricationCoupling::implicit);
    CellList<3> cells(floor.origin, floor.length, 0.03);
    ContactHistory<3> history;
    test::step_dem<3>(bodies, floor, settings, 1e-3, cells, history);
    EXPECT_FALSE(bodies[0].contact.is_in_contact);
    ASSERT_EQ(bodies[0].contact.lubrication_links.size(), 1U);
    EXPECT_GT(bodies[0].contact.lubrication_links[0].resistance.normal, 0.0);
}

TEST(Lubrication, DryAndLubricationForcesAreReportedApart)
{
    // A sphere pressed 0.1 mm into the floor and still approaching: the spring pushes it up and,
    // under in_contact = saturated, the lubrication resists the approach (its correction held
    // at the roughness). The mean force is their sum, and the lubrication part is the same size
    // as it is alone. Under the default (off) the overlapping sphere gets no film force.
    const double a = 0.01;
    DemSettings settings = lubricated(1.0, 0.002, 10);
    settings.lubrication.in_contact = LubricationInContact::saturated;
    const DemWalls<3> floor = test::box<3>(Vec<3>::Constant(0.1), {false, false, true});
    const auto pressed = [&](bool is_on) {
        std::vector<Particle<3>> bodies{
            test::ball<3>(Vec<3>(0.05, 0.05, a - 1e-4), Vec<3>(0.0, 0.0, -0.001), a, 2000.0)};
        settings.lubrication.is_enabled = is_on;
        CellList<3> cells(floor.origin, floor.length, 0.03);
        ContactHistory<3> history;
        test::step_dem<3>(bodies, floor, settings, 1e-5, cells, history);
        return bodies[0].contact;
    };
    const ContactState<3> wet = pressed(true);
    const ContactState<3> dry = pressed(false);
    EXPECT_GT(wet.lubrication_force.z(), 0.0);
    EXPECT_EQ(dry.lubrication_force, Vec<3>::Zero());
    const Vec<3> spring = wet.mean_force - wet.lubrication_force;
    EXPECT_GT(spring.z(), 0.0);
    // Over 10 µs the spring barely changes: the dry part with lubrication on is the dry run's
    // to well within the lubrication force.
    EXPECT_NEAR(spring.z(), dry.mean_force.z(), 0.01 * wet.lubrication_force.z());

    settings.lubrication.in_contact = LubricationInContact::off;
    const ContactState<3> in_contact = pressed(true);
    EXPECT_EQ(in_contact.lubrication_force, Vec<3>::Zero());
    EXPECT_EQ(in_contact.lubrication_torque, Vec<3>::Zero());
    EXPECT_EQ(in_contact.mean_force, dry.mean_force); // bit for bit the dry sub-steps
    EXPECT_EQ(in_contact.velocity, dry.velocity);
}

/// The normal exit/entry speed of a ball of radius a = 1.5 mm (steel, 7800 kg/m³) that touches
/// the floor at v0 = 0.55 m/s, under the adaptive model (e_dry, N_c = 1000 steps of Δt =
/// 1.3 µs, one sub-step each: T_c = 1.3 ms) with the lubrication correction on (range 0.75 mm,
/// roughness 1e-3 a) in a fluid of viscosity μ. It starts 1 nm above the floor (inside the
/// first sub-step's travel, so the film acts on the way in over that 1 nm only), and the exit speed
/// is the one at the end of the first step after which the ball is apart again. 0 if it never
/// leaves within 5 T_c.
template <int Dim>
double wet_restitution(double restitution, double viscosity, LubricationInContact in_contact)
{
    const double a = 1.5e-3;
    const double v0 = 0.55;
    const double dt = 1.3e-6;
    const int collision_steps = 1000;
    DemSettings settings{AdaptiveCollision({restitution, collision_steps, 1e-6, dt}), 0.0, 1};
    settings.lubrication = {true, viscosity, 7.5e-4, 1e-3, in_contact};
    settings.lubrication.coupling = LubricationCoupling::dem; // the film in the sub-steps
    std::vector<Particle<Dim>> bodies{test::ball<Dim>(test::along<Dim>(Dim - 1, a + 1e-9, 0.01),
                                                      test::along<Dim>(Dim - 1, -v0), a, 7800.0)};
    std::array<bool, Dim> walled{};
    walled[Dim - 1] = true;
    const DemWalls<Dim> floor = test::box<Dim>(Vec<Dim>::Constant(0.02), walled);
    CellList<Dim> cells(floor.origin, floor.length, 2.0 * a + 7.5e-4 + 0.5 * a);
    ContactHistory<Dim> history;
    bool has_touched = false;
    for (int step = 0; step < 5 * collision_steps; ++step) {
        test::step_dem<Dim>(bodies, floor, settings, dt, cells, history);
        const double gap = bodies[0].centre[Dim - 1] - a;
        has_touched = has_touched || gap < 0.0;
        if (has_touched && gap > 0.0) {
            return bodies[0].velocity[Dim - 1] / v0;
        }
    }
    return 0.0;
}

template <int Dim>
void check_dry_restitution_in_contact()
{
    // The fluid's viscosity is chosen so that the saturated correction c(h_σ) would act with
    // c T_c / m = 3.3, as it did in the Gondret St 152 case (its header): the overlap then lasts
    // the stretched collision, and held there the film takes most of the impact's energy.
    const double a = 1.5e-3;
    const double mass = test::ball<Dim>(Vec<Dim>::Zero(), Vec<Dim>::Zero(), a, 7800.0).mass();
    LubricationSettings unit{true, 1.0, 7.5e-4, 1e-3};
    const double per_viscosity = lubrication_correction<Dim>(1e-3 * a, a, wall, unit).normal;
    const double viscosity = 3.3 * mass / (1.3e-3 * per_viscosity);
    // In the step the ball leaves the floor the film acts over the part of the drift beyond
    // contact only (at most one sub-step's travel at c(h_σ)): at most 3.3e-3 of the speed.
    const double exit_loss = 3.3 / 1000.0;
    for (const double e_dry : {0.97, 0.5}) {
        const double off = wet_restitution<Dim>(e_dry, viscosity, LubricationInContact::off);
        const double held = wet_restitution<Dim>(e_dry, viscosity, LubricationInContact::saturated);
        std::printf("%dD, e_dry %.2f: in_contact off e = %.5f, saturated e = %.5f\n", Dim, e_dry,
                    off, held);
        // 1000 sub-steps per collision: the adaptive model's e within 2.5e-4 of e_dry
        // (test_adaptive_collision.cpp).
        EXPECT_LE(off, e_dry + 2.5e-4);
        EXPECT_GE(off, e_dry * (1.0 - exit_loss) - 2.5e-4);
        EXPECT_LT(held, 0.5 * e_dry); // the former behaviour: most of the energy gone
    }
}

TEST(Lubrication, AdaptiveCollisionKeepsDryRestitutionWithTheFilmOffInContact)
{
    check_dry_restitution_in_contact<2>();
    check_dry_restitution_in_contact<3>();
}

TEST(Lubrication, PrescribedBodiesReportTheFilmForce)
{
    // A prescribed sphere (a = 1 cm) approaching the floor at 1 mm/s from a gap of 1 mm, range
    // 2 mm, μ = 1 Pa·s: it keeps its velocity, and its lubrication force is the correction's
    // integral over the step's travel, [G(h) − G(h − U Δt)] / Δt, upward (each sub-step's film
    // acts over its drift).
    const double a = 0.01;
    const double speed = 1e-3;
    const double dt = 1e-3;
    const auto film = [a, dt](double gap, double closing, double other, const DemSettings& s) {
        const auto big_g = [&](double h) {
            return lubrication_correction_integral<3>(h, a, other, s.lubrication).normal;
        };
        return (big_g(gap) - big_g(gap - closing * dt)) / dt;
    };
    const DemSettings settings = lubricated(1.0, 0.002, 10);
    const DemWalls<3> floor = test::box<3>(Vec<3>::Constant(0.1), {false, false, true});
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>(0.05, 0.05, a + 1e-3), Vec<3>(0.0, 0.0, -speed), a, 2000.0)};
    bodies[0].motion = Motion::prescribed;
    CellList<3> cells(floor.origin, floor.length, 0.03);
    ContactHistory<3> history;
    test::step_dem<3>(bodies, floor, settings, dt, cells, history);
    const double expected = film(1e-3, speed, wall, settings);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(bodies[0].contact.lubrication_force.z(), expected, 1e-9 * expected);
    EXPECT_EQ(bodies[0].contact.mean_force, bodies[0].contact.lubrication_force); // no dry part
    EXPECT_EQ(bodies[0].velocity, Vec<3>(0.0, 0.0, -speed));

    // Two prescribed spheres closing head-on at 2 mm/s with a 1 mm gap: equal and opposite
    // forces c_corr(h) w from the two-sphere resistance.
    std::vector<Particle<3>> pair{
        test::ball<3>(Vec<3>(0.04, 0.05, 0.05), Vec<3>(speed, 0.0, 0.0), a, 2000.0),
        test::ball<3>(Vec<3>(0.061, 0.05, 0.05), Vec<3>(-speed, 0.0, 0.0), a, 2000.0)};
    for (Particle<3>& b : pair) {
        b.motion = Motion::prescribed;
    }
    const DemWalls<3> open{Vec<3>::Zero(), Vec<3>(0.1, 0.1, 0.1), {false, false, false}};
    CellList<3> open_cells(open.origin, open.length, 0.03);
    test::step_dem<3>(pair, open, settings, dt, open_cells, history);
    const double closing = film(1e-3, 2.0 * speed, a, settings);
    EXPECT_NEAR(pair[1].contact.lubrication_force.x(), closing, 1e-9 * closing);
    EXPECT_EQ(pair[0].contact.lubrication_force, Vec<3>(-pair[1].contact.lubrication_force));
}

/// The film's integral J of python/fddem/rebound.py (film_passage_integral) for a sphere at a
/// wall: ∫ c_corr dh / (6πμa²) over h from h_Δ to 0, x = h/a, in closed form.
double film_passage_integral(double x_range, double x_rough)
{
    const auto c = [](double x) { return 1.0 / x + std::log(1.0 / x) / 5.0; };
    return std::log(x_range / x_rough) +
           (x_range * (1.0 - std::log(x_range)) - x_rough * (1.0 - std::log(x_rough))) / 5.0 -
           x_range * c(x_range) + x_rough * c(x_rough);
}

/// A sphere (the St 39 rebound's: a = 1.5 mm, ρs 7800, 0.455 m/s, μ 0.03042) driven by nothing
/// but the film from the edge of the range (a/2) through the floor (no contact force): its
/// loss of momentum over the passage, in units of 6πμa², with `dt` and 8 sub-steps.
double film_passage_in_the_dem(double dt)
{
    const double a = 1.5e-3;
    const double viscosity = 0.03042;
    const double v0 = 0.455;
    DemSettings settings{LinearSpringDashpot({1e-12, 0.0}, 1.0), 0.0,
                         8}; // no contact force to speak of
    settings.lubrication = {true, viscosity, 0.5 * a, 1e-3};
    settings.lubrication.coupling = LubricationCoupling::dem; // the film in the sub-steps
    const DemWalls<3> floor = test::box<3>(Vec<3>::Constant(0.02), {false, false, true});
    std::vector<Particle<3>> bodies{test::ball<3>(Vec<3>(0.01, 0.01, 1.5 * a * (1.0 - 1e-12)),
                                                  Vec<3>(0.0, 0.0, -v0), a, 7800.0)};
    CellList<3> cells(floor.origin, floor.length, 3.0 * a);
    ContactHistory<3> history;
    while (bodies[0].centre.z() > 0.9 * a) { // through the film and into the floor
        test::step_dem<3>(bodies, floor, settings, dt, cells, history);
    }
    const double lost = bodies[0].mass() * (v0 + bodies[0].velocity.z());
    return lost / (6.0 * std::numbers::pi * viscosity * a * a);
}

TEST(Lubrication, AFilmPassageTakesTheImpulseOfTheIntegratedCorrection)
{
    // F = c_corr(h) v and dh = v dt: the impulse over the passage is ∫ c_corr dh whatever the
    // speed, J = 6.3144 (6πμa²) at range a/2 and roughness 1e-3 a (the film's own restitution,
    // docs/method.md §5). Each sub-step's film is the correction averaged over the drift it
    // precedes (film_step), so the sum telescopes to J at any step: from 1e-7 s to 1e-4 s (the
    // Gondret cases' step near the floor, 8 sub-steps) to round-off. With the resistance at
    // the gap each sub-step ended with, this passage took 5.2549 at 1e-4 s (0.83 J) and varied
    // non-monotonically with Δt (commit 89c5c3a's measurement).
    const double exact = film_passage_integral(0.5, 1e-3);
    EXPECT_NEAR(exact, 6.3144, 1e-4);
    for (const double dt : {1e-4, 5e-5, 2.5e-5, 1e-5, 1e-7}) {
        const double taken = film_passage_in_the_dem(dt);
        std::printf("film passage J at dt %.1e s: %.10f (closed form %.10f)\n", dt, taken, exact);
        EXPECT_NEAR(taken, exact, 1e-9 * exact) << "dt " << dt;
    }
}

TEST(Lubrication, ImplicitDampingIsStableWhenStiff)
{
    for (const LubricationFilmSolve solve :
         {LubricationFilmSolve::sweep, LubricationFilmSolve::joint}) {
        check_stiff_approach<2>(solve);
        check_stiff_approach<3>(solve);
    }
}

/// The largest difference of the bodies' velocities between two runs, matched by id.
template <int Dim>
double largest_velocity_difference(const std::vector<Particle<Dim>>& x,
                                   const std::vector<Particle<Dim>>& y)
{
    double largest = 0.0;
    for (const Particle<Dim>& b : x) {
        for (const Particle<Dim>& c : y) {
            if (c.id == b.id) {
                largest = std::max(largest, (b.velocity - c.velocity).norm());
            }
        }
    }
    return largest;
}

template <int Dim>
void check_order(LubricationFilmSolve film_solve, double bound, bool is_order_dependent)
{
    // A column of four balls settling onto the floor, each within the range of the next: the
    // bodies given in store order and reversed (the same ids), 40 sub-steps of lubrication
    // alone (no contact: the gaps stay above the roughness).
    const double a = 0.01;
    std::vector<Particle<Dim>> bodies;
    for (int i = 0; i < 4; ++i) {
        Vec<Dim> centre = Vec<Dim>::Constant(0.05);
        centre[Dim - 1] = a + 4e-4 + i * (2.0 * a + 3e-4 + 1e-4 * i);
        centre[0] += 1e-4 * i; // off the column's axis: the films also turn the balls
        Vec<Dim> velocity = Vec<Dim>::Zero();
        velocity[Dim - 1] = -0.01 * (1 + i);
        velocity[0] = 0.002 * (i % 2 == 0 ? 1.0 : -1.0);
        bodies.push_back(test::ball<Dim>(centre, velocity, a, 1500.0));
        bodies.back().id = i;
    }
    std::vector<Particle<Dim>> reversed(bodies.rbegin(), bodies.rend());
    const std::vector<Particle<Dim>> start = bodies;
    std::array<bool, Dim> walled{};
    walled[Dim - 1] = true;
    const DemWalls<Dim> box = test::box<Dim>(Vec<Dim>::Constant(0.1), walled);
    const DemSettings settings = lubricated(0.5, 0.002, 40, film_solve);
    CellList<Dim> cells(box.origin, box.length, 2.0 * a + 0.002 + 0.5 * a);
    CellList<Dim> other_cells(box.origin, box.length, 2.0 * a + 0.002 + 0.5 * a);
    ContactHistory<Dim> history;
    ContactHistory<Dim> other_history;
    const DemOutcome one =
        test::step_dem_keeping_ids<Dim>(bodies, box, settings, 2e-3, cells, history);
    const DemOutcome two =
        test::step_dem_keeping_ids<Dim>(reversed, box, settings, 2e-3, other_cells, other_history);
    EXPECT_EQ(one.n_contacts, 0);
    EXPECT_EQ(two.n_contacts, 0);
    const double difference = largest_velocity_difference<Dim>(bodies, reversed);
    std::printf("%dD, %s: velocities differ by %.3g m/s between the two orders\n", Dim,
                film_solve == LubricationFilmSolve::joint ? "joint" : "sweep", difference);
    if (is_order_dependent) {
        EXPECT_GT(difference, bound) << "the sweep no longer depends on the order";
    } else {
        EXPECT_LT(difference, bound);
    }
    const auto size = [](const AngularVec<Dim>& w) {
        if constexpr (Dim == 2) {
            return std::abs(w);
        } else {
            return w.norm();
        }
    };
    const double dt = 2e-3;
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        const Particle<Dim>& b = bodies[k];
        // The films slowed every approach.
        EXPECT_GT(b.velocity[Dim - 1], -0.01 * (1 + b.id));
        // What the forces report is what moved the body: no contact acted, so the mean force
        // is the lubrication force, and its impulse over the step the change of momentum (the
        // same for the torque and the angular momentum).
        EXPECT_EQ(b.contact.mean_force, b.contact.lubrication_force);
        const Vec<Dim> momentum = b.mass() * (b.velocity - start[k].velocity);
        EXPECT_LT((momentum - dt * b.contact.mean_force).norm(), 1e-9 * momentum.norm())
            << "ball " << b.id;
        const AngularVec<Dim> spin = b.inertia() * (b.omega - start[k].omega);
        EXPECT_GT(size(spin), 0.0) << "the films did not turn ball " << b.id;
        EXPECT_LT(size(spin - dt * b.contact.mean_torque), 1e-9 * size(spin)) << "ball " << b.id;
    }
}

TEST(Lubrication, JointFilmsDoNotDependOnTheBodiesOrder)
{
    // What moving the DEM to the owners of a split run needs (docs/parallel.md): a rank holding
    // the bodies in another order gets the same films. The sweep does not; the joint solve does,
    // to its tolerance.
    check_order<2>(LubricationFilmSolve::sweep, 1e-6, true);
    check_order<3>(LubricationFilmSolve::sweep, 1e-6, true);
    // The joint solve's tolerance is 1e-13 of the largest gap rate (0.04 m/s); 1e-12 of it.
    check_order<2>(LubricationFilmSolve::joint, 4e-14, false);
    check_order<3>(LubricationFilmSolve::joint, 4e-14, false);
}

} // namespace
} // namespace fddem
