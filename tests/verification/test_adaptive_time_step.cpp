// SPDX-License-Identifier: MIT
// The adaptive time step (time.max_courant) and the pseudo-time march to a steady state
// (time.steady) on whole runs: Δt follows the limit; a run that breaks down at a fixed Δt runs
// with the limit; the steady march reaches the time-marched steady state in far fewer steps.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
    // The fluid of the last good step: the collapse stops the next step before it moves the
    // time levels on, and what the run then writes (fields, checkpoint) must be this state.
    FaceField<2> u = sim.fluid().u;
    FaceField<2> u_n = sim.fluid().u_n;
    try {
        for (StepReport report = sim.advance(); !sim.is_finished(report); report = sim.advance()) {
            last_good = sim.clock().time;
            u = sim.fluid().u;
            u_n = sim.fluid().u_n;
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
    for (int axis = 0; axis < 2; ++axis) {
        const auto now = sim.fluid().u[axis].values();
        const auto now_n = sim.fluid().u_n[axis].values();
        EXPECT_TRUE(std::equal(now.begin(), now.end(), u[axis].values().begin()));
        EXPECT_TRUE(std::equal(now_n.begin(), now_n.end(), u_n[axis].values().begin()));
    }
}

TEST(AdaptiveTimeStep, ARunThatBreaksDownAtTheFixedStepRunsWithTheLimit)
{
    // At Δt = 0.02 the flow around the falling disk breaks down: the Courant number reaches
    // hundreds (measured: 14, 28, 70, 55, then 804 at step 5 with the default Anderson mixing;
    // 507 at step 5 without it) and steps end unconverged at the outer iterations' limit; with
    // the mixing's weights unrounded (simple.acceleration_weight_bits = 0) the velocity
    // overflows at step 7. Whether the broken-down flow overflows depends on round-off, so
    // either outcome is taken as the breakdown. With the limit the same run keeps the Courant
    // number near 1.
    const CaseConfig fixed = read_case_string(heavy_disk, "test:heavy disk");
    {
        const test::NansAllowed overflow; // the blow-up, until NumericalError reports it
        Simulation<2> sim(fixed);
        double fixed_courant = 0.0;
        bool is_any_unconverged = false;
        try {
            bool is_finished = false;
            while (!is_finished) {
                const StepReport report = sim.advance();
                fixed_courant = std::max(fixed_courant, report.courant);
                is_any_unconverged = is_any_unconverged || !report.is_converged;
                is_finished = sim.is_finished(report);
            }
        } catch (const NumericalError&) {
            fixed_courant = std::numeric_limits<double>::infinity();
            is_any_unconverged = true;
        }
        EXPECT_GT(fixed_courant, 100.0);
        EXPECT_TRUE(is_any_unconverged);
    }
    const CaseConfig limited =
        read_case_string(heavy_disk, "test:heavy disk", {"time.max_courant=0.5"});
    Simulation<2> sim(limited);
    double courant = 0.0;
    double largest_move = 0.0;
    int retried = 0;
    Vec<2> previous = sim.bodies().front().centre;
    for (StepReport report = sim.advance(); !sim.is_finished(report); report = sim.advance()) {
        courant = std::max(courant, report.courant);
        retried += report.retries > 0 ? 1 : 0;
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
    // about twice the start's (measured: 1.17 for the limit 0.5; at the fixed step: 14 to 804).
    EXPECT_LT(courant, 1.5);
    // By the controller alone: no step reached the default retry limit, 4 × 0.5.
    EXPECT_EQ(retried, 0);
}

TEST(AdaptiveTimeStep, WithoutItsKeyTheCourantRetryLimitIsFourTimesTheCourantLimit)
{
    // The simulation takes the default of retry_courant_limit (TimeStepControl.*), and the
    // case's own value over it; without time.max_courant nothing is retried. (No step of the
    // heavy disk reaches 4 × its limit: the controller binds the first step for any limit
    // below 6.2, and above it the first step's 14.3 stays under 4 × the limit.)
    const Simulation<2> defaulted(
        read_case_string(heavy_disk, "test:heavy disk", {"time.max_courant=0.3"}));
    ASSERT_TRUE(defaulted.retry_settings().courant.has_value());
    EXPECT_EQ(*defaulted.retry_settings().courant, 1.2);
    const Simulation<2> given(read_case_string(heavy_disk, "test:heavy disk",
                                               {"time.max_courant=0.3", "time.retry_courant=5"}));
    EXPECT_EQ(given.retry_settings().courant, 5.0);
    const Simulation<2> fixed(read_case_string(heavy_disk, "test:heavy disk"));
    EXPECT_FALSE(fixed.retry_settings().courant.has_value());
}

/// The largest difference between two simulations' fluid velocities [m/s].
template <int Dim>
double largest_velocity_difference(const Simulation<Dim>& a, const Simulation<Dim>& b)
{
    double largest = 0.0;
    for (int axis = 0; axis < Dim; ++axis) {
        const auto u = a.fluid().u[axis].values();
        const auto v = b.fluid().u[axis].values();
        for (std::size_t k = 0; k < u.size(); ++k) {
            largest = std::max(largest, std::abs(u[k] - v[k]));
        }
    }
    return largest;
}

TEST(AdaptiveTimeStep, ARetriedStepIsTheStepTakenAtHalfItsLength)
{
    // The heavy disk's first step at Δt = 0.02 s ends at a Courant number of 14.3 (the Courant
    // limit of 100 binds nothing); time.retry_courant = 10 has it taken again from the start at
    // 0.01 s, where it ends at 7.2. The rolled-back start must be exact: the retried step is
    // the first step of a run with time.dt = 0.01 s, bit for bit.
    const CaseConfig retried = read_case_string(heavy_disk, "test:heavy disk",
                                                {"time.max_courant=100", "time.retry_courant=10"});
    const CaseConfig direct =
        read_case_string(heavy_disk, "test:heavy disk", {"time.max_courant=100", "time.dt=0.01"});
    Simulation<2> a(retried);
    const StepReport first = a.advance();
    Simulation<2> b(direct);
    const StepReport reference = b.advance();
    EXPECT_EQ(first.retries, 1);
    EXPECT_EQ(reference.retries, 0);
    EXPECT_NE(a.last_retry_note().find("Courant number 14.3 above time.retry_courant = 10"),
              std::string::npos)
        << a.last_retry_note();
    EXPECT_EQ(a.clock().dt, 0.01);
    EXPECT_EQ(a.clock().time, b.clock().time);
    EXPECT_EQ(a.clock().step, 1);
    EXPECT_LE(first.courant, 10.0);
    EXPECT_EQ(first.outer_iterations, reference.outer_iterations);
    EXPECT_EQ(a.bodies().front().centre, b.bodies().front().centre);
    EXPECT_EQ(a.bodies().front().velocity, b.bodies().front().velocity);
    EXPECT_EQ(largest_velocity_difference(a, b), 0.0);
    // The next step grows from the kept Δt, not from the failed one: 1.2 × 0.01 s.
    a.advance();
    EXPECT_DOUBLE_EQ(a.clock().dt, 0.012);
}

TEST(AdaptiveTimeStep, RetriesHoldEveryKeptStepBelowTheLimitOrUseThemAllUp)
{
    // The heavy disk without a binding Courant limit reaches Courant numbers of 10–960 at
    // Δt = 0.02 s (measured). With time.retry_courant = 20 each step over it is taken again at
    // half its Δt: every kept step is then below 20, or has used its three retries.
    const CaseConfig c =
        read_case_string(heavy_disk, "test:heavy disk",
                         {"time.max_courant=100", "time.retry_courant=20", "time.max_retries=3"});
    Simulation<2> sim(c);
    int retried = 0;
    for (StepReport report = sim.advance(); !sim.is_finished(report); report = sim.advance()) {
        EXPECT_TRUE(report.courant <= 20.0 || report.retries == 3)
            << "step " << sim.clock().step << ": Courant " << report.courant << " after "
            << report.retries << " retries";
        retried += report.retries > 0 ? 1 : 0;
    }
    EXPECT_GE(retried, 3);
    EXPECT_NEAR(sim.clock().time, 0.2, 1e-12);
    EXPECT_TRUE(sim.bodies().front().velocity.allFinite());
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
    EXPECT_LT(largest_velocity_difference(a, b), 1e-4);
}

} // namespace
} // namespace fddem
