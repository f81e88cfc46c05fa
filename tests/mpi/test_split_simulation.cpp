// SPDX-License-Identifier: MIT
// Whole time steps of a case (Simulation::advance: the time step control, the SIMPLE outer
// iterations with their convergence test, the momentum multigrid, hypre's pressure correction,
// the step's diagnostics) on a grid split across MPI ranks (issue 15), against the same case
// on one process: the velocity and the pressure on every owned entry to 1e-10 of their largest
// value, and the same outer iterations and step sizes, step by step. Run under mpirun -n 1, 2
// and 4.

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/files_and_programs.hpp"
#include "support/split_compare.hpp"

namespace fddem {
namespace {

const std::vector<std::string> hypre_settings = {"simple.pressure_solver=hypre",
                                                 "simple.linear_tolerance=1e-13",
                                                 "simple.linear_max_iterations=2000"};

/// A case of tests/mpi/cases (shared with split_run.py).
std::string case_path(const char* name)
{
    return std::string(FDDEM_SOURCE_DIR) + "/tests/mpi/cases/" + name;
}

template <int Dim>
void expect_split_case_matches(const char* file, const char* name)
{
    const Communicator world = Communicator::world();
    // hypre on one process as well (auto would take the FFT solver there), solved tightly.
    const CaseConfig config = read_case(case_path(file), hypre_settings);
    Simulation<Dim> whole(config);
    Simulation<Dim> split(config, world);
    int steps = 0;
    double worst_u = 0.0;
    double largest_u = 0.0;
    double worst_p = 0.0;
    double largest_p = 0.0;
    bool is_finished = false;
    while (!is_finished) {
        const StepReport expected = whole.advance();
        const StepReport report = split.advance();
        is_finished = whole.is_finished(expected);
        ASSERT_EQ(split.is_finished(report), is_finished);
        ++steps;
        ASSERT_NEAR(split.clock().dt, whole.clock().dt, 1e-12 * whole.clock().dt);
        ASSERT_EQ(report.outer_iterations, expected.outer_iterations) << "step " << steps;
        for (int a = 0; a < Dim; ++a) {
            const auto [worst, largest] = test::compare_owned<Dim>(
                world, split.grid().owned_faces(a), split.fluid().u[a], whole.fluid().u[a]);
            worst_u = std::max(worst_u, worst / std::max(largest, 1e-300));
            largest_u = std::max(largest_u, largest);
        }
        const auto [worst, largest] = test::compare_owned<Dim>(world, split.grid().owned_cells(),
                                                               split.fluid().p, whole.fluid().p);
        worst_p = std::max(worst_p, worst / std::max(largest, 1e-300));
        largest_p = std::max(largest_p, largest);
    }
    EXPECT_GE(steps, 5);
    EXPECT_GT(largest_u, 0.5); // the flow has started
    EXPECT_GT(largest_p, 1e-3);
    EXPECT_LE(worst_u, 1e-10);
    EXPECT_LE(worst_p, 1e-10);
    if (world.rank() == 0) {
        std::printf("[ info ] %s, %d steps on %d ranks: max |Δu|/max|u| = %.2e, "
                    "max |Δp|/max|p| = %.2e\n",
                    name, steps, world.size(), worst_u, worst_p);
    }
}

TEST(SplitSimulation, CavityStepsMatchOneProcess)
{
    expect_split_case_matches<2>("cavity.toml", "2D cavity");
}

TEST(SplitSimulation, ChannelStepsMatchOneProcess)
{
    expect_split_case_matches<3>("channel.toml", "3D channel");
}

TEST(SplitSimulation, BodiesOnSeveralRanksAreRefusedByName)
{
    const Communicator world = Communicator::world();
    const std::string text = test::file_contents(case_path("cavity.toml")) + R"(
[[bodies]]
shape = "disk"
diameter = 0.2
density = 2.0
position = [0.5, 0.45]
)";
    const CaseConfig config = read_case_string(text, "disk.toml");
    if (world.size() == 1) {
        Simulation<2> sim(config, world); // one process: bodies as always
        EXPECT_EQ(sim.bodies().size(), 1U);
        return;
    }
    try {
        Simulation<2> sim(config, world);
        ADD_FAILURE() << "a split grid with a body was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not supported yet"), std::string::npos) << what;
        EXPECT_EQ(e.key(), "bodies");
    }
}

} // namespace
} // namespace fddem
