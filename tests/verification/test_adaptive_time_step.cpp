// SPDX-License-Identifier: MIT
// The adaptive time step (time.max_courant) and the pseudo-time march to a steady state
// (time.steady) on whole runs: Δt follows the limit; a run that blows up at a fixed Δt runs
// with the limit; the steady march reaches the time-marched steady state in far fewer steps.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/case_builders.hpp"
#include "support/nans_allowed.hpp"

namespace fddem {
namespace {

TEST(AdaptiveTimeStep, StepFollowsTheCourantLimit)
{
    CaseConfig config = test::cavity_config(32, 100.0, 0.1, 2.0);
    config.time.max_courant = 0.5;
    Simulation<2> sim(config);
    const double h = sim.grid().spacing(0);
    double smallest = config.time.dt;
    while (!sim.is_finished(sim.advance())) {
        const double dt = sim.clock().dt;
        smallest = std::min(smallest, dt);
        EXPECT_LE(dt, config.time.dt);
        // At the step's start the fluid moved at most as fast as the lid (1 m/s): Δt ≤ C h / 1.
        EXPECT_LE(dt, 0.5 * h * (1.0 + 1e-12));
    }
    // The lid sets the speed: Δt = C h / U_lid from the first step, i.e. 0.0156 s, not 0.1 s.
    EXPECT_NEAR(smallest, 0.5 * h, 1e-12);
    EXPECT_NEAR(sim.clock().time, 2.0, 1e-12) << "the last step lands on time.end";
}

/// A very heavy disk (ρs/ρf = 100) dropped in the paper's Fig. 5 box at a coarse h = 1/32.
const std::string heavy_disk = R"(
[domain]
size = [2.0, 6.0]
cells = [64, 192]
[fluid]
density = 1.0
viscosity = 0.1
gravity = [0.0, -980.0]
[[bodies]]
shape = "disk"
diameter = 0.25
density = 100.0
position = [1.0, 4.0]
n_rings = 3
[contact]
model = "linear"
coupling = "paper"
stiffness = 1e7
damping = 560.0
velocity_damping = 2.0
[time]
dt = 0.02
end = 0.2
[simple]
tolerance = 1e-4
)";

TEST(AdaptiveTimeStep, AStepBelowTheShortestAllowedStopsTheRunAtTheLastGoodStep)
{
    // time.min_dt as the collapse of a diverged flow would meet it: the falling disk speeds up,
    // the Courant limit shortens the step below 0.002 s at the third step (0.0057, 0.0024, 0.0018
    // s), and the run stops there with a NumericalError naming the time step, back at the end of
    // the last step it took.
    const CaseConfig c = read_case_string(heavy_disk, "test:heavy disk",
                                          {"time.max_courant=0.5", "time.min_dt=0.002"});
    Simulation<2> sim(c);
    double last_good = 0.0;
    try {
        for (StepReport report = sim.advance(); !sim.is_finished(report); report = sim.advance()) {
            last_good = sim.clock().time;
        }
        ADD_FAILURE() << "the run reached its end";
    } catch (const NumericalError& e) {
        EXPECT_EQ(e.where(), "the adaptive time step");
        EXPECT_NE(std::string(e.what()).find("time.min_dt = 0.002 s"), std::string::npos)
            << e.what();
    }
    EXPECT_GT(last_good, 0.0);
    EXPECT_DOUBLE_EQ(sim.clock().time, last_good);
    EXPECT_TRUE(sim.bodies().front().velocity.allFinite());
}

TEST(AdaptiveTimeStep, ARunThatBlowsUpAtTheFixedStepRunsWithTheLimit)
{
    // At Δt = 0.02 the flow around the falling disk blows up (measured: step 7, t = 0.14 s,
    // Courant numbers 8 to 14). With the limit the same run goes on past that time.
    const CaseConfig fixed = read_case_string(heavy_disk, "test:heavy disk");
    {
        const test::NansAllowed overflow; // the blow-up, until NumericalError reports it
        Simulation<2> sim(fixed);
        EXPECT_THROW(while (!sim.is_finished(sim.advance())){}, NumericalError);
    }
    const CaseConfig limited =
        read_case_string(heavy_disk, "test:heavy disk", {"time.max_courant=0.5"});
    Simulation<2> sim(limited);
    double courant = 0.0;
    double largest_move = 0.0;
    Vec<2> previous = sim.bodies().front().centre;
    for (StepReport report = sim.advance(); !sim.is_finished(report); report = sim.advance()) {
        courant = std::max(courant, report.courant);
        largest_move = std::max(largest_move, (sim.bodies().front().centre - previous).norm());
        previous = sim.bodies().front().centre;
    }
    EXPECT_NEAR(sim.clock().time, 0.2, 1e-12);
    EXPECT_TRUE(sim.bodies().front().velocity.allFinite());
    // Half a cell a step, predicted from the state at the step's start: the body's own
    // motion is bounded by its buoyant weight; the flow it drives may run somewhat ahead.
    EXPECT_LT(largest_move, 0.5 * sim.grid().spacing(1) * 1.05);
    // The flow's Courant number after each step: the limit is predicted from the start of the
    // step, and the fluid in and around the disk speeds up with it within the step, up to
    // about twice the start's (measured: 1.17 for the limit 0.5; at the fixed step: 8 to 14).
    EXPECT_LT(courant, 1.5);
}

TEST(AdaptiveTimeStep, SteadyMarchReachesTheTimeMarchedSteadyStateInFewSteps)
{
    CaseConfig marched = test::cavity_config(32, 100.0, 0.03125, 100.0);
    marched.time.steady_tolerance = 1e-6;
    CaseConfig pseudo = marched;
    pseudo.time.is_steady = true;
    Simulation<2> a(marched);
    while (!a.is_finished(a.advance())) {
    }
    Simulation<2> b(pseudo);
    while (!b.is_finished(b.advance())) {
    }
    EXPECT_LT(b.clock().step * 10, a.clock().step)
        << "time-marched " << a.clock().step << " steps, pseudo-time " << b.clock().step;
    // The same steady state: both stopped with max|∂u/∂t| L/U² < 1e-6, so they may differ by
    // about that over the relaxation time of the slowest mode; 1e-4 of the lid speed is ample.
    double largest = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        const auto u = a.fluid().u[axis].values();
        const auto v = b.fluid().u[axis].values();
        for (std::size_t k = 0; k < u.size(); ++k) {
            largest = std::max(largest, std::abs(u[k] - v[k]));
        }
    }
    EXPECT_LT(largest, 1e-4);
}

} // namespace
} // namespace fddem
