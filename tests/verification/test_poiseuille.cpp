// SPDX-License-Identifier: MIT
// Plane Poiseuille flow: periodic in x, walls at y = 0 and H, driven by a uniform body force G.
// Exact: u = G y (H − y) / (2μ). The profile is quadratic, which the discretisation
// (three-point diffusion, quadratic wall ghost) represents exactly, so the discrete steady
// state equals the exact one to the solver tolerance. The same channel between a parabolic
// inflow and a zero-gradient outflow must be exact too, with the pressure gradient
// dp/dx = −8 μ U_max / H² (= −12 μ U_mean / H²) and as much fluid leaving as entering.

#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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
    config.domain.size = {2.0, height};
    config.domain.cells = {8, 16};
    config.domain.periodic = {true, false};
    config.walls.velocity[1][1] = {0.0, 0.0};
    config.fluid.viscosity = mu;
    config.fluid.body_force = {drive, 0.0};
    config.time.steady_tolerance = 1e-12;
    config.simple.tolerance = 1e-12;
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

TEST(Poiseuille, ChannelDrivenHardFromRestAcceleratesItsCoreAtFOverRho)
{
    // A fluid at rest under a large force has a momentum residual before it has a velocity;
    // normalised by the floor of the velocity scale it overflowed into a false blow-up at the
    // first outer iteration. Here G = 1000, Δt = 0.01: over 0.1 s the viscous layers grow
    // only √(νt) = 0.1 from each wall, and the core accelerates freely, u = G t / ρ (implicit
    // Euler is exact for a uniform acceleration).
    const double drive = 1000.0;
    CaseConfig config = test::cavity_config(16, 1.0, 0.01, 0.1);
    config.domain.periodic = {true, false};
    config.walls.velocity[1][1] = {0.0, 0.0};
    config.fluid.viscosity = 0.1;
    config.fluid.body_force = {drive, 0.0};
    config.simple.tolerance = 1e-8;
    Simulation<2> sim(config);
    test::run_to_end(sim);
    const double core = sim.fluid().u[0]({8, 8});
    std::printf("t = %.3f, core u = %.4f (G t / rho = %.4f)\n", sim.clock().time, core,
                drive * sim.clock().time);
    EXPECT_NEAR(sim.clock().time, 0.1, 1e-12);
    EXPECT_NEAR(core, drive * sim.clock().time, 0.01 * drive * sim.clock().time);
}

TEST(Poiseuille, ThreeDimensionalPlaneChannelIsExactToSolverTolerance)
{
    // Periodic in x and z, walls at y = 0 and H: the same quadratic profile, now through the
    // 3D instantiation of every stage (7-point stencils, 3D FFT with a mixed transform).
    const double mu = 0.5;
    const double drive = 4.0;
    CaseConfig config = test::cavity_config(8, 1.0, 0.05, 200.0);
    config.domain.dimension = 3;
    config.domain.origin = {0.0, 0.0, 0.0};
    config.domain.size = {1.0, 1.0, 0.5};
    config.domain.cells = {6, 12, 4};
    config.domain.periodic = {true, false, true};
    config.walls.velocity.clear();
    config.fluid.viscosity = mu;
    config.fluid.body_force = {drive, 0.0, 0.0};
    config.time.steady_tolerance = 1e-12;
    config.simple.tolerance = 1e-12;
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

TEST(Poiseuille, InflowToOutflowChannelIsExactWithTheExactPressureGradient)
{
    // Parabolic inflow on x_low (maximum 1.5, mean 1), zero-gradient outflow on x_high, walls
    // at y = 0 and H; Re = ρ U_mean H / μ = 10, started from rest. The fully developed profile
    // is exact at every face, so the steady state is the exact solution everywhere, pressure
    // gradient included, whatever the entrance flow did on the way.
    const double height = 1.0;
    const double mu = 0.1;
    const double u_max = 1.5;
    CaseConfig config = test::cavity_config(8, 1.0, 0.05, 400.0);
    config.domain.size = {4.0, height};
    config.domain.cells = {32, 16};
    config.walls.velocity[1][1] = {0.0, 0.0};
    config.boundaries = {{BoundaryKind::inflow, BoundaryKind::outflow},
                         {BoundaryKind::wall, BoundaryKind::wall}};
    config.inflow.profile = InflowShape::parabolic;
    config.inflow.velocity = u_max;
    config.fluid.viscosity = mu;
    config.time.steady_tolerance = 1e-11;
    config.simple.tolerance = 1e-12;
    config.simple.max_outer_iterations = 200;
    Simulation<2> sim(config);
    test::run_to_end(sim);

    const auto& grid = sim.grid();
    const auto& state = sim.fluid();
    double max_error = 0.0;
    double max_v = 0.0;
    for (int j = 0; j < grid.cells(1); ++j) {
        for (int i = 0; i <= grid.cells(0); ++i) {
            const double y = grid.face_centre(0, {i, j})[1];
            const double exact = 4.0 * u_max * y * (height - y) / (height * height);
            max_error = std::max(max_error, std::abs(state.u[0]({i, j}) - exact));
        }
    }
    for (int j = 0; j <= grid.cells(1); ++j) {
        for (int i = 0; i < grid.cells(0); ++i) {
            max_v = std::max(max_v, std::abs(state.u[1]({i, j})));
        }
    }
    // dp/dx between every pair of neighbouring cells, on every row.
    const double exact_gradient = -8.0 * mu * u_max / (height * height);
    double max_gradient_error = 0.0;
    for (int j = 0; j < grid.cells(1); ++j) {
        for (int i = 1; i < grid.cells(0); ++i) {
            const double gradient = (state.p({i, j}) - state.p({i - 1, j})) / grid.spacing(0);
            max_gradient_error = std::max(max_gradient_error, std::abs(gradient - exact_gradient));
        }
    }
    const auto [inflow, outflow] = boundary_fluxes(grid, sim.boundary_conditions(), state.u);
    std::printf("steps %ld  max |u − exact| = %.3e  max |v| = %.3e  dp/dx error %.3e (exact "
                "%.4f)  inflow %.15f outflow %.15f\n",
                sim.clock().step, max_error, max_v, max_gradient_error, exact_gradient, inflow,
                outflow);
    // Steady to 1e-11 in the normalised rate of change: 1e-9 of U_max is room for the slowest
    // mode not yet decayed below round-off.
    EXPECT_LT(max_error, 1e-9);
    EXPECT_LT(max_v, 1e-9);
    EXPECT_LT(max_gradient_error, 1e-8 * std::abs(exact_gradient));
    // Mass: the outflow is corrected to the inflow's flux; round-off of a 16-term sum.
    EXPECT_NEAR(outflow, inflow, 1e-14 * inflow);
}

TEST(Poiseuille, ThreeDimensionalInflowToOutflowChannelIsExact)
{
    // The same through the 3D instantiation: outflow on x_low and inflow on x_high (flow along
    // −x), walls in y, periodic in z; the parabola is over y only (z is periodic).
    const double mu = 0.1;
    const double u_max = 1.5;
    CaseConfig config = test::cavity_config(8, 1.0, 0.05, 400.0);
    config.domain.dimension = 3;
    config.domain.origin = {0.0, 0.0, 0.0};
    config.domain.size = {2.0, 1.0, 0.5};
    config.domain.cells = {12, 8, 4};
    config.domain.periodic = {false, false, true};
    config.walls.velocity.clear();
    config.boundaries = {{BoundaryKind::outflow, BoundaryKind::inflow},
                         {BoundaryKind::wall, BoundaryKind::wall},
                         {BoundaryKind::wall, BoundaryKind::wall}};
    config.inflow.profile = InflowShape::parabolic;
    config.inflow.velocity = u_max;
    config.fluid.viscosity = mu;
    config.fluid.body_force = {0.0, 0.0, 0.0};
    config.fluid.gravity = {0.0, 0.0, 0.0};
    config.time.steady_tolerance = 1e-11;
    config.simple.tolerance = 1e-12;
    config.simple.max_outer_iterations = 200;
    Simulation<3> sim(config);
    test::run_to_end(sim);
    const auto& grid = sim.grid();
    double max_error = 0.0;
    double max_gradient_error = 0.0;
    for (int k = 0; k < grid.cells(2); ++k) {
        for (int j = 0; j < grid.cells(1); ++j) {
            for (int i = 0; i <= grid.cells(0); ++i) {
                const double y = grid.face_centre(0, {i, j, k})[1];
                const double exact = -4.0 * u_max * y * (1.0 - y);
                max_error = std::max(max_error, std::abs(sim.fluid().u[0]({i, j, k}) - exact));
            }
            for (int i = 1; i < grid.cells(0); ++i) {
                const double gradient =
                    (sim.fluid().p({i, j, k}) - sim.fluid().p({i - 1, j, k})) / grid.spacing(0);
                max_gradient_error =
                    std::max(max_gradient_error, std::abs(gradient - 8.0 * mu * u_max));
            }
        }
    }
    const auto [inflow, outflow] = boundary_fluxes(grid, sim.boundary_conditions(), sim.fluid().u);
    EXPECT_LT(max_error, 1e-9);
    EXPECT_LT(max_gradient_error, 1e-8 * 8.0 * mu * u_max);
    EXPECT_NEAR(outflow, inflow, 1e-14 * inflow);
}

} // namespace
} // namespace fddem
