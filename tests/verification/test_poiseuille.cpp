// SPDX-License-Identifier: MIT
// Plane Poiseuille flow: periodic in x, walls at y = 0 and H, driven by a uniform body force G.
// Exact: u = G y (H − y) / (2μ). The profile is quadratic, which the discretisation
// (three-point diffusion, quadratic wall ghost) represents exactly, so the discrete steady
// state equals the exact one to the solver tolerance.

#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/case_builders.hpp"
#include "support/run_to_end.hpp"

namespace fddem {
namespace {

TEST(Poiseuille, SteadyProfileIsExactToSolverTolerance)
{
    const double height = 1.0;
    const double mu = 0.5;
    const double drive = 4.0; // G [N/m³]: u_max = G H² / (8 μ) = 1
    CaseConfig config = test::cavity_config(8, 1.0, 0.05, 200.0);
    config.size = {2.0, height};
    config.cells = {8, 16};
    config.periodic = {true, false};
    config.wall_velocity[1][1] = {0.0, 0.0};
    config.viscosity = mu;
    config.body_force = {drive, 0.0};
    config.steady_tolerance = 1e-12;
    config.tolerance = 1e-12;
    Simulation<2> sim(config);
    test::run_to_end(sim);

    double max_error = 0.0;
    double max_v = 0.0;
    const auto& grid = sim.grid();
    for (int j = 0; j < grid.cells(1); ++j) {
        for (int i = 0; i < grid.cells(0); ++i) {
            const double y = grid.face_centre(0, {i, j})[1];
            const double exact = drive * y * (height - y) / (2.0 * mu);
            max_error = std::max(max_error, std::abs(sim.fluid().u[0]({i, j}) - exact));
            max_v = std::max(max_v, std::abs(sim.fluid().u[1]({i, j})));
        }
    }
    std::printf("steps %ld  max |u − exact| = %.3e  max |v| = %.3e\n", sim.clock().step, max_error,
                max_v);
    // Steady to 1e-12 in the normalised rate of change; 1e-9 of u_max leaves room for the
    // decay of the slowest mode not yet below round-off.
    EXPECT_LT(max_error, 1e-9);
    EXPECT_LT(max_v, 1e-12);
}

TEST(Poiseuille, ThreeDimensionalPlaneChannelIsExactToSolverTolerance)
{
    // Periodic in x and z, walls at y = 0 and H: the same quadratic profile, now through the
    // 3D instantiation of every stage (7-point stencils, 3D FFT with a mixed transform).
    const double mu = 0.5;
    const double drive = 4.0;
    CaseConfig config = test::cavity_config(8, 1.0, 0.05, 200.0);
    config.dimension = 3;
    config.origin = {0.0, 0.0, 0.0};
    config.size = {1.0, 1.0, 0.5};
    config.cells = {6, 12, 4};
    config.periodic = {true, false, true};
    config.wall_velocity.clear();
    config.viscosity = mu;
    config.body_force = {drive, 0.0, 0.0};
    config.steady_tolerance = 1e-12;
    config.tolerance = 1e-12;
    Simulation<3> sim(config);
    test::run_to_end(sim);
    const auto& grid = sim.grid();
    double max_error = 0.0;
    for (int k = 0; k < grid.cells(2); ++k) {
        for (int j = 0; j < grid.cells(1); ++j) {
            for (int i = 0; i < grid.cells(0); ++i) {
                const double y = grid.face_centre(0, {i, j, k})[1];
                const double exact = drive * y * (1.0 - y) / (2.0 * mu);
                max_error = std::max(max_error, std::abs(sim.fluid().u[0]({i, j, k}) - exact));
            }
        }
    }
    EXPECT_LT(max_error, 1e-9);
}

} // namespace
} // namespace fddem
