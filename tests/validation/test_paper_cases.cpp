// SPDX-License-Identifier: MIT
// The paper's experiments at their published resolutions (label `validation`: minutes, not in
// the default test run; `ctest --test-dir build/release -L validation`).

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/run_to_end.hpp"
#include "support/track_bodies.hpp"

namespace fddem {
namespace {

std::string paper_case(const std::string& name)
{
    return std::string(FDDEM_SOURCE_DIR) + "/cases/paper/" + name + "/case.toml";
}

double terminal_velocity(const std::string& name)
{
    Simulation<2> sim(read_case(paper_case(name), {}));
    test::run_to_end(sim);
    return -sim.bodies().front().velocity[1];
}

TEST(PaperFigs3And4, TerminalVelocityApproachesTheAnalyticOneWithRefinement)
{
    // Figs. 3-4: Re = 0.1, W/D = 4, ρr = 1.2, t = 0.3; analytic U/U_c = 1 (Faxén's wall
    // factor, eq. (20), the Re → 0 limit; accurate to well below 1 % at W/D = 4).
    const double coarse = terminal_velocity("fig03_settling_channel");    // h = D/16
    const double fine = terminal_velocity("fig04_settling_channel_fine"); // h = D/32
    std::printf("U/U_c: h = D/16: %.4f, h = D/32: %.4f\n", coarse, fine);
    // Measured 1.041 and 1.028: the diffuse interface converges at about first order.
    EXPECT_NEAR(coarse, 1.0, 0.05);
    EXPECT_NEAR(fine, 1.0, 0.035);
    EXPECT_LT(std::abs(fine - 1.0), 0.8 * std::abs(coarse - 1.0));
}

TEST(PaperFig5, DiskFallsAtTheSettlingSpeedLandsAndRests)
{
    Simulation<2> sim(read_case(paper_case("fig05_disk_in_box"), {}));
    const test::BodyHistory run = test::run_and_track(sim);
    const Particle<2>& body = sim.bodies().front();
    const double r = body.shape.radius();
    std::printf("max speed %.3f, first contact t = %.3f, rest from t = %.3f, overlap %.2e r, "
                "rest at (%.5f, %.5f)\n",
                run.max_speed, run.first_contact, run.rest_from, run.max_relative_overlap,
                body.centre[0], body.centre[1]);
    // Measured at h = 1/64: 5.55 cm/s (Re_p = 13.9), contact at t = 0.785, rest from 0.875.
    EXPECT_NEAR(run.max_speed, 5.55, 0.15);
    EXPECT_NEAR(run.first_contact, 0.785, 0.03);
    EXPECT_GT(run.rest_from, 0.0);
    EXPECT_LT(run.rest_from, 1.2);
    EXPECT_LT(run.max_relative_overlap, 0.01);
    EXPECT_NEAR(body.centre[1], r, 0.01 * r);
    EXPECT_NEAR(body.centre[0], 1.0, 0.02);
}

TEST(PaperFigs9To13, EighteenDisksSettleIntoAPileWithSmallOverlaps)
{
    Simulation<2> sim(read_case(paper_case("fig09_eighteen_disks"), {}));
    const test::BodyHistory run = test::run_and_track(sim);
    double top = 0.0;
    for (const Particle<2>& body : sim.bodies()) {
        const double r = body.shape.radius();
        // Every disk inside the box, none in a wall beyond the contact overlap.
        EXPECT_GT(body.centre[0], 0.98 * r);
        EXPECT_LT(body.centre[0], 2.0 - 0.98 * r);
        EXPECT_GT(body.centre[1], 0.98 * r);
        top = std::max(top, body.centre[1]);
    }
    std::printf("max overlap %.2e r, rest from t = %.3f, top of the pile %.3f\n",
                run.max_relative_overlap, run.rest_from, top);
    // With the case's contact margin of h: max overlap 0.29 % of the radius, at rest from
    // t = 1.91 (2026-11-23). The pile is chaotic (runs that differ only in round-off settle
    // differently), so the bounds are the overlap requirement (1 % of the radius) and
    // twice the time to rest; without the margin the overlaps reached 0.56-2.95 % and the pile
    // came to rest at t = 2.4-3.9.
    EXPECT_LT(run.max_relative_overlap, 0.01);
    EXPECT_GT(run.rest_from, 0.0);
    EXPECT_LT(run.rest_from, 3.8);
    // 18 disks of diameter 0.25 in a box 2 wide: at least three layers, at most a loose six.
    EXPECT_GT(top, 0.5);
    EXPECT_LT(top, 1.5);
}

} // namespace
} // namespace fddem
