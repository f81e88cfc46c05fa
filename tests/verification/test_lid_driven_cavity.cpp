// SPDX-License-Identifier: MIT
// Lid-driven cavity at Re = 100 against Ghia, Ghia & Shin (1982), Tables I and II.

#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "support/case_builders.hpp"
#include "support/reference_csv.hpp"

namespace fddem {
namespace {

/// u on the vertical centreline x = 0.5 at height y (u-faces at x = i h; y linear between
/// cell centres, wall values at y = 0 and 1).
double u_on_vertical_centerline(const Simulation<2>& sim, double y)
{
    const auto& grid = sim.grid();
    const int n = grid.cells(1);
    const int i = grid.cells(0) / 2;
    const double h = grid.spacing(1);
    const double s = y / h - 0.5; // cell-centre coordinate
    if (s <= 0.0) {
        return (1.0 + s) * sim.fluid().u[0](Index<2>{i, 0}) + (-s) * 0.0;
    }
    if (s >= n - 1) {
        const double t = s - (n - 1); // 0 … 0.5, wall at t = 0.5
        return (1.0 - 2.0 * t) * sim.fluid().u[0](Index<2>{i, n - 1}) + 2.0 * t * 1.0;
    }
    const int j = static_cast<int>(std::floor(s));
    const double t = s - j;
    return (1.0 - t) * sim.fluid().u[0](Index<2>{i, j}) + t * sim.fluid().u[0](Index<2>{i, j + 1});
}

double v_on_horizontal_centerline(const Simulation<2>& sim, double x)
{
    const auto& grid = sim.grid();
    const int n = grid.cells(0);
    const int j = grid.cells(1) / 2;
    const double h = grid.spacing(0);
    const double s = x / h - 0.5;
    if (s <= 0.0) {
        return (1.0 + s) * sim.fluid().u[1](Index<2>{0, j});
    }
    if (s >= n - 1) {
        const double t = s - (n - 1);
        return (1.0 - 2.0 * t) * sim.fluid().u[1](Index<2>{n - 1, j});
    }
    const int i = static_cast<int>(std::floor(s));
    const double t = s - i;
    return (1.0 - t) * sim.fluid().u[1](Index<2>{i, j}) + t * sim.fluid().u[1](Index<2>{i + 1, j});
}

/// Marches the cavity at Re 100 on 64² to its steady state (Δt = h, Courant number about 1).
std::unique_ptr<Simulation<2>> steady_cavity(StepAlgorithm algorithm)
{
    const int n = 64;
    CaseConfig config = test::cavity_config(n, 100.0, 1.0 / 64, 100.0);
    config.time.steady_tolerance = 1e-5;
    config.simple.algorithm = algorithm;
    auto sim = std::make_unique<Simulation<2>>(config);
    StepReport report;
    do {
        report = sim->advance();
        EXPECT_TRUE(report.is_converged) << "step " << sim->clock().step;
        if (algorithm == StepAlgorithm::projection) {
            EXPECT_EQ(report.outer_iterations, 1) << "step " << sim->clock().step;
        }
    } while (!sim->is_finished(report));
    return sim;
}

TEST(LidDrivenCavity, Re100At64MatchesGhiaCentrelines)
{
    const std::unique_ptr<Simulation<2>> run = steady_cavity(StepAlgorithm::simple);
    const Simulation<2>& sim = *run;
    const std::string dir = std::string(FDDEM_SOURCE_DIR) + "/cases/verification/cavity_re100/";
    double max_u = 0.0;
    for (const auto& [y, u] :
         test::read_two_columns(dir + "reference/ghia1982_u_vertical_centerline.csv")) {
        max_u = std::max(max_u, std::abs(u_on_vertical_centerline(sim, y) - u));
    }
    double max_v = 0.0;
    for (const auto& [x, v] :
         test::read_two_columns(dir + "reference/ghia1982_v_horizontal_centerline.csv")) {
        max_v = std::max(max_v, std::abs(v_on_horizontal_centerline(sim, x) - v));
    }
    RecordProperty("max_u_deviation", std::to_string(max_u));
    RecordProperty("max_v_deviation", std::to_string(max_v));
    std::printf("steps %ld time %.3f  max|u-ghia| %.5f  max|v-ghia| %.5f\n", sim.clock().step,
                sim.clock().time, max_u, max_v);
    EXPECT_LT(max_u, 0.01);
    EXPECT_LT(max_v, 0.01);
}

TEST(LidDrivenCavity, TheProjectionStepMarchesToTheSameSteadyState)
{
    // At a steady state the predictor solves the whole discrete momentum equations and the
    // projection changes nothing, so simple.algorithm = "projection" must arrive where SIMPLE's
    // outer iterations do, to the march's own tolerance.
    const std::unique_ptr<Simulation<2>> simple_run = steady_cavity(StepAlgorithm::simple);
    const std::unique_ptr<Simulation<2>> projection_run = steady_cavity(StepAlgorithm::projection);
    const Simulation<2>& simple = *simple_run;
    const Simulation<2>& projection = *projection_run;
    double largest = 0.0;
    for (const double y : {0.1, 0.3, 0.5, 0.7, 0.9, 0.97}) {
        largest = std::max(largest, std::abs(u_on_vertical_centerline(projection, y) -
                                             u_on_vertical_centerline(simple, y)));
    }
    for (const double x : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        largest = std::max(largest, std::abs(v_on_horizontal_centerline(projection, x) -
                                             v_on_horizontal_centerline(simple, x)));
    }
    std::printf("steps: simple %ld, projection %ld; centre lines apart by %.2e\n",
                simple.clock().step, projection.clock().step, largest);
    EXPECT_LT(largest, 1e-4);
}

} // namespace
} // namespace fddem
