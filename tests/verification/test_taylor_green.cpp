// SPDX-License-Identifier: MIT
// Taylor–Green vortex in a periodic box [0, 2π]²: u = sin x cos y e^{−2νt},
// v = −cos x sin y e^{−2νt}. The measured decay rate of the velocity must match 2ν.

#include "fddem/grid/loops.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/case_builders.hpp"
#include "support/run_to_end.hpp"

namespace fddem {
namespace {

double kinetic_energy(const Simulation<2>& sim)
{
    const auto& grid = sim.grid();
    double e = 0.0;
    for (int a = 0; a < 2; ++a) {
        e += sum_over(grid.communicator(), grid.owned_cells(), [&](const Index<2>& c) {
            return 0.5 * std::pow(sim.fluid().u[a](c), 2) * grid.cell_volume();
        });
    }
    return e;
}

TEST(TaylorGreen, DecayRateWithinOnePercentAt64)
{
    const double length = 2.0 * std::numbers::pi;
    const double nu = 0.01;
    const double end = 10.0;
    CaseConfig config = test::cavity_config(64, 1.0 / nu, 0.05, end);
    config.domain.size = {length, length};
    config.domain.periodic = {true, true};
    config.walls.velocity.clear();
    config.simple.tolerance = 1e-8;
    Simulation<2> sim(config);
    const auto& grid = sim.grid();
    for_each_index(grid.face_box(0), [&](const Index<2>& c) {
        const Vec<2> x = grid.face_centre(0, c);
        sim.fluid().u[0](c) = std::sin(x[0]) * std::cos(x[1]);
    });
    for_each_index(grid.face_box(1), [&](const Index<2>& c) {
        const Vec<2> x = grid.face_centre(1, c);
        sim.fluid().u[1](c) = -std::cos(x[0]) * std::sin(x[1]);
    });
    const double e0 = kinetic_energy(sim);
    test::run_to_end(sim);
    const double e1 = kinetic_energy(sim);
    // Energy decays at twice the velocity's rate, 4ν.
    const double rate = -std::log(e1 / e0) / (2.0 * sim.clock().time);
    std::printf("velocity decay rate %.6f  exact %.6f  relative error %.2e\n", rate, 2.0 * nu,
                rate / (2.0 * nu) - 1.0);
    // Issue 2: within 1 % at 64². Expected error: h²/12 ≈ 8e-4 (space) + νΔt ≈ 5e-4 (time).
    EXPECT_NEAR(rate / (2.0 * nu), 1.0, 0.01);
}

} // namespace
} // namespace fddem
