// SPDX-License-Identifier: MIT
// DEM sub-steps (contact/dem_step.hpp) against the analytic spring–dashpot collision: dry
// normal collisions with walls and between bodies give the restitution coefficient
// exp(−ζπ/√(1−ζ²)) within 1 %, conserve kinetic energy with c = 0 and β = 0 within 0.1 %,
// conserve linear momentum to round-off, and nothing tunnels at twice the fastest impact of
// the paper's cases.

#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/dem_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;

DemBody<2> disk(const Vec<2>& centre, const Vec<2>& velocity, double radius = 0.125,
                double density = 1.25)
{
    const double mass = density * pi * radius * radius;
    return {centre, velocity,       0.0, radius, mass, 0.5 * mass * radius * radius,
            true,   Vec<2>::Zero(), 0.0};
}

const DemWalls<2> box{Vec<2>(0.0, 0.0), Vec<2>(2.0, 6.0), {true, true}};

/// Runs whole fluid steps of `dt` until `done` or `max_steps`; returns the steps taken and the
/// largest relative overlap.
template <class Done>
double run(std::vector<DemBody<2>>& bodies, const DemSettings& settings, double dt, int max_steps,
           Done done)
{
    CellList<2> cells(box.origin, box.length, 0.25);
    double overlap = 0.0;
    for (int s = 0; s < max_steps && !done(bodies); ++s) {
        overlap = std::max(
            overlap, advance_contacts<2>(bodies, box, settings, dt, cells).max_relative_overlap);
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
    // a spins at 2 about z: its contact point (0.5, 0) moves at (0, 1); b's slides by −1 in y.
    EXPECT_NEAR(g.slip_velocity.y(), -1.0, 1e-15);
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
        std::vector<DemBody<2>> bodies{disk(Vec<2>(1.0, 0.126), Vec<2>(0.0, -5.0))};
        const double t_c = 2.5e-4;
        const auto law = LinearSpringDashpot::from_restitution(e, t_c, bodies[0].mass);
        const double dt = 0.005;
        const DemSettings settings{law, 0.0, static_cast<int>(std::ceil(100.0 * dt / t_c))};
        run(bodies, settings, dt, 4, [](const auto&) { return false; });
        EXPECT_NEAR(bodies[0].velocity.y() / 5.0, e, 0.01 * e) << "e = " << e;
        EXPECT_GT(bodies[0].centre.y(), 0.125); // left the floor again
        EXPECT_NEAR(bodies[0].velocity.x(), 0.0, 1e-15);
    }
}

TEST(DemStep, PairCollisionConservesMomentumAndGivesTheRestitution)
{
    const double e = 0.7;
    // Unequal disks, head on along a slant line.
    std::vector<DemBody<2>> bodies{disk(Vec<2>(0.8, 3.0), Vec<2>(2.0, 1.0)),
                                   disk(Vec<2>(1.2, 3.2), Vec<2>(-1.0, -0.5), 0.1, 2.0)};
    const Vec<2> momentum =
        bodies[0].mass * bodies[0].velocity + bodies[1].mass * bodies[1].velocity;
    const double reduced = bodies[0].mass * bodies[1].mass / (bodies[0].mass + bodies[1].mass);
    const auto law = LinearSpringDashpot::from_restitution(e, 1e-3, reduced);
    const Vec<2> n = (bodies[1].centre - bodies[0].centre).normalized();
    const double approach = (bodies[0].velocity - bodies[1].velocity).dot(n);
    const double dt = 0.005;
    const DemSettings settings{law, 0.0, 250}; // 50 sub-steps per collision
    run(bodies, settings, dt, 60, [](const auto&) { return false; });
    const Vec<2> after = bodies[0].mass * bodies[0].velocity + bodies[1].mass * bodies[1].velocity;
    EXPECT_NEAR((after - momentum).norm(), 0.0, 1e-14 * momentum.norm());
    const double separation = (bodies[1].velocity - bodies[0].velocity).dot(n);
    EXPECT_NEAR(separation / approach, e, 0.01 * e);
}

TEST(DemStep, ElasticCollisionConservesKineticEnergy)
{
    std::vector<DemBody<2>> bodies{disk(Vec<2>(0.7, 3.0), Vec<2>(3.0, 0.4)),
                                   disk(Vec<2>(1.3, 3.05), Vec<2>(-2.0, 0.0))};
    const auto energy = [&] {
        double k = 0.0;
        for (const auto& b : bodies) {
            k += 0.5 * b.mass * b.velocity.squaredNorm();
        }
        return k;
    };
    const double before = energy();
    const DemSettings settings{{1e6, 0.0}, 0.0, 400};
    run(bodies, settings, 0.005, 40, [](const auto&) { return false; });
    EXPECT_GT(bodies[1].velocity.x(), 0.0); // they did collide
    EXPECT_NEAR(energy(), before, 1e-3 * before);
}

TEST(DemStep, NoTunnellingAtTwiceTheFastestImpactOfThePaperCases)
{
    // The Fig. 5 disk (k = 1e7, c = 0, the case's automatic sub-steps) thrown at the floor at
    // 22 cm/s, twice the fastest impact the paper's cases reach (about 11 cm/s), under gravity.
    std::vector<DemBody<2>> bodies{disk(Vec<2>(1.0, 0.2), Vec<2>(0.0, -22.0))};
    bodies[0].steady_force = Vec<2>(0.0, -(1.25 - 1.0) * pi * 0.125 * 0.125 * 980.0);
    const DemSettings settings{{1e7, 0.0}, 0.0, 1150};
    const double overlap = run(bodies, settings, 0.005, 10, [](const auto&) { return false; });
    EXPECT_GT(overlap, 0.0);
    EXPECT_LT(overlap, 0.02); // 22 √(m/k) / r = 1.4 %
    EXPECT_GT(bodies[0].centre.y(), 0.125);
}

TEST(DemStep, RestsOnTheFloorUnderItsWeight)
{
    std::vector<DemBody<2>> bodies{disk(Vec<2>(1.0, 0.125), Vec<2>::Zero())};
    const double weight = 0.25 * pi * 0.125 * 0.125 * 980.0;
    bodies[0].steady_force = Vec<2>(0.0, -weight);
    const auto law = LinearSpringDashpot::from_restitution(0.1, 2.5e-4, bodies[0].mass);
    const DemSettings settings{law, 0.0, 1000};
    CellList<2> cells(box.origin, box.length, 0.25);
    DemOutcome<2> outcome;
    for (int s = 0; s < 40; ++s) {
        outcome = advance_contacts<2>(bodies, box, settings, 0.005, cells);
    }
    // Static overlap W/k, and the mean contact force carries the weight.
    EXPECT_NEAR(0.125 - bodies[0].centre.y(), weight / law.stiffness,
                1e-3 * weight / law.stiffness);
    EXPECT_NEAR(outcome.mean_force[0].y(), weight, 1e-6 * weight);
    EXPECT_TRUE(outcome.has_contact[0]);
}

} // namespace
} // namespace fddem
