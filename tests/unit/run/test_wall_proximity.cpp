// SPDX-License-Identifier: MIT
// The warning of a shallow marker ring beside a wall (run/wall_proximity.hpp): the gap to the
// box's walls and inflows, the layouts that count, and a run that gives the warning once with the
// retracted layout and not with the paper's layout nor with coupling.markers_off_at_walls.

#include "fddem/io/case_reader.hpp"
#include "fddem/run/run_case.hpp"
#include "fddem/run/wall_proximity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

TEST(WallProximity, TheGapIsToTheNearestWallOrInflowInItsAxissCells)
{
    PeriodicDomain<3> box;
    box.origin = Vec<3>(1.0, 0.0, -1.0);
    box.length = Vec<3>(4.0, 2.0, 3.0);
    BoundaryConditions<3> bc;
    bc.is_periodic = {false, true, false};
    const Vec<3> h(0.1, 0.1, 0.5);
    // x: 0.35 m = 3.5 cells from the low side; y periodic (0.1 from its side, ignored); z:
    // 1.25 m = 2.5 cells of 0.5 from both sides.
    EXPECT_NEAR(gap_to_walls<3>(Vec<3>(1.6, 0.1, 0.5), 0.25, box, bc, h), 2.5, 1e-12);
    EXPECT_NEAR(gap_to_walls<3>(Vec<3>(4.9, 1.0, 0.5), 0.25, box, bc, h), -1.5, 1e-12); // overlap
    // An outflow on x high is no wall; an inflow is (its ghosts mirror the fluid).
    bc.kind[0][1] = BoundaryKind::outflow;
    EXPECT_NEAR(gap_to_walls<3>(Vec<3>(4.9, 1.0, 0.5), 0.25, box, bc, h), 2.5, 1e-12);
    bc.kind[0][1] = BoundaryKind::inflow;
    EXPECT_NEAR(gap_to_walls<3>(Vec<3>(4.9, 1.0, 0.5), 0.25, box, bc, h), -1.5, 1e-12);
    bc.is_periodic = {true, true, true};
    EXPECT_TRUE(std::isinf(gap_to_walls<3>(Vec<3>(1.6, 0.1, 0.5), 0.25, box, bc, h)));
}

TEST(WallProximity, OnlyARetractedRingShallowerThanSixTenthsOfACellWithoutTheFullReachCounts)
{
    CouplingConfig coupling; // the paper's layout
    EXPECT_FALSE(has_shallow_ring_at_walls(coupling));
    coupling.markers = MarkerLayout::retracted; // 0.3 h
    EXPECT_TRUE(has_shallow_ring_at_walls(coupling));
    coupling.marker_retraction = 0.5;
    EXPECT_TRUE(has_shallow_ring_at_walls(coupling));
    coupling.marker_retraction = 0.7;
    EXPECT_FALSE(has_shallow_ring_at_walls(coupling));
    coupling.markers = MarkerLayout::surface;
    coupling.marker_retraction = 0.3;
    EXPECT_TRUE(has_shallow_ring_at_walls(coupling));
    coupling.is_wall_marker_off = true;
    EXPECT_FALSE(has_shallow_ring_at_walls(coupling)); // the hat kernel's default reach, 1.5 h
    coupling.wall_marker_reach = 1.5;
    EXPECT_FALSE(has_shallow_ring_at_walls(coupling));
    coupling.wall_marker_reach = 1.0; // the rule before 2026-12-01: still drifts (WallSqueeze)
    EXPECT_TRUE(has_shallow_ring_at_walls(coupling));
    coupling.kernel = KernelKind::peskin4; // its default reach is 2.5 h
    coupling.wall_marker_reach = 2.0;
    EXPECT_TRUE(has_shallow_ring_at_walls(coupling));
    coupling.wall_marker_reach.reset();
    EXPECT_FALSE(has_shallow_ring_at_walls(coupling));
}

/// The messages of 16 steps of the 2D squeeze case (a disk driven to 0.038 h from a wall) with
/// `overrides`.
std::vector<std::string> squeeze_messages(const std::vector<std::string>& overrides)
{
    const std::string case_file =
        std::string(FDDEM_SOURCE_DIR) + "/cases/verification/disk_wall_squeeze/case.toml";
    struct Collect final : RunMonitor {
        std::vector<std::string> lines;
        void message(const std::string& text) override { lines.push_back(text); }
    } monitor;
    const auto run = test::fresh_test_directory("fddem_wall_ring_") / "squeeze";
    // From gap 0.195 − 0.125 = 0.07 (2.24 h) at U = 1: the gap after step 13 of Δt 0.0043 is
    // 0.0141 = 0.45 h, the first below half a cell (0.59 h after step 12).
    std::vector<std::string> all = {"bodies.1.position=[1.0,0.195]", "time.end=0.0688"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    const RunResult result = run_case(read_case(case_file, all), run, monitor);
    EXPECT_EQ(result.outcome, RunResult::Outcome::completed);
    return monitor.lines;
}

long count_containing(const std::vector<std::string>& lines, const std::string& text)
{
    return std::count_if(lines.begin(), lines.end(), [&](const std::string& line) {
        return line.find(text) != std::string::npos;
    });
}

TEST(WallProximity, ARunWarnsOnceOfARetractedRingBesideAWall)
{
    const std::string warning = "there the resolved force grows as Δt shrinks";
    const auto retracted = squeeze_messages({"coupling.markers=retracted"});
    EXPECT_EQ(count_containing(retracted, warning), 1);
    EXPECT_EQ(count_containing(retracted, "body id 0 is 0.45 cells"),
              1); // the first step below 0.5 h
    EXPECT_EQ(count_containing(retracted, "markers 0.3 cells inside"), 1);
    EXPECT_EQ(count_containing(squeeze_messages({}), warning), 0); // the paper's layout
    EXPECT_EQ(count_containing(squeeze_messages({"coupling.markers=retracted",
                                                 "coupling.markers_off_at_walls=true"}),
                               warning),
              0);
}

} // namespace
} // namespace fddem
