// SPDX-License-Identifier: MIT
// The order in time of time.scheme (core/time_scheme.hpp), with the space error held fixed: a
// decaying Taylor–Green vortex, u = sin x cos y e^{−2νt}, v = −cos x sin y e^{−2νt}, in the
// periodic box [0, 2π]² on one 32² grid, run to t = 2 with Δt = 0.2, 0.1 and 0.05. The grid,
// and so the space error, is the same in the three runs: the differences between them are time
// error alone, and their ratio gives the observed order, p = log2((A_1 − A_2)/(A_2 − A_3)) of
// the velocity amplitude A = (E(t)/E(0))^{1/2}.

#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/taylor_green.hpp"

namespace fddem {
namespace {

/// The amplitude of the vortex at t = 2 s after steps of `dt`.
double amplitude_at_end(TimeScheme scheme, double dt,
                        StepAlgorithm algorithm = StepAlgorithm::simple)
{
    // ν = 0.1: the amplitude falls to e^{−0.4} = 0.67 by t = 2; Re = 1/ν = 10 keeps convection
    // in the problem. νk²Δt = 0.04 at the largest step (k² = 2): in the asymptotic range.
    CaseConfig config = test::taylor_green_config(32, 10.0, dt, 2.0);
    config.time.scheme = scheme;
    config.simple.algorithm = algorithm;
    // The outer iterations' error must stay far below BDF2's time error at Δt = 0.05 (about
    // 1e-6 of the amplitude), so that the differences between the runs are time error.
    config.simple.tolerance = 1e-11;
    config.simple.max_outer_iterations = 200;
    Simulation<2> sim(config);
    test::set_taylor_green_vortex(sim);
    const double e0 = test::kinetic_energy(sim);
    StepReport last;
    do {
        last = sim.advance();
        EXPECT_TRUE(last.is_converged) << "step " << sim.clock().step;
        if (algorithm == StepAlgorithm::projection) {
            // One predictor and one projection, the predictor solved in rounds.
            EXPECT_EQ(last.outer_iterations, 1);
            EXPECT_GE(last.momentum_rounds, 1);
        }
    } while (!sim.is_finished(last));
    EXPECT_NEAR(sim.clock().time, 2.0, 1e-12);
    return std::sqrt(test::kinetic_energy(sim) / e0);
}

/// Three runs of one scheme, Δt = 0.2, 0.1, 0.05: the observed order, and the Richardson
/// extrapolation of the amplitude to Δt → 0 for that order.
struct TimeSeries {
    double order;
    double limit;
};

TimeSeries three_steps(TimeScheme scheme, const char* name, int nominal_order,
                       StepAlgorithm algorithm = StepAlgorithm::simple, double dt = 0.2)
{
    const double a1 = amplitude_at_end(scheme, dt, algorithm);
    const double a2 = amplitude_at_end(scheme, dt / 2, algorithm);
    const double a3 = amplitude_at_end(scheme, dt / 4, algorithm);
    const double order = std::log2((a1 - a2) / (a2 - a3));
    const double limit = a3 - (a2 - a3) / (std::pow(2.0, nominal_order) - 1.0);
    std::printf("%s: amplitude at t = 2: %.12f %.12f %.12f, order %.3f, extrapolated %.9f "
                "(e^-0.4 = %.9f; the rest is the 32² grid's error)\n",
                name, a1, a2, a3, order, limit, std::exp(-0.4));
    return {order, limit};
}

TEST(TimeOrder, EulerIsFirstOrderAndBdf2SecondToTheSameAnswer)
{
    const TimeSeries euler = three_steps(TimeScheme::euler, "euler", 1);
    const TimeSeries bdf2 = three_steps(TimeScheme::bdf2, "bdf2", 2);
    // Asymptotically 1 and 2 (BDF2's first step is Euler: a local O(Δt²) error, second order
    // overall); the bands allow for the next-order remainder at νk²Δt ≤ 0.04.
    EXPECT_GT(euler.order, 0.8);
    EXPECT_LT(euler.order, 1.2);
    EXPECT_GT(bdf2.order, 1.7);
    EXPECT_LT(bdf2.order, 2.3);
    // Both converge to the same Δt → 0 answer on this grid: BDF2 is not second order towards
    // something else. Euler's extrapolation keeps its O(Δt²) remainder, about 2e-5 here
    // (measured: the two limits differ by 1.5e-5; Euler at Δt = 0.05 is 1.3e-3 from its limit).
    EXPECT_NEAR(euler.limit, bdf2.limit, 1e-4);
}

TEST(TimeOrder, TheProjectionStepKeepsEachSchemesOrderToTheSameAnswer)
{
    // simple.algorithm = "projection": one predictor, solved to the tolerance, and one
    // projection a step (the incremental pressure-correction scheme, rotational update), the
    // predictor linearised about u^n + ω (u^n − u^{n−1}). Its splitting error must not lower
    // either scheme's order, and it must converge to SIMPLE's Δt → 0 answer on this grid.
    const double answer = three_steps(TimeScheme::bdf2, "bdf2, simple", 2).limit;
    // BDF2: Δt = 0.1, 0.05, 0.025. At Δt = 0.2 the splitting error is not yet asymptotic
    // (measured: the differences give 1.6 from Δt = 0.2).
    const TimeSeries bdf2 =
        three_steps(TimeScheme::bdf2, "bdf2, projection", 2, StepAlgorithm::projection, 0.1);
    EXPECT_GT(bdf2.order, 1.7);
    EXPECT_LT(bdf2.order, 2.3);
    EXPECT_NEAR(bdf2.limit, answer, 1e-5); // measured 3.6e-6 apart
    // Euler: its error against that answer, at Δt = 0.05, 0.025, 0.0125 (measured 9.8e-4,
    // 5.8e-4, 3.1e-4: order 0.76, then 0.89, tending to 1 more slowly than SIMPLE's Euler,
    // whose errors are 1.1 to 1.4 times these: 1.33e-3, 6.6e-4, 3.3e-4).
    const double e1 =
        amplitude_at_end(TimeScheme::euler, 0.025, StepAlgorithm::projection) - answer;
    const double e2 =
        amplitude_at_end(TimeScheme::euler, 0.0125, StepAlgorithm::projection) - answer;
    const double euler_order = std::log2(e1 / e2);
    std::printf("euler, projection: error at dt = 0.025, 0.0125: %.3e %.3e, order %.3f\n", e1, e2,
                euler_order);
    EXPECT_GT(euler_order, 0.8);
    EXPECT_LT(euler_order, 1.2);
}

} // namespace
} // namespace fddem
