// SPDX-License-Identifier: MIT
// The adaptive collision model (contact/adaptive_collision.hpp, Kempe & Fröhlich 2012) and the
// scaled Hertz-with-damper collision behind it (contact/hertz_damper_collision.hpp): the scaled
// collision against the exact undamped Hertz solution and the first-order energy loss of a weak
// damper; then, integrated by fddem's DEM sub-steps, single collisions (ball–wall and
// ball–ball, 2D and 3D, several impact speeds) rebound with e_dry and last N_c Δt whatever the
// speed and mass, the constants are kept while a contact stays open and fixed anew for the next
// one, and bad input names its key.

#include "fddem/contact/adaptive_collision.hpp"
#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/hertz_damper_collision.hpp"
#include "fddem/core/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

using test::along;

/// (5/4)^{2/5}: the undamped scaled collision's largest overlap (x'²/2 + (2/5) x^{5/2} = 1/2).
const double undamped_max_overlap = std::pow(1.25, 0.4);

TEST(HertzDamperCollision, UndampedCollisionIsHertzs)
{
    const ScaledCollision c = scaled_hertz_damper_collision(0.0);
    // τ_c = 2 x_max ∫₀¹ (1 − u^{5/2})^{−1/2} du, the integral √π Γ(7/5)/Γ(9/10) (Johnson 1985,
    // ch. 11; hertz_mindlin.hpp).
    const double integral = std::sqrt(std::numbers::pi) * std::tgamma(1.4) / std::tgamma(0.9);
    std::printf("undamped: e − 1 = %.1e, tau_c = %.12f (exact %.12f), x_max = %.12f\n",
                c.restitution - 1.0, c.duration, 2.0 * integral * undamped_max_overlap,
                c.max_overlap);
    // RK4 at a step of 1e-3 (hertz_damper_collision.hpp): 1e-9 is a thousand times its error.
    EXPECT_NEAR(c.restitution, 1.0, 1e-9);
    EXPECT_NEAR(c.duration, 2.0 * integral * undamped_max_overlap, 1e-9);
    // The largest x is sampled at the steps: within (1e-3)² x'' of the peak.
    EXPECT_NEAR(c.max_overlap, undamped_max_overlap, 1e-6);
}

TEST(HertzDamperCollision, WeakDamperLosesTheFirstOrderEnergy)
{
    // To first order in γ the damper removes γ ∫ x'² dτ of the energy 1/2 along the undamped
    // path, x'² = 1 − (4/5) x^{5/2}: 1 − e = γ · 2 x_max B, B = ∫₀¹ (1 − u^{5/2})^{1/2} du =
    // (2/5) Γ(2/5) Γ(3/2) / Γ(19/10), with an O(γ²) remainder.
    const double b = 0.4 * std::tgamma(0.4) * std::tgamma(1.5) / std::tgamma(1.9);
    const double slope = 2.0 * undamped_max_overlap * b;
    for (const double gamma : {1e-4, 1e-3}) {
        const double loss = 1.0 - scaled_hertz_damper_collision(gamma).restitution;
        EXPECT_NEAR(loss / gamma, slope, 2.0 * gamma * slope) << "gamma = " << gamma;
    }
}

TEST(HertzDamperCollision, DampingForRestitutionInvertsTheCollision)
{
    EXPECT_EQ(scaled_damping_for_restitution(1.0), 0.0);
    double previous = 0.0;
    for (const double e : {0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01}) {
        const double gamma = scaled_damping_for_restitution(e);
        const ScaledCollision c = scaled_hertz_damper_collision(gamma);
        std::printf("e = %.2f: gamma = %.10f, tau_c = %.6f, x_max = %.6f\n", e, gamma, c.duration,
                    c.max_overlap);
        EXPECT_NEAR(c.restitution, e, 1e-12 * e);
        EXPECT_GT(gamma, previous); // e falls as γ grows
        previous = gamma;
    }
    // Beyond γ* ≈ 1.128 the overlap creeps back and never reaches 0: no rebound.
    EXPECT_LT(previous, 1.128);
    const ScaledCollision stuck = scaled_hertz_damper_collision(1.2);
    EXPECT_EQ(stuck.restitution, 0.0);
    EXPECT_TRUE(std::isinf(stuck.duration));
}

/// Glass-like spheres: 2500 kg/m³; the surfaces do not matter to the adaptive model.
constexpr double density = 2500.0;

AdaptiveCollision::Params adaptive(double restitution, double dt, int collision_steps = 10)
{
    return {restitution, collision_steps, 1e-6, dt};
}

/// What one collision did: exit/entry normal speed, and its duration from the straight free
/// flights before and after it (no gravity: they are exact lines), extrapolated to α = 0.
struct Collision {
    double restitution;
    double duration; ///< [s]
};

/// Runs whole fluid steps of `dt` with `substeps` sub-steps each (as Simulation does) until the
/// gap `gap(bodies)` (> 0 apart) has closed and opened again and the bodies are 10 steps past.
/// `approach(bodies)` is the normal approach speed. Before the touch the gap closes at v0 from
/// g0: t_touch = g0/v0; after, the gap opens at the exit speed: t_exit = t − gap/speed.
template <int Dim, class Gap, class Approach>
Collision collide(std::vector<Particle<Dim>>& bodies, const DemWalls<Dim>& walls,
                  const AdaptiveCollision& model, double dt, int substeps, Gap gap,
                  Approach approach)
{
    const double v0 = approach(bodies);
    const double touch = gap(bodies) / v0;
    double largest = 0.0;
    for (const Particle<Dim>& b : bodies) {
        largest = std::max(largest, 2.0 * b.radius());
    }
    CellList<Dim> cells(walls.origin, walls.length, largest);
    ContactHistory<Dim> history;
    const DemSettings settings{model, 0.0, substeps};
    bool has_touched = false;
    int after = 0;
    long steps = 0;
    while (after < 10 && steps < 100000) {
        (void)test::step_dem<Dim>(bodies, walls, settings, dt, cells, history);
        ++steps;
        has_touched = has_touched || !history.coefficients.empty();
        if (has_touched && history.coefficients.empty()) {
            ++after;
        }
    }
    const double exit_speed = -approach(bodies);
    const double exit = static_cast<double>(steps) * dt - gap(bodies) / exit_speed;
    return {exit_speed / v0, exit - touch};
}

/// A ball of radius r at gap g0 above the floor (axis 1) moving down at v0, through steps of
/// dt with `substeps` sub-steps.
template <int Dim>
Collision wall_collision(const AdaptiveCollision& model, double v0, double dt, int substeps)
{
    const double r = 0.05;
    const double g0 = 2e-4; // touches after 0.07–20 steps, at a different phase of each
    std::vector<Particle<Dim>> bodies{
        test::ball<Dim>(along<Dim>(1, r + g0, 0.5), along<Dim>(1, -v0), r, density)};
    DemWalls<Dim> floor = test::box<Dim>(Vec<Dim>::Constant(1.0), {});
    floor.has_walls[1] = true;
    return collide<Dim>(
        bodies, floor, model, dt, substeps, [r](const auto& b) { return b[0].centre[1] - r; },
        [](const auto& b) { return -b[0].velocity[1]; });
}

/// Two unequal balls (radii 0.05 and 0.03, densities 2500 and 7800 kg/m³) head on along a
/// slant line, closing at v0.
template <int Dim>
Collision pair_collision(const AdaptiveCollision& model, double v0, double dt, int substeps)
{
    const double r1 = 0.05;
    const double r2 = 0.03;
    const Vec<Dim> n = Vec<Dim>::Ones().normalized();
    const Vec<Dim> c1 = Vec<Dim>::Constant(0.4);
    const double g0 = 2e-4;
    std::vector<Particle<Dim>> bodies{
        test::ball<Dim>(c1, Vec<Dim>(0.7 * v0 * n), r1, density),
        test::ball<Dim>(c1 + (r1 + r2 + g0) * n, Vec<Dim>(-0.3 * v0 * n), r2, 7800.0)};
    const DemWalls<Dim> open = test::box<Dim>(Vec<Dim>::Constant(1.0), {});
    return collide<Dim>(
        bodies, open, model, dt, substeps,
        [=](const auto& b) { return (b[1].centre - b[0].centre).norm() - r1 - r2; },
        [=](const auto& b) { return (b[0].velocity - b[1].velocity).dot(n); });
}

template <class D>
class AdaptiveImpact : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(AdaptiveImpact, Dimensions);

// Tolerances: the error of the sub-steps is first order in Δt_i / T_c (the contact opens within
// a sub-step and the damper's force jumps there): at 1000 sub-steps per collision e is within
// 2.5e-4 and T_c within 1e-4, measured; 1e-3 and 1 % leave room. At fddem's automatic 80 per
// collision (8 per step at N_c = 10) e is 0.4966 for 0.5 and 0.96998 for 0.97 (printed).
constexpr int fine_substeps = 100; // per step: 1000 per collision at N_c = 10

TYPED_TEST(AdaptiveImpact, WallCollisionReboundsWithEdryAndLastsNcStepsAtAnySpeed)
{
    constexpr int Dim = TypeParam::value;
    const double dt = 1e-3;
    for (const double e : {0.97, 0.5}) {
        const AdaptiveCollision model(adaptive(e, dt));
        for (const double v0 : {0.01, 0.3, 3.0}) {
            for (const int substeps : {8, fine_substeps}) {
                const Collision c = wall_collision<Dim>(model, v0, dt, substeps);
                std::printf("%dD wall, e_dry %.2f, %4.2f m/s, %3d sub-steps per step: e = %.5f, "
                            "T_c / (N_c dt) = %.5f\n",
                            Dim, e, v0, substeps, c.restitution, c.duration / (10.0 * dt));
                if (substeps == fine_substeps) {
                    EXPECT_NEAR(c.restitution, e, 1e-3) << "v0 = " << v0;
                    EXPECT_NEAR(c.duration / (10.0 * dt), 1.0, 0.01) << "v0 = " << v0;
                }
            }
        }
    }
}

TYPED_TEST(AdaptiveImpact, PairCollisionReboundsWithEdryAndLastsNcSteps)
{
    constexpr int Dim = TypeParam::value;
    const double dt = 2e-3;
    for (const int collision_steps : {4, 10}) {
        const AdaptiveCollision model(adaptive(0.8, dt, collision_steps));
        const double t_c = collision_steps * dt;
        for (const double v0 : {0.05, 2.0}) {
            const Collision c = pair_collision<Dim>(model, v0, dt, 1000 / collision_steps);
            std::printf("%dD pair, N_c %d, %4.2f m/s: e = %.5f, T_c / (N_c dt) = %.5f\n", Dim,
                        collision_steps, v0, c.restitution, c.duration / t_c);
            EXPECT_NEAR(c.restitution, 0.8, 1e-3) << "v0 = " << v0;
            EXPECT_NEAR(c.duration / t_c, 1.0, 0.01) << "v0 = " << v0;
        }
    }
}

TEST(AdaptiveCollision, CoefficientsFollowTheScaling)
{
    const double dt = 1e-3;
    const AdaptiveCollision model({0.6, 10, 0.05, dt});
    ContactPair pair;
    pair.effective_mass = 0.2;
    const double gamma = model.scaled_damping();
    const double time_scale = 10.0 * dt / model.scaled().duration; // T = T_c / τ_c
    const NormalCoefficients k = model.coefficients(pair, 0.8, dt);
    // k L^{1/2} T² / m = 1 with L = v T; γ = d T / m.
    EXPECT_NEAR(k.stiffness * std::sqrt(0.8 * time_scale) * time_scale * time_scale / 0.2, 1.0,
                1e-14);
    EXPECT_NEAR(k.damping * time_scale / 0.2, gamma, 1e-14 * gamma);
    // k ∝ m v^{−1/2}, d ∝ m; T_c follows the step it opens in.
    const NormalCoefficients slower = model.coefficients(pair, 0.2, dt);
    EXPECT_NEAR(slower.stiffness / k.stiffness, 2.0, 1e-14);
    EXPECT_EQ(slower.damping, k.damping);
    pair.effective_mass = 0.6;
    EXPECT_NEAR(model.coefficients(pair, 0.8, dt).stiffness / k.stiffness, 3.0, 1e-14);
    pair.effective_mass = 0.2;
    const NormalCoefficients longer = model.coefficients(pair, 0.8, 2.0 * dt);
    EXPECT_NEAR(longer.damping / k.damping, 0.5, 1e-14);
    // Below v_min = 0.05 m/s (and at rest, or separating) the constants of an impact at v_min.
    const NormalCoefficients floor = model.coefficients(pair, 0.05, dt);
    for (const double v : {0.01, 0.0, -0.3}) {
        EXPECT_EQ(model.coefficients(pair, v, dt).stiffness, floor.stiffness) << v;
    }
    // The law: F_n = k α^{3/2} + d α̇, k_t = κ (3/2) k α^{1/2}, c_t = √κ d (κ = 2/7).
    const ContactLaw law = model.law({1e-4, 0.3}, pair, k);
    EXPECT_NEAR(law.normal_force, k.stiffness * 1e-6 + k.damping * 0.3, 1e-14 * law.normal_force);
    EXPECT_NEAR(law.tangential_stiffness, 2.0 / 7.0 * 1.5 * k.stiffness * 1e-2,
                1e-14 * law.tangential_stiffness);
    EXPECT_NEAR(law.tangential_damping, std::sqrt(2.0 / 7.0) * k.damping, 1e-14 * k.damping);
    EXPECT_EQ(model.elastic_collision_time(pair, 123.0), 10.0 * dt);
    EXPECT_EQ(model.restitution(pair), 0.6);
}

TEST(AdaptiveCollision, ConstantsAreKeptWhileAContactIsOpenAndFixedAnewForTheNext)
{
    const double dt = 1e-3;
    const AdaptiveCollision model({0.7, 10, 1e-6, dt});
    const double r = 0.05;
    std::vector<Particle<2>> bodies{
        test::ball<2>(Vec<2>(0.5, r + 1e-4), Vec<2>(0.0, -0.2), r, density)};
    DemWalls<2> floor = test::box<2>(Vec<2>(1.0, 1.0), {false, true});
    CellList<2> cells(floor.origin, floor.length, 2.0 * r);
    ContactHistory<2> history;
    const DemSettings settings{model, 0.0, 20};
    const ContactPair pair = make_contact_pair(
        ball_side(bodies[0].mass(), bodies[0].inertia(), r, {}, true), wall_side({}));
    const ContactKey floor_key = wall_contact_key(0, 1, 0);
    for (const double v : {0.2, 1.5}) {
        bodies[0].velocity = Vec<2>(0.0, -v); // thrown back down (a new contact)
        bodies[0].centre.y() = r + 1e-4;
        int open_steps = 0;
        std::optional<NormalCoefficients> first;
        for (int s = 0; s < 40; ++s) {
            (void)test::step_dem<2>(bodies, floor, settings, dt, cells, history);
            const PairCoefficients* entry = history.find_coefficients(floor_key);
            if (entry == nullptr) {
                if (first) {
                    break; // the contact opened: its constants are gone
                }
                continue;
            }
            ASSERT_EQ(history.coefficients.size(), 1U);
            if (!first) {
                first = entry->normal;
                // Fixed from the approach speed at the touch: v (no force acts before it).
                const NormalCoefficients expected = model.coefficients(pair, v, dt);
                EXPECT_NEAR(first->stiffness, expected.stiffness, 1e-12 * expected.stiffness);
                EXPECT_NEAR(first->damping, expected.damping, 1e-12 * expected.damping);
            }
            EXPECT_EQ(entry->normal.stiffness, first->stiffness); // kept, bit for bit
            EXPECT_EQ(entry->normal.damping, first->damping);
            ++open_steps;
        }
        ASSERT_TRUE(first.has_value());
        EXPECT_TRUE(history.coefficients.empty());
        EXPECT_GE(open_steps, 9) << "v = " << v; // open through T_c = 10 steps
        // Rebounding with e_dry (200 sub-steps per collision: within 2e-3, as above).
        EXPECT_NEAR(bodies[0].velocity.y() / v, 0.7, 2e-3) << "v = " << v;
    }
}

TEST(AdaptiveCollision, BodyRestingOnTheFloorOscillatesWithThePeriodOfTheFloor)
{
    // A sphere under its weight m g touches the floor at rest: the constants are those of an
    // impact at v_min = g T_c / 1000 (the default floor), k = m / (v_min^{1/2} T^{5/2}), and
    // about its static overlap α_s = (m g / k)^{2/3} it oscillates (undamped, e_dry = 1) at
    // (ωT)² = (3/2) (gT/v_min)^{1/3}: the period is 0.61 T_c (adaptive_collision.hpp).
    // Sampled at every one of 200 steps per collision (N_c = 200, one sub-step each).
    const double g = 9.81;
    const double dt = 5e-5;
    const int collision_steps = 200;
    const double t_c = collision_steps * dt;
    const double floor = g * t_c / AdaptiveCollision::floor_ratio;
    const AdaptiveCollision model({1.0, collision_steps, floor, dt});
    const double r = 0.05;
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>(0.5, r, 0.5), Vec<3>(0.0, -1e-9, 0.0), r, density)};
    const double mass = bodies[0].mass();
    const double time_scale = t_c / model.scaled().duration;
    const double k = mass / (std::sqrt(floor) * std::pow(time_scale, 2.5));
    const double rest = std::pow(mass * g / k, 2.0 / 3.0);
    bodies[0].centre.y() = r - 1.01 * rest; // 1 % below the rest position: small amplitude
    bodies[0].contact.steady_force = Vec<3>(0.0, -mass * g, 0.0);
    DemWalls<3> floor_only = test::box<3>(Vec<3>::Constant(1.0), {false, true, false});
    CellList<3> cells(floor_only.origin, floor_only.length, 2.0 * r);
    ContactHistory<3> history;
    const DemSettings settings{model, 0.0, 1};
    std::vector<double> upward_crossings;
    double previous = bodies[0].velocity.y();
    for (int s = 1; s <= 2000; ++s) {
        (void)test::step_dem<3>(bodies, floor_only, settings, dt, cells, history);
        bodies[0].contact.steady_force = Vec<3>(0.0, -mass * g, 0.0);
        const double v = bodies[0].velocity.y();
        if (previous < 0.0 && v >= 0.0) {
            upward_crossings.push_back((s - 1 + previous / (previous - v)) * dt);
        }
        previous = v;
    }
    ASSERT_FALSE(history.coefficients.empty()); // never left the floor
    EXPECT_NEAR(history.coefficients[0].normal.stiffness, k, 1e-12 * k);
    ASSERT_GE(upward_crossings.size(), 5U);
    const double period = (upward_crossings.back() - upward_crossings.front()) /
                          static_cast<double>(upward_crossings.size() - 1);
    const double omega =
        std::sqrt(1.5 * std::cbrt(g * time_scale / floor)) / time_scale; // linearised
    std::printf("resting sphere: period %.4f T_c (linearised %.4f T_c), static overlap %.3g m\n",
                period / t_c, 2.0 * std::numbers::pi / omega / t_c, rest);
    // Amplitude 1 % of α_s: the nonlinearity shifts the period by O(1e-4); Verlet at about 120
    // sub-steps per period by (ωΔt)²/24 ≈ 1e-4.
    EXPECT_NEAR(period * omega / (2.0 * std::numbers::pi), 1.0, 2e-3);
    EXPECT_NEAR(period / t_c, 0.61, 0.005);
}

TEST(AdaptiveCollision, BadInputNamesItsKey)
{
    const auto key_of = [](const AdaptiveCollision::Params& p) {
        try {
            (void)AdaptiveCollision(p);
        } catch (const InputError& e) {
            return e.key();
        }
        return std::string("no error");
    };
    EXPECT_EQ(key_of({0.0, 10, 0.1, 1e-3}), "contact.restitution");
    EXPECT_EQ(key_of({1.1, 10, 0.1, 1e-3}), "contact.restitution");
    EXPECT_EQ(key_of({-0.5, 10, 0.1, 1e-3}), "contact.restitution");
    EXPECT_EQ(key_of({0.5, 0, 0.1, 1e-3}), "contact.collision_steps");
    EXPECT_EQ(key_of({0.5, 10, 0.0, 1e-3}), "contact.minimum_impact_velocity");
    EXPECT_EQ(key_of({0.5, 10, 0.1, 0.0}), "time.dt");
    EXPECT_EQ(key_of({1.0, 1, 0.1, 1e-3}), "no error");
}

} // namespace
} // namespace fddem
