// SPDX-License-Identifier: MIT
// DEM sub-steps (contact/dem_step.hpp) against the analytic spring–dashpot collision: dry
// normal collisions with walls and between bodies give the restitution coefficient
// exp(−ζπ/√(1−ζ²)) within 1 %, conserve kinetic energy with c = 0 and β = 0 within 0.1 %,
// conserve linear momentum to round-off, and nothing tunnels at twice the fastest impact of
// the paper's cases. With friction and rolling resistance, a collision conserves linear and
// angular momentum to round-off (both models, 2D and 3D), the tangential springs persist
// across time steps (static friction holds a body still) and are dropped when contacts open.

#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/dem_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;

Particle<2> disk(const Vec<2>& centre, const Vec<2>& velocity, double radius = 0.125,
                 double density = 1.25)
{
    return test::ball<2>(centre, velocity, radius, density);
}

const DemWalls<2> box{Vec<2>(0.0, 0.0), Vec<2>(2.0, 6.0), {true, true}};

/// The paper's frictionless linear model with k and c as given, checked for effective mass
/// `mass` [kg] (not overdamped).
DemSettings linear(const LinearSpringDashpot::Params& law, int substeps, double mass)
{
    return {LinearSpringDashpot(law, mass), 0.0, substeps};
}

/// Runs whole fluid steps of `dt` until `done` or `max_steps`; returns the steps taken and the
/// largest relative overlap.
template <class Done>
double run(std::vector<Particle<2>>& bodies, const DemSettings& settings, double dt, int max_steps,
           Done done)
{
    CellList<2> cells(box.origin, box.length, 0.25);
    ContactHistory<2> history;
    double overlap = 0.0;
    for (int s = 0; s < max_steps && !done(bodies); ++s) {
        overlap = std::max(
            overlap,
            test::step_dem<2>(bodies, box, settings, dt, cells, history).max_relative_overlap);
    }
    return overlap;
}

TEST(ContactGeometry, OverlapRateAndSlipOfTwoDisksAndAWall)
{
    const BallState<2> a{Vec<2>(0.0, 0.0), 0.5, Vec<2>(1.0, 0.0), 2.0};
    const BallState<2> b{Vec<2>(0.9, 0.0), 0.5, Vec<2>(-1.0, 0.0), 0.0};
    const ContactGeometry<2> g = ball_ball_contact(a, b);
    EXPECT_NEAR(g.overlap, 0.1, 1e-15);
    EXPECT_NEAR(g.overlap_rate, 2.0, 1e-15); // approaching at 2
    EXPECT_NEAR(g.normal.x(), 1.0, 1e-15);
    // a spins at 2 about z: its contact point, the middle of the overlap (0.45, 0), moves at
    // (0, 0.9); b's slides by −0.9 in y relative to it.
    EXPECT_NEAR(g.slip_velocity.y(), -0.9, 1e-15);
    const BallState<2> c{Vec<2>(1.0, 0.1), 0.125, Vec<2>(0.0, -3.0), 0.0};
    const ContactGeometry<2> floor = ball_wall_contact(c, 1, 0, 0.0);
    EXPECT_NEAR(floor.overlap, 0.025, 1e-15);
    EXPECT_NEAR(floor.overlap_rate, 3.0, 1e-15);
    EXPECT_NEAR(floor.normal.y(), -1.0, 1e-15);
    const ContactGeometry<2> top = ball_wall_contact(c, 1, 1, 6.0);
    EXPECT_LT(top.overlap, 0.0);
}

TEST(DemStep, WallCollisionGivesTheAnalyticRestitution)
{
    for (const double e : {0.5, 0.8, 1.0}) {
        std::vector<Particle<2>> bodies{disk(Vec<2>(1.0, 0.126), Vec<2>(0.0, -5.0))};
        const double t_c = 2.5e-4;
        const auto law = LinearSpringDashpot::from_restitution(e, t_c, bodies[0].mass());
        const double dt = 0.005;
        const DemSettings settings =
            linear(law, static_cast<int>(std::ceil(100.0 * dt / t_c)), bodies[0].mass());
        run(bodies, settings, dt, 4, [](const auto&) { return false; });
        EXPECT_NEAR(bodies[0].velocity.y() / 5.0, e, 0.01 * e) << "e = " << e;
        EXPECT_GT(bodies[0].centre.y(), 0.125); // left the floor again
        EXPECT_NEAR(bodies[0].velocity.x(), 0.0, 1e-15);
    }
}

TEST(DemStep, HeldFluidForceActsWhileApartAndNotWhileTouching)
{
    // contact.fluid_force = "held" (docs/method.md §5, Coupling): the resolved force of the step
    // before acts on a body the DEM moves while it touches nothing, and not while it touches.
    const auto law = LinearSpringDashpot::from_restitution(
        0.8, 2.5e-4, disk(Vec<2>::Zero(), Vec<2>::Zero()).mass());
    const double dt = 1e-4;
    DemSettings settings = linear(law, 20, disk(Vec<2>::Zero(), Vec<2>::Zero()).mass());
    settings.margin = 0.05; // apart but within the margin: the DEM moves it (has_contact)
    const Vec<2> held(0.3, 2.0);
    const Vec<2> weight(0.0, -1.0);
    // Apart: 0.02 above the floor, slow, never touching within the step.
    std::vector<Particle<2>> apart{disk(Vec<2>(1.0, 0.145), Vec<2>(0.0, -0.1))};
    apart[0].contact.steady_force = weight;
    apart[0].contact.held_fluid_force = held;
    CellList<2> cells(box.origin, box.length, 0.5);
    ContactHistory<2> history;
    (void)advance_contacts<2>(apart, box, settings, dt, cells, history);
    const Particle<2>& a = apart[0];
    EXPECT_TRUE(a.contact.is_in_contact);
    const Vec<2> expected = a.velocity + (held + weight) * dt / a.mass();
    EXPECT_NEAR((a.contact.velocity - expected).norm(), 0.0, 1e-14);
    // Touching through the whole step (just touched, moving in; the step is 0.4 of the
    // collision): the same end state with and without the held force.
    const auto touching = [&](const Vec<2>& fluid) {
        std::vector<Particle<2>> bodies{disk(Vec<2>(1.0, 0.125 - 1e-6), Vec<2>(0.0, -0.5))};
        bodies[0].contact.steady_force = weight;
        bodies[0].contact.held_fluid_force = fluid;
        ContactHistory<2> fresh;
        (void)advance_contacts<2>(bodies, box, settings, dt, cells, fresh);
        EXPECT_LT(bodies[0].contact.centre.y(), 0.125); // still overlapping at the end
        return bodies[0].contact.velocity;
    };
    EXPECT_EQ((touching(held) - touching(Vec<2>::Zero())).norm(), 0.0);
}

TEST(DemStep, HeldFluidForceActsInContactWhenAlways)
{
    // contact.fluid_force = "always" (docs/method.md §5, "A fluid force in an enduring
    // contact"): the held force acts also while the body touches. Two disks that touch through
    // the whole step: the contact forces are equal and opposite, so the pair's momentum changes
    // by exactly the sum of the forces outside the contact over Δt, with the held forces under
    // "always" and without them (the buoyant weights only) under "held".
    // about a ninth of the pair's collision (t_c/√2 at half the mass): it touches throughout
    const double dt = 2e-5;
    const auto momentum_change = [&](bool is_held_in_contact) {
        std::vector<Particle<2>> bodies{disk(Vec<2>(1.0, 3.0), Vec<2>::Zero()),
                                        disk(Vec<2>(1.0, 3.25 - 1e-6), Vec<2>::Zero(), 0.125)};
        const auto law = LinearSpringDashpot::from_restitution(0.8, 2.5e-4, bodies[0].mass());
        DemSettings settings = linear(law, 20, 0.5 * bodies[0].mass());
        settings.is_fluid_force_held_in_contact = is_held_in_contact;
        bodies[0].contact.held_fluid_force = Vec<2>(0.3, 2.0);
        bodies[1].contact.held_fluid_force = Vec<2>(-0.1, 0.5);
        for (Particle<2>& body : bodies) {
            body.contact.steady_force = Vec<2>(0.0, -1.0);
        }
        CellList<2> cells(box.origin, box.length, 0.5);
        ContactHistory<2> history;
        (void)advance_contacts<2>(bodies, box, settings, dt, cells, history);
        EXPECT_LT((bodies[1].contact.centre - bodies[0].contact.centre).norm(), 0.25);
        return Vec<2>(bodies[0].mass() * bodies[0].contact.velocity +
                      bodies[1].mass() * bodies[1].contact.velocity);
    };
    const Vec<2> always = momentum_change(true);
    const Vec<2> touching_nothing = momentum_change(false);
    EXPECT_NEAR((always - Vec<2>(0.2, 0.5) * dt).norm(), 0.0, 1e-15);
    EXPECT_NEAR((touching_nothing - Vec<2>(0.0, -2.0) * dt).norm(), 0.0, 1e-15);
}

TEST(DemStep, AutomaticFluidForceIsHeldOnlyWithLubrication)
{
    // contact.fluid_force: "auto" (the default) holds the resolved force with lubrication on
    // and leaves it out without, as the paper; the explicit choices ignore lubrication.
    using enum ContactFluidForce;
    static_assert(held_fluid_force_applies(automatic, true));
    static_assert(!held_fluid_force_applies(automatic, false));
    static_assert(held_fluid_force_applies(held, false) && held_fluid_force_applies(held, true));
    static_assert(!held_fluid_force_applies(none, true) && !held_fluid_force_applies(none, false));
    static_assert(held_fluid_force_applies(always, false) &&
                  held_fluid_force_acts_in_contact(always));
    static_assert(!held_fluid_force_acts_in_contact(held) &&
                  !held_fluid_force_acts_in_contact(automatic));
    EXPECT_TRUE(held_fluid_force_applies(automatic, true));
}

TEST(DemStep, PairCollisionConservesMomentumAndGivesTheRestitution)
{
    const double e = 0.7;
    // Unequal disks, head on along a slant line.
    std::vector<Particle<2>> bodies{disk(Vec<2>(0.8, 3.0), Vec<2>(2.0, 1.0)),
                                    disk(Vec<2>(1.2, 3.2), Vec<2>(-1.0, -0.5), 0.1, 2.0)};
    const Vec<2> momentum =
        bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
    const double reduced =
        bodies[0].mass() * bodies[1].mass() / (bodies[0].mass() + bodies[1].mass());
    const auto law = LinearSpringDashpot::from_restitution(e, 1e-3, reduced);
    const Vec<2> n = (bodies[1].centre - bodies[0].centre).normalized();
    const double approach = (bodies[0].velocity - bodies[1].velocity).dot(n);
    const double dt = 0.005;
    const DemSettings settings = linear(law, 250, reduced); // 50 sub-steps per collision
    run(bodies, settings, dt, 60, [](const auto&) { return false; });
    const Vec<2> after =
        bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
    EXPECT_NEAR((after - momentum).norm(), 0.0, 1e-14 * momentum.norm());
    const double separation = (bodies[1].velocity - bodies[0].velocity).dot(n);
    EXPECT_NEAR(separation / approach, e, 0.01 * e);
}

TEST(ContactGeometry, APairAcrossAPeriodicSideHasTheNormalAndOverlapOfTheSamePairInside)
{
    const PeriodicDomain<2> channel{Vec<2>::Zero(), Vec<2>(2.0, 6.0), {true, false}};
    // The same two disks, 0.45 apart in x: inside the box, and with the seam between them.
    const BallState<2> a{Vec<2>(0.75, 3.0), 0.25, Vec<2>(1.0, 0.5), 2.0};
    const BallState<2> b{Vec<2>(1.2, 3.1), 0.25, Vec<2>(-1.0, 0.0), -1.0};
    BallState<2> a_seam = a;
    BallState<2> b_seam = b;
    a_seam.centre.x() = 1.75; // 0.25 from the right side
    b_seam.centre.x() = 0.2;  // 0.2 from the left side
    const ContactGeometry<2> inside = ball_ball_contact(a, b);
    const ContactGeometry<2> seam = ball_ball_contact(a_seam, b_seam, channel);
    EXPECT_GT(inside.overlap, 0.0);
    EXPECT_NEAR(seam.overlap, inside.overlap, 1e-15);
    EXPECT_NEAR((seam.normal - inside.normal).norm(), 0.0, 1e-15); // +x, across the seam
    EXPECT_NEAR(seam.overlap_rate, inside.overlap_rate, 1e-14);
    EXPECT_NEAR((seam.slip_velocity - inside.slip_velocity).norm(), 0.0, 1e-14);
    EXPECT_NEAR((seam.lever_first - inside.lever_first).norm(), 0.0, 1e-15);
    // Without the nearest image the two would be 1.55 apart: no contact.
    EXPECT_LT(ball_ball_contact(a_seam, b_seam).overlap, 0.0);
}

TEST(DemStep, ACollisionAcrossAPeriodicSideIsTheCollisionInside)
{
    const double e = 0.7;
    // The pair of PairCollisionConservesMomentumAndGivesTheRestitution, in a box periodic along
    // x: once in the middle, once moved by 0.9 so that the seam x = 0 ≡ 2 lies between them.
    const std::vector<Particle<2>> inside_start{
        disk(Vec<2>(0.8, 3.0), Vec<2>(2.0, 1.0)),
        disk(Vec<2>(1.2, 3.2), Vec<2>(-1.0, -0.5), 0.1, 2.0)};
    std::vector<Particle<2>> seam = inside_start;
    seam[0].centre.x() = 1.7;
    seam[1].centre.x() = 0.1;
    std::vector<Particle<2>> inside = inside_start;
    const double reduced = seam[0].mass() * seam[1].mass() / (seam[0].mass() + seam[1].mass());
    const DemSettings settings =
        linear(LinearSpringDashpot::from_restitution(e, 1e-3, reduced), 250, reduced);
    const PeriodicDomain<2> channel{box.origin, box.length, {true, false}};
    const DemWalls<2> walls{box.origin, box.length, {false, true}};
    for (auto* bodies : {&inside, &seam}) {
        CellList<2> cells(channel, 0.25);
        ContactHistory<2> history;
        for (int s = 0; s < 60; ++s) {
            static_cast<void>(test::step_dem<2>(*bodies, walls, settings, 0.005, cells, history));
        }
    }
    EXPECT_GT(inside[1].velocity.x(), 0.0); // they collided
    for (std::size_t b = 0; b < 2; ++b) {
        // As inside, to round-off: the centres moved by 0.9 differ from those inside by their
        // rounding (1e-16), which 15 000 sub-steps of a stiff spring amplify to about 1e-12
        // (measured 2.6e-12 in speed); a contact missed or misplaced would differ by O(1).
        EXPECT_NEAR((seam[b].velocity - inside[b].velocity).norm(), 0.0, 1e-10) << b;
        const Vec<2> moved = channel.minimum_image(seam[b].centre - inside[b].centre);
        EXPECT_NEAR((moved - Vec<2>(0.9, 0.0)).norm(), 0.0, 1e-10) << b;
    }
}

TEST(DemStep, ElasticCollisionConservesKineticEnergy)
{
    std::vector<Particle<2>> bodies{disk(Vec<2>(0.7, 3.0), Vec<2>(3.0, 0.4)),
                                    disk(Vec<2>(1.3, 3.05), Vec<2>(-2.0, 0.0))};
    const auto energy = [&] {
        double k = 0.0;
        for (const auto& b : bodies) {
            k += 0.5 * b.mass() * b.velocity.squaredNorm();
        }
        return k;
    };
    const double before = energy();
    const DemSettings settings = linear({1e6, 0.0}, 400, bodies[0].mass());
    run(bodies, settings, 0.005, 40, [](const auto&) { return false; });
    EXPECT_GT(bodies[1].velocity.x(), 0.0); // they did collide
    EXPECT_NEAR(energy(), before, 1e-3 * before);
}

TEST(DemStep, NoTunnellingAtTwiceTheFastestImpactOfThePaperCases)
{
    // The Fig. 5 disk (k = 1e7, c = 0, the case's automatic sub-steps) thrown at the floor at
    // 22 cm/s, twice the fastest impact the paper's cases reach (about 11 cm/s), under gravity.
    std::vector<Particle<2>> bodies{disk(Vec<2>(1.0, 0.2), Vec<2>(0.0, -22.0))};
    bodies[0].contact.steady_force = Vec<2>(0.0, -(1.25 - 1.0) * pi * 0.125 * 0.125 * 980.0);
    const DemSettings settings = linear({1e7, 0.0}, 1150, bodies[0].mass());
    const double overlap = run(bodies, settings, 0.005, 10, [](const auto&) { return false; });
    EXPECT_GT(overlap, 0.0);
    EXPECT_LT(overlap, 0.02); // 22 √(m/k) / r = 1.4 %
    EXPECT_GT(bodies[0].centre.y(), 0.125);
}

TEST(DemStep, BodiesWithinTheMarginCountAsInContactWithoutAForce)
{
    // Two disks 0.01 apart side by side, and one 0.01 above the floor; all at rest.
    const std::vector<Particle<2>> start{disk(Vec<2>(0.5, 3.0), Vec<2>::Zero()),
                                         disk(Vec<2>(0.76, 3.0), Vec<2>::Zero()),
                                         disk(Vec<2>(1.5, 0.135), Vec<2>::Zero())};
    for (const double margin : {0.0, 0.005, 0.02}) {
        std::vector<Particle<2>> bodies = start;
        DemSettings settings = linear({1e7, 0.0}, 10, bodies[0].mass());
        settings.margin = margin;
        CellList<2> cells(box.origin, box.length, 0.25 + margin);
        ContactHistory<2> history;
        const DemOutcome outcome = test::step_dem<2>(bodies, box, settings, 0.005, cells, history);
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            EXPECT_EQ(bodies[b].contact.is_in_contact, margin > 0.01)
                << "margin " << margin << ", body " << b;
            EXPECT_EQ(bodies[b].contact.mean_force, Vec<2>::Zero());
            EXPECT_EQ(bodies[b].centre, start[b].centre);
        }
        EXPECT_EQ(outcome.max_overlap, 0.0);
    }
}

TEST(DemStep, RestsOnTheFloorUnderItsWeight)
{
    std::vector<Particle<2>> bodies{disk(Vec<2>(1.0, 0.125), Vec<2>::Zero())};
    const double weight = 0.25 * pi * 0.125 * 0.125 * 980.0;
    bodies[0].contact.steady_force = Vec<2>(0.0, -weight);
    const auto law = LinearSpringDashpot::from_restitution(0.1, 2.5e-4, bodies[0].mass());
    const DemSettings settings = linear(law, 1000, bodies[0].mass());
    CellList<2> cells(box.origin, box.length, 0.25);
    ContactHistory<2> history;
    DemOutcome outcome;
    for (int s = 0; s < 40; ++s) {
        outcome = test::step_dem<2>(bodies, box, settings, 0.005, cells, history);
    }
    // Static overlap W/k, and the mean contact force carries the weight.
    EXPECT_NEAR(0.125 - bodies[0].centre.y(), weight / law.stiffness,
                1e-3 * weight / law.stiffness);
    EXPECT_NEAR(bodies[0].contact.mean_force.y(), weight, 1e-6 * weight);
    EXPECT_TRUE(bodies[0].contact.is_in_contact);
}

template <class D>
class FrictionalCollision : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(FrictionalCollision, Dimensions);

/// Σ m (x − o) × v + J ω about the fixed point o.
template <int Dim>
AngularVec<Dim> angular_momentum(const std::vector<Particle<Dim>>& bodies, const Vec<Dim>& o)
{
    AngularVec<Dim> total = zero_angular<Dim>();
    for (const Particle<Dim>& b : bodies) {
        total += b.mass() * cross(Vec<Dim>(b.centre - o), b.velocity) + b.inertia() * b.omega;
    }
    return total;
}

template <int Dim>
double magnitude(const AngularVec<Dim>& x)
{
    if constexpr (Dim == 2) {
        return std::abs(x);
    } else {
        return x.norm();
    }
}

TYPED_TEST(FrictionalCollision, ConservesLinearAndAngularMomentumToRoundOff)
{
    constexpr int Dim = TypeParam::value;
    const Material rough{1e8, 0.25, 0.4, 0.05, 0.7};
    const double mass = 2500.0 * Ball<Dim>{0.1}.volume();
    const std::vector<std::pair<const char*, AnyContactModel>> models{
        {"hertz_mindlin", HertzMindlin{}},
        {"linear", LinearSpringDashpot({1e6, 0.2 * std::sqrt(1e6 * mass)}, 0.5 * mass)}};
    for (const auto& [name, model] : models) {
        // Unequal spinning balls, off-centre: the contact slides, then sticks and rolls.
        std::vector<Particle<Dim>> bodies{
            test::ball<Dim>(Vec<Dim>::Constant(0.3), test::along<Dim>(0, 2.0, 0.5), 0.05, 2500.0,
                            rough),
            test::ball<Dim>(test::along<Dim>(0, 0.38, 0.33), test::along<Dim>(0, -1.0, -0.3), 0.04,
                            5000.0, rough)};
        if constexpr (Dim == 2) {
            bodies[0].omega = 30.0;
            bodies[1].omega = -50.0;
        } else {
            bodies[0].omega = Vec<3>(10.0, -20.0, 30.0);
            bodies[1].omega = Vec<3>(-40.0, 0.0, -50.0);
        }
        const Vec<Dim> o = Vec<Dim>::Constant(-1.0); // any fixed point
        const Vec<Dim> p0 =
            bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
        const AngularVec<Dim> l0 = angular_momentum<Dim>(bodies, o);
        const double spin_before = magnitude<Dim>(AngularVec<Dim>(bodies[0].omega));
        ContactHistory<Dim> history;
        bool has_touched = false;
        test::run_substeps<Dim>(bodies, test::box<Dim>(Vec<Dim>::Constant(1.0), {}),
                                DemSettings{model, 0.0, 1}, 2e-6, 40000, history,
                                [&](const auto& b, const auto& h) {
                                    has_touched = has_touched || !h.springs.empty();
                                    return b[1].centre.x() < 0.9;
                                });
        ASSERT_TRUE(has_touched) << name;
        EXPECT_GT(std::abs(spin_before - magnitude<Dim>(AngularVec<Dim>(bodies[0].omega))), 1.0)
            << name << ": friction changed the spins";
        const Vec<Dim> p1 =
            bodies[0].mass() * bodies[0].velocity + bodies[1].mass() * bodies[1].velocity;
        const AngularVec<Dim> l1 = angular_momentum<Dim>(bodies, o);
        // Round-off: each of the ~1e4 sub-steps adds a few ulps of |p| and |L| (an O(α/r) error
        // in the lever arms would show as 1e-4).
        const double scale = bodies[0].mass() * 2.0;
        std::printf("%dD %s: |Δp| / (m v) = %.1e, |ΔL| / (m v L) = %.1e\n", Dim, name,
                    (p1 - p0).norm() / scale, magnitude<Dim>(AngularVec<Dim>(l1 - l0)) / scale);
        EXPECT_LT((p1 - p0).norm(), 1e-11 * scale) << name;
        EXPECT_LT(magnitude<Dim>(AngularVec<Dim>(l1 - l0)), 1e-11 * scale) << name;
    }
}

TEST(ContactHistory, TangentialSpringIsDroppedWhenTheContactOpens)
{
    const Material rough{1e8, 0.25, 0.5, 0.0, 0.8};
    // A spinning disk hits the floor at a slant; a second one hits the first from the side.
    std::vector<Particle<2>> bodies{
        test::ball<2>(Vec<2>(0.5, 0.0501), Vec<2>(1.0, -1.0), 0.05, 2500.0, rough),
        test::ball<2>(Vec<2>(0.7, 0.5), Vec<2>(0.0, 0.0), 0.05, 2500.0, rough)};
    bodies[0].omega = 20.0;
    const DemWalls<2> walls = test::box<2>(Vec<2>(2.0, 2.0), {false, true}, rough);
    ContactHistory<2> history;
    std::vector<ContactKey> seen;
    test::run_substeps<2>(bodies, walls, DemSettings{HertzMindlin{}, 0.0, 1}, 1e-6, 200000, history,
                          [&](const auto& b, const auto& h) {
                              const double floor_overlap = b[0].radius() - b[0].centre.y();
                              EXPECT_EQ(h.springs.size(), floor_overlap > 0.0 ? 1U : 0U);
                              if (!h.springs.empty() && seen.empty()) {
                                  seen.push_back(h.springs.front().key);
                              }
                              return !(seen.size() == 1 && floor_overlap < -1e-3);
                          });
    ASSERT_EQ(seen.size(), 1U);
    EXPECT_EQ(seen.front(), wall_contact_key(0, 1, 0));
    EXPECT_TRUE(history.springs.empty());
    // Now a pair: the first disk flies into the second, which waits at rest.
    bodies[0].centre = Vec<2>(0.5, 0.5);
    bodies[0].velocity = Vec<2>(1.0, 0.03);
    bool was_open = false;
    test::run_substeps<2>(bodies, walls, DemSettings{HertzMindlin{}, 0.0, 1}, 1e-6, 400000, history,
                          [&](const auto& b, const auto& h) {
                              const bool touching = (b[1].centre - b[0].centre).norm() <
                                                    b[0].radius() + b[1].radius();
                              EXPECT_EQ(h.springs.size(), touching ? 1U : 0U);
                              if (touching) {
                                  EXPECT_EQ(h.springs.front().key, (ContactKey{0, 1}));
                                  was_open = true;
                              }
                              return !(was_open && !touching);
                          });
    EXPECT_TRUE(was_open);
    EXPECT_TRUE(history.springs.empty());
}

TEST(ContactHistory, StaticFrictionHoldsABodyAcrossTimeSteps)
{
    // A disk on the floor pushed along it by F below μ m g, with the torque that cancels the
    // friction's moment: it must stay, the spring carrying F (ξ = −F/k_t). Force and torque
    // move the centre and turn the disk in the ratio 1 : κ (κ = m r²/J = 2), so the centre
    // moves ξ/3. The spring lives in the history from one time step (one call of
    // advance_contacts) to the next; a history thrown away every step lets the disk creep.
    const Material rough{1e8, 0.25, 0.5, 0.0, 0.5};
    const double g = 9.81;
    const auto hold = [&](bool keep_history) {
        std::vector<Particle<2>> bodies{
            test::ball<2>(Vec<2>(1.0, 0.05), Vec<2>::Zero(), 0.05, 2500.0, rough)};
        Particle<2>& b = bodies[0];
        // Start at the static overlap (F_n = m g), so that the disk does not bounce.
        const ContactPair pair = make_contact_pair(
            ball_side(b.mass(), b.inertia(), b.radius(), rough, true), wall_side(rough));
        const double overlap =
            std::pow(b.mass() * g / HertzMindlin::hertz_stiffness(pair), 2.0 / 3.0);
        b.centre.y() -= overlap;
        const double push = 0.5 * 0.5 * b.mass() * g;
        b.contact.steady_force = Vec<2>(push, -b.mass() * g);
        b.contact.steady_torque =
            push * (b.radius() - 0.5 * overlap); // the lever of the friction force
        const DemWalls<2> walls = test::box<2>(Vec<2>(2.0, 2.0), {false, true}, rough);
        CellList<2> cells(walls.origin, walls.length, 0.1);
        ContactHistory<2> history;
        const DemSettings settings{HertzMindlin{}, 0.0, 100};
        for (int step = 0; step < 400; ++step) { // 0.4 s, many tangential periods (5 ms)
            (void)test::step_dem<2>(bodies, walls, settings, 1e-3, cells, history);
            if (!keep_history) {
                history.springs.clear();
            }
        }
        const double stretch = push / HertzMindlin{}.law({overlap, 0.0}, pair).tangential_stiffness;
        if (keep_history) {
            // The tangential dashpot has damped the oscillation; 1 % for F_n ≠ m g exactly.
            EXPECT_EQ(history.springs.size(), 1U);
            EXPECT_NEAR(history.springs.front().displacement.x() / stretch, -1.0, 0.01);
        }
        return 3.0 * (b.centre.x() - 1.0) / stretch;
    };
    const double kept = hold(true);
    const double dropped = hold(false);
    std::printf("the contact point moved %.4g (history kept) and %.3g (dropped every step) "
                "static stretches F/k_t\n",
                kept, dropped);
    EXPECT_NEAR(kept, 1.0, 0.01);
    EXPECT_GT(dropped, 10.0); // the test can tell
}

} // namespace
} // namespace fddem
