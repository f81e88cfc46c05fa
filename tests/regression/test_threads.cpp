// SPDX-License-Identifier: MIT
// The OpenMP threads change nothing but the time (tests/CMakeLists.txt runs every other test on
// one thread, so this is the test that runs the threaded loops, reductions and FFTW's threaded
// transforms with more than one).

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

#include <string>

namespace fddem {
namespace {

struct Outcome {
    Vec<2> centre;
    Vec<2> velocity;
    double omega = 0.0;
    double mass_residual = 0.0;
    int iterations = 0;
};

/// The Fig. 5 disk (64 × 192 cells) released 0.3 above the floor: 40 steps of falling, landing
/// (a contact) and Anderson-mixed outer iterations, on `threads` OpenMP threads.
Outcome fig05_on(int threads)
{
#ifdef FDDEM_HAVE_OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
    const std::string fig05 =
        std::string(FDDEM_SOURCE_DIR) + "/cases/paper/fig05_disk_in_box/case.toml";
    Simulation<2> sim(read_case(
        fig05, {"domain.cells=[64,192]", "bodies.1.n_rings=0", "bodies.1.position=[1.0,0.45]"}));
    Outcome outcome;
    for (int step = 0; step < 40; ++step) {
        const StepReport report = sim.advance();
        outcome.mass_residual = report.mass_residual;
        outcome.iterations += report.outer_iterations;
    }
    outcome.centre = sim.bodies()[0].centre;
    outcome.velocity = sim.bodies()[0].velocity;
    outcome.omega = sim.bodies()[0].omega;
#ifdef FDDEM_HAVE_OPENMP
    omp_set_num_threads(before);
#endif
    return outcome;
}

TEST(Threads, TwoThreadsGiveTheOneThreadRun)
{
    const Outcome one = fig05_on(1);
    const Outcome two = fig05_on(2);
    // The same outer iterations, and the state to round-off (the loops are per cell, the
    // reductions are maxima or blocked sums, and FFTW's threads split whole 1-D transforms).
    EXPECT_EQ(one.iterations, two.iterations);
    EXPECT_LT((one.centre - two.centre).norm(), 1e-12);
    EXPECT_LT((one.velocity - two.velocity).norm(), 1e-10 * std::max(1.0, one.velocity.norm()));
    EXPECT_NEAR(one.omega, two.omega, 1e-10);
    EXPECT_NEAR(one.mass_residual, two.mass_residual, 1e-10);
    EXPECT_LT(one.centre.y(), 0.2); // it has landed (radius 0.125)
}

} // namespace
} // namespace fddem
