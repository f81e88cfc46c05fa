// SPDX-License-Identifier: MIT
// A long run: 100 disks settle into a pile (cases/benchmarks/sedimentation_100_disks, about
// 1 minute on one core) without blowing up, leaving the box or overlapping much.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/track_bodies.hpp"

namespace fddem {
namespace {

TEST(Sedimentation100, SettlesIntoAPileWithoutEscapeOrLargeOverlap)
{
    const std::string file =
        std::string(FDDEM_SOURCE_DIR) + "/cases/benchmarks/sedimentation_100_disks/case.toml";
    Simulation<2> sim(read_case(file, {}));
    const test::BodyHistory run = test::run_and_track(sim, 1e-2);
    double mean_speed = 0.0;
    for (const Particle<2>& body : sim.bodies()) {
        const double r = body.shape.radius();
        EXPECT_GT(body.centre[0], 0.95 * r);
        EXPECT_LT(body.centre[0], 2.0 - 0.95 * r);
        EXPECT_GT(body.centre[1], 0.95 * r);
        EXPECT_LT(body.centre[1], 6.0 - r);
        mean_speed += body.velocity.norm() / static_cast<double>(sim.bodies().size());
    }
    std::printf("max overlap %.3f r, all below 1e-2 cm/s from t = %.2f, mean speed %.2e\n",
                run.max_relative_overlap, run.rest_from, mean_speed);
    // Measured (contact.margin = h): 0.32 % overlap, at rest from t = 2.0, mean speed 2e-11 cm/s
    // at t = 3; variants differing in margin or Δt: 0.30-0.33 %, 1.8-1.95 s. The bound
    // is 5 %; 2 % catches a regression of the margin (without it: 3.3-5.1 %).
    EXPECT_LT(run.max_relative_overlap, 0.02);
    EXPECT_GE(run.rest_from, 0.0); // −1: never at rest
    EXPECT_LT(run.rest_from, 2.5);
    EXPECT_LT(mean_speed, 1e-3);
}

} // namespace
} // namespace fddem
