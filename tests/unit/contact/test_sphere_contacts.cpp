// SPDX-License-Identifier: MIT
// Contacts of spheres in 3D, through the DEM sub-steps (contact/dem_step.hpp), against analytic
// collisions:
//  - the linear spring–dashpot's restitution e = exp(−πζ/√(1 − ζ²)) for a sphere pair along an
//    oblique line and for a sphere on each of the six walls of the box;
//  - Hertz (Johnson 1985, ch. 11): duration 2.87 (m*²/(R* E*² v))^{1/5} and peak force
//    (4/3) E* √R* α_max^{3/2} of an unequal pair, R* = R₁R₂/(R₁ + R₂), and the restitution of
//    the Tsuji-form dashpot (contact/hertz_mindlin.hpp) at two impact speeds;
//  - oblique impact on a wall, the two regimes of Maw, Barber & Fawcett (1976) with exact answers
//    for the linear model: sticking at small incidence (κ = 2/7 gives a solid sphere equal
//    normal and tangential periods, so the contact point's tangential velocity is reversed) and
//    gross sliding at large incidence (ω = 5μ(1 + e)v_n/(2R) about n × t̂), and gross sliding of
//    an unequal pair in three random orientations (the Coulomb impulse μ m*(1 + e)v_n);
//  - a sphere rolling (and twisting) across the floor along a diagonal decelerates at
//    (5/7) μ_r g, the rate of the constant rolling torque, without turning aside, and keeps its
//    twist (the torque acts on the rolling part of ω only);
//  - a frictional collision never gains kinetic energy;
//  - a frictional, spinning, off-centre pair conserves linear and angular momentum, and the same
//    collision turned by a random rotation gives the turned answer (rotational invariance).

#include "fddem/contact/dem_step.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double density = 2500.0; // [kg/m³]

/// E = 1e8 Pa, ν = 0.25, friction μ, rolling friction μ_r, restitution e.
Material surface(double mu, double mu_r, double e)
{
    return {1.0e8, 0.25, mu, mu_r, e};
}

double kinetic_energy(const std::vector<Particle<3>>& bodies)
{
    double energy = 0.0;
    for (const Particle<3>& b : bodies) {
        energy +=
            0.5 * b.mass() * b.velocity.squaredNorm() + 0.5 * b.inertia() * b.omega.squaredNorm();
    }
    return energy;
}

double overlap(const Particle<3>& a, const Particle<3>& b)
{
    return a.radius() + b.radius() - (b.centre - a.centre).norm();
}

/// The unbounded box [0, 1]³ (no walls), or with all six walls.
DemWalls<3> open_box()
{
    return test::box<3>(Vec<3>::Constant(1.0), {false, false, false});
}
DemWalls<3> closed_box(const Material& m)
{
    return test::box<3>(Vec<3>::Constant(1.0), {true, true, true}, m);
}

/// A uniformly distributed rotation (Shoemake 1992, "Uniform random rotations").
Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double u1 = u(rng);
    const double u2 = 2.0 * pi * u(rng);
    const double u3 = 2.0 * pi * u(rng);
    const Eigen::Quaterniond q(std::sqrt(u1) * std::cos(u3), std::sqrt(1.0 - u1) * std::sin(u2),
                               std::sqrt(1.0 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3));
    return q.toRotationMatrix();
}

/// What a binary collision did, observed after each sub-step.
struct Collision {
    double duration = 0.0;   ///< time with α > 0 [s]
    double peak_force = 0.0; ///< largest |contact force| on the first body [N]
};

/// Runs sub-steps of `step` until the first contact has opened again (`gap` > 0 after it was
/// ≤ 0), or `max_steps`.
template <class Gap>
Collision collide(std::vector<Particle<3>>& bodies, const DemWalls<3>& walls,
                  const AnyContactModel& model, double step, long max_steps, Gap gap)
{
    Collision out;
    bool has_touched = false;
    ContactHistory<3> history;
    test::run_substeps<3>(bodies, walls, DemSettings{model, 0.0, 1}, step, max_steps, history,
                          [&](const auto& b, const auto&) {
                              const double g = gap(b);
                              if (g < 0.0) {
                                  has_touched = true;
                                  out.duration += step;
                              }
                              out.peak_force =
                                  std::max(out.peak_force, b[0].contact.mean_force.norm());
                              return !(has_touched && g >= 0.0);
                          });
    EXPECT_TRUE(has_touched);
    return out;
}

/// e of the linear model from its k, c and the effective mass: exp(−πζ/√(1 − ζ²)).
double linear_restitution(const LinearSpringDashpot::Params& p, double mass)
{
    const double zeta = p.damping / (2.0 * std::sqrt(p.stiffness * mass));
    return std::exp(-pi * zeta / std::sqrt(1.0 - zeta * zeta));
}

// (a) The linear spring–dashpot.

TEST(SphereContacts, LinearPairReboundsWithTheAnalyticRestitutionAlongAnObliqueLine)
{
    const double r1 = 0.05;
    const double r2 = 0.03;
    const Vec<3> n = Vec<3>(2.0, -3.0, 6.0) / 7.0;
    for (const double e : {0.9, 0.5}) {
        std::vector<Particle<3>> bodies{
            test::ball<3>(Vec<3>::Constant(0.4), 1.5 * n, r1, density),
            test::ball<3>(Vec<3>::Constant(0.4) + (r1 + r2 + 1e-9) * n, -0.5 * n, r2, 7800.0)};
        const double mass =
            1.0 / (1.0 / bodies[0].mass() + 1.0 / bodies[1].mass()); // m* = m₁m₂/(m₁ + m₂)
        const auto params = LinearSpringDashpot::from_restitution(e, 1e-3, mass);
        const double analytic = linear_restitution(params, mass);
        const Vec<3> p0 =
            bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
        const Collision c = collide(bodies, open_box(), LinearSpringDashpot(params, mass), 1e-6,
                                    10000, [](const auto& b) { return -overlap(b[0], b[1]); });
        const double measured = (bodies[1].velocity - bodies[0].velocity).dot(n) / 2.0;
        const Vec<3> p1 =
            bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
        std::printf("linear pair: e = %.5f (analytic %.5f), t_c = %.4g s (π/ω_d = 1e-3 s)\n",
                    measured, analytic, c.duration);
        // 1000 sub-steps per contact: the explicit dashpot's O(Δt_i) error is 1e-3 of e.
        EXPECT_NEAR(measured / analytic, 1.0, 2e-3) << "e = " << e;
        EXPECT_NEAR(c.duration / 1e-3, 1.0, 2e-3) << "e = " << e;
        EXPECT_LT((p1 - p0).norm(), 1e-13 * bodies[0].mass());
        // Frictionless and head on: no velocity across the line of centres, no spin.
        EXPECT_LT((bodies[0].velocity - bodies[0].velocity.dot(n) * n).norm(), 1e-12);
        EXPECT_LT(bodies[0].omega.norm(), 1e-12); // round-off of n × n
    }
}

TEST(SphereContacts, LinearWallImpactOnEachOfTheSixWallsGivesTheAnalyticRestitution)
{
    const double r = 0.05;
    const double e = 0.7;
    const Material smooth = surface(0.0, 0.0, e);
    const double mass = density * Ball<3>{2.0 * r}.volume();
    const auto params = LinearSpringDashpot::from_restitution(e, 1e-3, mass);
    const double analytic = linear_restitution(params, mass);
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            // Towards the wall at 1 m/s, and 0.4 m/s along it (frictionless: kept).
            const double out = side == 0 ? -1.0 : 1.0;
            Vec<3> centre = Vec<3>::Constant(0.5);
            centre[axis] = side == 0 ? r + 1e-9 : 1.0 - r - 1e-9;
            Vec<3> velocity = Vec<3>::Zero();
            velocity[axis] = out;
            velocity[(axis + 1) % 3] = 0.4;
            std::vector<Particle<3>> bodies{test::ball<3>(centre, velocity, r, density, smooth)};
            (void)collide(bodies, closed_box(smooth), LinearSpringDashpot(params, mass), 1e-6,
                          10000, [&](const auto& b) {
                              const double wall = side == 0 ? 0.0 : 1.0;
                              return std::abs(b[0].centre[axis] - wall) - r;
                          });
            const double measured = -bodies[0].velocity[axis] / out;
            std::printf("linear wall %c %s: e = %.5f (analytic %.5f)\n", "xyz"[axis],
                        side == 0 ? "low" : "high", measured, analytic);
            EXPECT_NEAR(measured / analytic, 1.0, 2e-3) << "axis " << axis << " side " << side;
            EXPECT_EQ(bodies[0].velocity[(axis + 1) % 3], 0.4);
            EXPECT_EQ(bodies[0].velocity[(axis + 2) % 3], 0.0);
            EXPECT_EQ(bodies[0].omega.norm(), 0.0);
        }
    }
}

// (b) Hertz.

/// Two unequal spheres of glass-like surfaces (restitution e each) meeting head on along a slant
/// line at relative speed v; returns the pair's measured restitution and the collision.
struct HertzPair {
    double restitution;
    Collision collision;
    double effective_mass;
};

HertzPair hertz_pair(double e, double v, int per_collision)
{
    const double r1 = 0.05;
    const double r2 = 0.03;
    const Vec<3> n = Vec<3>(-4.0, 4.0, 7.0) / 9.0;
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>::Constant(0.4), 0.25 * v * n, r1, density, surface(0.0, 0.0, e)),
        test::ball<3>(Vec<3>::Constant(0.4) + (r1 + r2 + 1e-12) * n, -0.75 * v * n, r2, 7800.0,
                      surface(0.0, 0.0, e))};
    const double mass = 1.0 / (1.0 / bodies[0].mass() + 1.0 / bodies[1].mass());
    const double radius = r1 * r2 / (r1 + r2);
    const double modulus = 1e8 / (2.0 * (1.0 - 0.25 * 0.25)); // E* of two equal surfaces
    // Johnson's duration sets the sub-step.
    const double johnson = 2.87 * std::pow(mass * mass / (radius * modulus * modulus * v), 0.2);
    const Collision c =
        collide(bodies, open_box(), HertzMindlin{}, johnson / per_collision, 20L * per_collision,
                [](const auto& b) { return -overlap(b[0], b[1]); });
    return {(bodies[1].velocity - bodies[0].velocity).dot(n) / v, c, mass};
}

TEST(SphereContacts, HertzPairLastsJohnsonsDurationWithJohnsonsPeakForce)
{
    const double v = 2.0;
    const HertzPair p = hertz_pair(1.0, v, 2000);
    const double radius = 0.05 * 0.03 / 0.08; // R* = R₁R₂/(R₁ + R₂) = 0.01875 m
    const double modulus = 1e8 / (2.0 * (1.0 - 0.25 * 0.25));
    const double m = p.effective_mass;
    // Johnson (1985), §11.1: t_c = 2.87 (m*²/(R* E*² v))^{1/5};
    // α_max = (15 m* v²/(16 E* √R*))^{2/5}, F_max = (4/3) E* √R* α_max^{3/2}.
    const double duration = 2.87 * std::pow(m * m / (radius * modulus * modulus * v), 0.2);
    const double deepest = std::pow(15.0 * m * v * v / (16.0 * modulus * std::sqrt(radius)), 0.4);
    const double peak = 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(deepest, 1.5);
    std::printf("Hertz pair at %g m/s: t_c = %.6g s (Johnson %.6g s), F_max = %.6g N "
                "(Johnson %.6g N), e = %.6f\n",
                v, p.collision.duration, duration, p.collision.peak_force, peak, p.restitution);
    // 2.87 is Johnson's rounding of 2.868 (hertz_mindlin.hpp): 7e-4; the duration is counted in
    // sub-steps of t_c/2000.
    EXPECT_NEAR(p.collision.duration / duration, 1.0, 2e-3);
    EXPECT_NEAR(p.collision.peak_force / peak, 1.0, 1e-4);
    EXPECT_NEAR(p.restitution, 1.0, 1e-5);
}

TEST(SphereContacts, HertzPairReboundsWithThePairRestitutionAtAnySpeed)
{
    for (const double e : {0.9, 0.5}) {
        for (const double v : {0.1, 3.0}) {
            const HertzPair p = hertz_pair(e, v, 500);
            std::printf("Hertz pair e = %.1f at %g m/s: measured %.5f\n", e, v, p.restitution);
            // Tsuji's form with A = √5 ζ (Antypov & Elliott 2011): e at any speed; 0.5 %
            // for the explicit dashpot at 500 sub-steps per collision.
            EXPECT_NEAR(p.restitution / e, 1.0, 5e-3) << "e = " << e << ", v = " << v;
        }
    }
}

// (c) Oblique impact on a wall.

/// A sphere without spin hits the floor z = 0 at normal speed v_n and tangential velocity
/// v_t t̂ (t̂ in the floor); the linear model with k, c for restitution e and κ = 2/7.
struct Oblique {
    Vec<3> velocity;
    Vec<3> omega;
    double radius;
};

Oblique oblique_impact(double mu, double e, double v_n, const Vec<3>& tangential)
{
    const double r = 0.05;
    const Material m = surface(mu, 0.0, e);
    std::vector<Particle<3>> bodies{test::ball<3>(
        Vec<3>(0.5, 0.5, r + 1e-12), tangential - v_n * Vec<3>::UnitZ(), r, density, m)};
    const double mass = bodies[0].mass();
    // Stiff (t_c = 0.2 ms: α_max = 6e-5 m at 1 m/s), so that the lever arm of the friction
    // force, R − α/2 (contact_geometry.hpp), is R within 1e-3 and the rigid-sphere impulse
    // relations below hold to that accuracy.
    const auto params = LinearSpringDashpot::from_restitution(e, 2e-4, mass);
    DemWalls<3> floor = test::box<3>(Vec<3>::Constant(1.0), {false, false, true}, m);
    (void)collide(bodies, floor, LinearSpringDashpot(params, mass), 2e-7, 10000,
                  [r](const auto& b) { return b[0].centre.z() - r; });
    return {bodies[0].velocity, bodies[0].omega, r};
}

TEST(SphereContacts, ObliqueWallImpactAtSmallIncidenceSticksAndReversesTheContactPointSlip)
{
    // Undamped, κ = 2/7: the contact point's tangential motion (effective mass 2m/7 for a solid
    // sphere, stiffness κk) has the period of the normal one, and F_t/F_n = κ v_t/v_n stays
    // constant: below μ the contact sticks throughout and the slip comes back reversed,
    // v_t' = (3/7) v_t, |ω'| = (10/7) v_t/R about ẑ × t̂ (Maw, Barber & Fawcett 1976: the
    // small-incidence regime, here with its exact linear-model answer).
    const Vec<3> t = Vec<3>(0.6, 0.8, 0.0);
    const double v_t = 0.5;
    const Oblique o = oblique_impact(0.5, 1.0, 1.0, v_t * t); // κ v_t/v_n = 0.14 < μ
    const Vec<3> slip = o.velocity + o.omega.cross(Vec<3>(0.0, 0.0, -o.radius));
    const Vec<3> slip_t(slip.x(), slip.y(), 0.0);
    std::printf("oblique impact, small incidence: slip after / before = %.5f, v_t'/v_t = %.5f "
                "(3/7 = %.5f), |ω'| R/v_t = %.5f (10/7 = %.5f)\n",
                slip_t.dot(t) / v_t, o.velocity.dot(t) / v_t, 3.0 / 7.0,
                o.omega.norm() * o.radius / v_t, 10.0 / 7.0);
    EXPECT_NEAR(slip_t.dot(t) / v_t, -1.0, 2e-3);
    EXPECT_NEAR(o.velocity.dot(t) / v_t, 3.0 / 7.0, 1e-3);
    EXPECT_NEAR((o.omega - 10.0 / 7.0 * v_t / o.radius * Vec<3>::UnitZ().cross(t)).norm() *
                    o.radius / v_t,
                0.0, 2e-3);
    EXPECT_NEAR(o.velocity.z(), 1.0, 1e-3);
}

/// ∫ max(F_n, 0) dt / (m v) of a linear spring–dashpot collision of restitution e at approach
/// speed v: the impulse of the repulsive phase. With α = (v/ω_d) e^{−ζω₀t} sin ω_d t, F_n = −mα̈
/// turns attractive where α̈ = 0, at ω_d t* = π − 2 atan s, s = ζ/√(1 − ζ²) = −ln e/π; the
/// rebound speed is largest there, v e^{−s ω_d t*} = e v exp(2 s atan s), and the repulsive
/// impulse m(v + that). 1 + e for e = 1; 1.0202 (1 + e) at e = 0.6.
double repulsive_impulse(double e)
{
    const double s = -std::log(e) / pi;
    return 1.0 + e * std::exp(2.0 * s * std::atan(s));
}

TEST(SphereContacts, ObliqueWallImpactAtLargeIncidenceSlidesWithTheCoulombImpulse)
{
    // Gross sliding throughout (slip v_t > (7/2) μ (1 + e) v_n): the tangential impulse is μ
    // times the normal one, m(1 + e)v_n, so v_t' = v_t − μ(1 + e)v_n and ω' = 5μ(1 + e)v_n/(2R)
    // about ẑ × t̂ (solid sphere, J = (2/5) m R²). That holds exactly for e = 1. With damping the
    // linear model's normal force is attractive at the end of the contact (F_n = kα + cα̇ is not
    // clipped, so that e is the analytic one), which friction, limited by μ max(F_n, 0), does not
    // see: the tangential impulse is then μ times the repulsive impulse (repulsive_impulse), 2 %
    // above μ(1 + e) m v_n at e = 0.6.
    const Vec<3> t = Vec<3>(-0.28, 0.96, 0.0);
    const double mu = 0.1;
    const double v_t = 2.0;
    for (const double e : {1.0, 0.6}) {
        const Oblique o = oblique_impact(mu, e, 1.0, v_t * t);
        const double impulse = mu * repulsive_impulse(e); // per unit mass and v_n
        const double spin = 2.5 * impulse / o.radius;
        std::printf("oblique impact, large incidence, e = %.1f: e_n = %.5f, v_t' = %.5f m/s "
                    "(model %.5f, rigid Coulomb %.5f), |ω'| = %.5f rad/s (model %.5f, rigid "
                    "Coulomb 5μ(1 + e)v_n/(2R) = %.5f)\n",
                    e, o.velocity.z(), o.velocity.dot(t), v_t - impulse, v_t - mu * (1.0 + e),
                    o.omega.norm(), spin, 2.5 * mu * (1.0 + e) / o.radius);
        // 1e-3: the lever arm R − α/2 (see oblique_impact) and the sub-steps.
        EXPECT_NEAR((o.omega - spin * Vec<3>::UnitZ().cross(t)).norm() / spin, 0.0, 1e-3)
            << "e = " << e;
        EXPECT_NEAR((v_t - o.velocity.dot(t)) / impulse, 1.0, 1e-3) << "e = " << e;
        EXPECT_NEAR(o.velocity.z() / e, 1.0, 2e-3);
        EXPECT_NEAR(o.velocity.cross(t).z(), 0.0, 1e-12); // no turn aside
    }
}

TEST(SphereContacts, ObliquePairImpactSlidesWithTheCoulombImpulseInAnyOrientation)
{
    // Two unequal spheres without spin meet along n with approach speed v_n = 1 m/s and slip
    // v_t = 2 m/s along t̂ ⟂ n; gross sliding throughout (v_t > (7/2) μ (1 + e) v_n), e = 1. The
    // normal impulse is J_n = m*(1 + e)v_n and the friction impulse μ J_n against the slip, so
    // each sphere's velocity across n changes by μ J_n/m_i and it spins up to
    // ω_i = μ J_n R_i/J_i = (5/2) μ J_n/(m_i R_i), both about n × t̂.
    std::mt19937 rng(76);
    const double mu = 0.1;
    const Material m = surface(mu, 0.0, 1.0);
    for (int trial = 0; trial < 3; ++trial) {
        const Eigen::Matrix3d q = random_rotation(rng);
        const Vec<3> n = q * Vec<3>::UnitX();
        const Vec<3> t = q * Vec<3>::UnitY();
        std::vector<Particle<3>> bodies{
            test::ball<3>(Vec<3>::Constant(0.4), 0.5 * n - 1.0 * t, 0.05, density, m),
            test::ball<3>(Vec<3>::Constant(0.4) + (0.08 + 1e-12) * n, -0.5 * n + 1.0 * t, 0.03,
                          7800.0, m)};
        const double mass = 1.0 / (1.0 / bodies[0].mass() + 1.0 / bodies[1].mass());
        // The rigid-body answer is for an instant impact. During a contact of duration t_c the
        // line of centres turns by about v_t t_c/(R₁ + R₂), which tips part of the normal
        // impulse into t̂ (measured 2.9 % of the friction impulse at t_c = 0.2 ms, μ = 0.1);
        // t_c = 5 µs keeps that, and the lever arms R_i − α/2, within 1e-3.
        const auto params = LinearSpringDashpot::from_restitution(1.0, 5e-6, mass);
        (void)collide(bodies, open_box(), LinearSpringDashpot(params, mass), 5e-9, 20000,
                      [](const auto& b) { return -overlap(b[0], b[1]); });
        const double impulse = mu * mass * 2.0; // μ J_n, v_n = 1
        double worst = 0.0;
        for (std::size_t k = 0; k < 2; ++k) {
            const Particle<3>& b = bodies[k];
            const double sign = k == 0 ? 1.0 : -1.0; // the friction on the first is along +t̂
            const double slip_change =
                (b.velocity.dot(t) - sign * -1.0) / (sign * impulse / b.mass());
            const Vec<3> spin = 2.5 * impulse / (b.mass() * b.radius()) * n.cross(t);
            worst = std::max(
                {worst, std::abs(slip_change - 1.0), (b.omega - spin).norm() / spin.norm()});
        }
        std::printf("oblique pair impact, rotation %d: velocity change and spin within %.1e of "
                    "the Coulomb impulse; v_n' = %.5f m/s (e v_n = 1)\n",
                    trial, worst, (bodies[1].velocity - bodies[0].velocity).dot(n));
        EXPECT_LT(worst, 2e-3) << "rotation " << trial;
        EXPECT_NEAR((bodies[1].velocity - bodies[0].velocity).dot(n), 1.0, 1e-3);
    }
}

// (d) Rolling resistance.

TEST(SphereContacts, SphereRollingAlongADiagonalDeceleratesAtTheRollingTorqueRate)
{
    // Rolling without slip, the constant torque μ_r R m g against ω: (J/R + m R) dv/dt =
    // −μ_r R m g, i.e. dv/dt = −(5/7) μ_r g for a solid sphere (R* = R on a wall).
    const double r = 0.05;
    const double g = 9.81;
    const double mu_r = 0.05;
    const Material m = surface(0.4, mu_r, 0.5);
    const Vec<3> t = Vec<3>(0.6, -0.8, 0.0);
    const double v0 = 1.0;
    const double twist = 5.0; // [rad/s]
    for (const auto& [name, model] : std::vector<std::pair<const char*, AnyContactModel>>{
             {"hertz_mindlin", HertzMindlin{}},
             {"linear", LinearSpringDashpot({1e7, 0.4 * std::sqrt(1e7 * 1.309)}, 1.309)}}) {
        std::vector<Particle<3>> bodies{test::ball<3>(Vec<3>(0.2, 3.0, r), v0 * t, r, density, m)};
        Particle<3>& b = bodies[0];
        // v + ω × (−R ẑ) = 0, and a twist about the normal, which the rolling torque must
        // leave alone (rolling_part in tangential_contact.cpp; there is no twisting resistance).
        b.omega = Vec<3>::UnitZ().cross(t) * (v0 / r) + twist * Vec<3>::UnitZ();
        b.contact.steady_force = -b.mass() * g * Vec<3>::UnitZ();
        // Start at the static overlap F_n(α) = m g.
        const ContactPair pair =
            make_contact_pair(ball_side(b.mass(), b.inertia(), r, m, true), wall_side(m));
        b.centre.z() -= test::static_overlap(model, pair, b.mass() * g, 0.01 * r);
        const DemWalls<3> floor = test::box<3>(Vec<3>(4.0, 4.0, 1.0), {false, false, true}, m);
        const double step = 2e-5;
        std::vector<double> speeds;
        ContactHistory<3> history;
        long n = 0;
        test::run_substeps<3>(bodies, floor, DemSettings{model, 0.0, 1}, step, 30000, history,
                              [&](const auto& now, const auto&) {
                                  if (++n % 5000 == 0) { // every 0.1 s
                                      speeds.push_back(now[0].velocity.dot(t));
                                  }
                                  return true;
                              });
        // v(0.1 s) → v(0.6 s): from the first sample, after the spring's start-up oscillation.
        const double rate = (speeds.front() - speeds.back()) / 0.5;
        const double analytic = 5.0 / 7.0 * mu_r * g;
        std::printf("%s: rolling deceleration %.5f m/s² (5/7 μ_r g = %.5f), speed across %.1e, "
                    "twist %.6f rad/s (5 at the start)\n",
                    name, rate, analytic, b.velocity.cross(t).norm(), b.omega.dot(Vec<3>::UnitZ()));
        EXPECT_NEAR(rate / analytic, 1.0, 1e-3) << name;
        EXPECT_LT(b.velocity.cross(t).norm(), 1e-9) << name;            // rolls straight on
        EXPECT_NEAR(b.omega.dot(Vec<3>::UnitZ()), twist, 1e-9) << name; // the twist is kept
        // Still rolling without slip.
        EXPECT_LT((b.velocity + b.omega.cross(Vec<3>(0.0, 0.0, -r))).norm(), 1e-3 * v0) << name;
    }
}

// (e) and (f): frictional pairs.

/// Two spinning spheres of unequal size and density meeting off centre, with friction and
/// rolling resistance: the contact slides, sticks and rolls.
std::vector<Particle<3>> spinning_pair(const Material& m)
{
    std::vector<Particle<3>> bodies{
        test::ball<3>(Vec<3>(0.45, 0.47, 0.5), Vec<3>(2.0, 0.3, -0.1), 0.05, 2500.0, m),
        test::ball<3>(Vec<3>(0.56, 0.5, 0.52), Vec<3>(-1.0, -0.2, 0.3), 0.04, 5000.0, m)};
    bodies[0].omega = Vec<3>(10.0, -20.0, 30.0);
    bodies[1].omega = Vec<3>(-40.0, 0.0, -50.0);
    return bodies;
}

/// Σ m (x − o) × v + J ω about o.
Vec<3> angular_momentum(const std::vector<Particle<3>>& bodies, const Vec<3>& o)
{
    Vec<3> total = Vec<3>::Zero();
    for (const Particle<3>& b : bodies) {
        total += b.mass() * (b.centre - o).cross(b.velocity) + b.inertia() * b.omega;
    }
    return total;
}

Vec<3> linear_momentum(const std::vector<Particle<3>>& bodies)
{
    return bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
}

/// The two contact models with the pair's surface.
std::vector<std::pair<const char*, AnyContactModel>> models()
{
    const double mass = 2500.0 * Ball<3>{0.1}.volume();
    return {{"hertz_mindlin", HertzMindlin{}},
            {"linear", LinearSpringDashpot({1e6, 0.2 * std::sqrt(1e6 * mass)}, 0.5 * mass)}};
}

/// Runs the pair `bodies` until they have touched and are 0.02 m apart again.
void run_pair(std::vector<Particle<3>>& bodies, const AnyContactModel& model, double step)
{
    ContactHistory<3> history;
    bool has_touched = false;
    test::run_substeps<3>(bodies, open_box(), DemSettings{model, 0.0, 1}, step, 100000, history,
                          [&](const auto& b, const auto&) {
                              has_touched = has_touched || overlap(b[0], b[1]) > 0.0;
                              return !has_touched || overlap(b[0], b[1]) > -0.02;
                          });
    ASSERT_TRUE(has_touched);
}

TEST(SphereContacts, AFrictionalCollisionNeverGainsKineticEnergy)
{
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double largest_gain = -1.0;
    for (const auto& [name, model] : models()) {
        for (int trial = 0; trial < 20; ++trial) {
            // e = 1 in half the trials: friction and rolling resistance alone must not create
            // energy (the Hertz–Mindlin spring's stiffness changes with α under load).
            const Material m = surface(0.1 + 0.4 * std::abs(u(rng)), 0.05 * std::abs(u(rng)),
                                       trial % 2 == 0 ? 1.0 : 0.7);
            std::vector<Particle<3>> bodies = spinning_pair(m);
            bodies[1].centre += 0.04 * Vec<3>(0.0, u(rng), u(rng));
            for (Particle<3>& b : bodies) {
                b.omega = 40.0 * Vec<3>(u(rng), u(rng), u(rng));
            }
            const double before = kinetic_energy(bodies);
            run_pair(bodies, model, 2e-6);
            const double gain = kinetic_energy(bodies) / before - 1.0;
            largest_gain = std::max(largest_gain, gain);
            EXPECT_LE(gain, 1e-4) << name << " trial " << trial;
        }
    }
    std::printf("frictional collisions: largest kinetic energy after/before − 1 = %.2e\n",
                largest_gain);
}

TEST(SphereContacts, FrictionalCollisionIsRotationInvariantAndConservesMomentum)
{
    const Material rough = surface(0.4, 0.05, 0.7);
    const Vec<3> centre = Vec<3>::Constant(0.5); // the rotations turn the setup about it
    std::mt19937 rng(2026);
    for (const auto& [name, model] : models()) {
        std::vector<Particle<3>> reference = spinning_pair(rough);
        run_pair(reference, model, 2e-6);
        double worst_position = 0.0;
        double worst_velocity = 0.0;
        double worst_momentum = 0.0;
        for (int trial = 0; trial < 5; ++trial) {
            const Eigen::Matrix3d q = random_rotation(rng);
            std::vector<Particle<3>> bodies = spinning_pair(rough);
            for (Particle<3>& b : bodies) {
                b.centre = centre + q * (b.centre - centre);
                b.velocity = q * b.velocity;
                b.omega = q * b.omega; // a pseudovector: the same for a proper rotation
            }
            const Vec<3> p0 = linear_momentum(bodies);
            const Vec<3> l0 = angular_momentum(bodies, Vec<3>::Constant(-1.0));
            run_pair(bodies, model, 2e-6);
            const double scale = bodies[0].mass() * 2.0; // m v
            worst_momentum =
                std::max({worst_momentum, (linear_momentum(bodies) - p0).norm() / scale,
                          (angular_momentum(bodies, Vec<3>::Constant(-1.0)) - l0).norm() / scale});
            for (std::size_t k = 0; k < 2; ++k) {
                const Particle<3>& a = reference[k];
                const Particle<3>& b = bodies[k];
                worst_position = std::max(worst_position,
                                          (b.centre - (centre + q * (a.centre - centre))).norm());
                worst_velocity = std::max({worst_velocity, (b.velocity - q * a.velocity).norm(),
                                           (b.omega - q * a.omega).norm() * a.radius()});
            }
        }
        std::printf("%s: rotated collision vs rotated answer: |Δx| ≤ %.1e m, |Δv|, |Δω| R ≤ "
                    "%.1e m/s; |Δp|, |ΔL| / (m v) ≤ %.1e\n",
                    name, worst_position, worst_velocity, worst_momentum);
        // The spins changed by friction (the test can tell a wrong torque).
        EXPECT_GT((reference[0].omega - Vec<3>(10.0, -20.0, 30.0)).norm(), 1.0) << name;
        // Round-off over ~1e4 sub-steps (an axis-dependent term would show at O(1)).
        EXPECT_LT(worst_position, 1e-11) << name;
        EXPECT_LT(worst_velocity, 1e-9) << name;
        EXPECT_LT(worst_momentum, 1e-11) << name;
    }
}

} // namespace
} // namespace fddem
