// SPDX-License-Identifier: MIT
// DEM collisions coupled to the fluid (eq. (18) with eqs. (13)–(17)): the paper's Fig. 5 disk
// on a coarser grid falls, touches the floor, and comes to rest on it without sinking in.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/track_bodies.hpp"

namespace fddem {
namespace {

const std::string fig05 =
    std::string(FDDEM_SOURCE_DIR) + "/cases/paper/fig05_disk_in_box/case.toml";

TEST(DiskInBox, FallsLandsAndComesToRestOnTheFloor)
{
    // Fig. 5 case (k = 1e7, restitution 0.3, β = 2, paper coupling) at h = 1/32, N_a = 3.
    CaseConfig config = read_case(fig05, {"domain.cells=[64,192]", "time.end=1.2"});
    config.bodies.front().n_rings = 3;
    Simulation<2> sim(config);
    const test::BodyHistory landing = test::run_and_track(sim);
    const Particle<2>& body = sim.bodies().front();
    const double r = body.shape.radius();
    std::printf("max speed %.3f, first contact t = %.3f, at rest from t = %.3f, "
                "max overlap %.2e r, rest at (%.5f, %.5f)\n",
                landing.max_speed, landing.first_contact, landing.rest_from,
                landing.max_relative_overlap, body.centre[0], body.centre[1]);
    // It falls 3.875 cm at about 5.5 cm/s (5.55 at h = 1/64): contact near t = 0.8.
    EXPECT_GT(landing.max_speed, 4.5);
    EXPECT_LT(landing.max_speed, 7.0);
    EXPECT_GT(landing.first_contact, 0.6);
    EXPECT_LT(landing.first_contact, 1.0);
    // Stiff contact: the overlap stays below 1 % of the radius, and the disk rests on the
    // floor (centre one radius up), not in it, well before the end.
    EXPECT_LT(landing.max_relative_overlap, 0.01);
    EXPECT_NEAR(body.centre[1], r, 0.01 * r);
    EXPECT_GT(landing.rest_from, 0.0);
    EXPECT_LT(landing.rest_from, 1.1);
    // Released on the centre line of a symmetric box: it lands there.
    EXPECT_NEAR(body.centre[0], 1.0, 0.02);
}

/// What a Fig. 5 run at h = 1/32 did, step by step, under `algorithm`.
struct FallAndLanding {
    double speed_at_half = 0.0; ///< |v| at t = 0.5 s, in free fall [cm/s]
    double max_speed = 0.0;     ///< largest |v| over the run [cm/s]
    double max_overlap = 0.0;   ///< largest α / r
    double rest_height = 0.0;   ///< the centre's height at the end [cm]
    int projection_steps = 0;   ///< steps taken as projection steps (a predictor's rounds)
    int iterated_steps = 0;     ///< steps of SIMPLE's outer iterations
};

FallAndLanding fall_and_land(StepAlgorithm algorithm)
{
    CaseConfig config = read_case(fig05, {"domain.cells=[64,192]", "time.end=1.2"});
    config.bodies.front().n_rings = 3;
    config.simple.algorithm = algorithm;
    config.coupling.is_forcing_normalised = true; // what the projection step needs with bodies
    Simulation<2> sim(config);
    FallAndLanding run;
    StepReport report;
    do {
        report = sim.advance();
        const Particle<2>& body = sim.bodies().front();
        run.max_speed = std::max(run.max_speed, body.velocity.norm());
        run.max_overlap = std::max(run.max_overlap, report.max_relative_overlap);
        if (std::abs(sim.clock().time - 0.5) < 1e-9) {
            run.speed_at_half = body.velocity.norm();
        }
        ++(report.momentum_rounds > 0 ? run.projection_steps : run.iterated_steps);
    } while (!sim.is_finished(report));
    run.rest_height = sim.bodies().front().centre[1];
    return run;
}

TEST(DiskInBox, TheProjectionStepFallsAndLandsAsSimpleDoes)
{
    // simple.algorithm = "projection" with a body: one predictor, one projection and one pass of
    // eqs. (13)–(16) a step, and SIMPLE's iterations in the steps where the disk is within two
    // cells of the floor or touches it. Without that fallback the disk left the floor at
    // 20 cm/s after its first touch (docs/method.md §1); it must land as SIMPLE's does.
    const FallAndLanding simple = fall_and_land(StepAlgorithm::simple);
    const FallAndLanding projection = fall_and_land(StepAlgorithm::projection);
    std::printf("speed at t = 0.5: simple %.4f, projection %.4f; largest speed %.3f / %.3f; "
                "overlap %.2e / %.2e; rest height %.5f / %.5f; projection run: %d projection "
                "steps, %d iterated\n",
                simple.speed_at_half, projection.speed_at_half, simple.max_speed,
                projection.max_speed, simple.max_overlap, projection.max_overlap,
                simple.rest_height, projection.rest_height, projection.projection_steps,
                projection.iterated_steps);
    EXPECT_NEAR(projection.speed_at_half, simple.speed_at_half, 0.015 * simple.speed_at_half);
    EXPECT_LT(projection.max_speed, 1.05 * simple.max_speed); // no kick off the floor
    EXPECT_LT(projection.max_overlap, 0.01);
    EXPECT_NEAR(projection.rest_height, simple.rest_height, 0.001);
    // Projection steps in the fall, SIMPLE's iterations in the landing (and none in SIMPLE's run).
    EXPECT_EQ(simple.projection_steps, 0);
    EXPECT_GT(projection.projection_steps, 100);
    EXPECT_GT(projection.iterated_steps, 10);
}

TEST(DiskInBox, AProjectionStepNearAnotherBodyOrAWallIteratesInstead)
{
    // is_any_body_near_contact: a free disk within two cells (the hat kernel's two widths) of a
    // fixed disk listed before it, or of a wall, takes SIMPLE's iterations (no predictor
    // rounds); one far from both takes the projection step.
    const auto first_step = [](double free_x, double free_y) {
        const std::string text = R"([domain]
size = [2.0, 2.0]
cells = [32, 32]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -980.0]
[time]
dt = 0.001
end = 0.001
[simple]
algorithm = "projection"
[coupling]
normalised_forcing = true
[[bodies]]
diameter = 0.5
density = 2.0
position = [0.5, 1.0]
motion = "fixed"
[[bodies]]
diameter = 0.5
density = 2.0
)";
        const CaseConfig config = read_case_string(
            text, "near.toml",
            {"bodies.2.position=[" + std::to_string(free_x) + "," + std::to_string(free_y) + "]"});
        Simulation<2> sim(config);
        return sim.advance().momentum_rounds;
    };
    const double h = 2.0 / 32;
    EXPECT_GT(first_step(1.5, 1.0), 0);            // far from the fixed disk and the walls
    EXPECT_EQ(first_step(1.0 + 1.5 * h, 1.0), 0);  // 1.5 h from the fixed disk
    EXPECT_EQ(first_step(1.5, 0.25 + 1.5 * h), 0); // 1.5 h above the floor
}

TEST(DiskInBox, RunStopsOnceTheDiskHasSettled)
{
    // time.rest_speed: the run ends rest_duration after every free body became slower than
    // the given speed (|U| + |ω|R), not at time.end.
    CaseConfig config = read_case(fig05, {"domain.cells=[64,192]", "time.end=1.5",
                                          "time.rest_speed=0.01", "time.rest_duration=0.05"});
    config.bodies.front().n_rings = 3;
    Simulation<2> sim(config);
    const test::BodyHistory landing = test::run_and_track(sim, 0.01);
    ASSERT_TRUE(sim.at_rest_since().has_value());
    const double since = *sim.at_rest_since();
    std::printf("first contact t = %.3f, at rest since t = %.3f, stopped at t = %.3f\n",
                landing.first_contact, since, sim.clock().time);
    EXPECT_GT(since, landing.first_contact); // not while it was still falling
    EXPECT_NEAR(sim.clock().time, since + 0.05, 0.5 * config.time.dt);
    EXPECT_LT(sim.clock().time, 1.2);
    // It stopped because the disk rests on the floor, one radius up.
    const Particle<2>& body = sim.bodies().front();
    EXPECT_LT(body.velocity.norm() + std::abs(body.omega) * body.shape.radius(), 0.01);
    EXPECT_NEAR(body.centre[1], body.shape.radius(), 0.01 * body.shape.radius());
}

} // namespace
} // namespace fddem
