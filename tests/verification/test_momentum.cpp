// SPDX-License-Identifier: MIT
// Momentum of fluid and body together, the system of eqs. (13)–(16): with nothing outside it (a
// box periodic both ways, no gravity) it is conserved; in a closed box only the walls take it.
// P = ρf Σ u ΔV over all faces (the fluid fills the body too) + (ρs − ρf) V U.

#include "fddem/grid/loops.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace fddem {
namespace {

/// A disk of density 2 thrown at (1, 0.5) through fluid at rest, periodic or walled.
CaseConfig thrown_disk(const std::string& periodic)
{
    return read_case_string(R"([domain]
size = [2.0, 2.0]
cells = [32, 32]
periodic = )" + periodic + R"(
[fluid]
density = 1.0
viscosity = 0.05
[[bodies]]
diameter = 0.5
density = 2.0
position = [1.0, 1.0]
velocity = [1.0, 0.5]
[contact]
model = "none"
[time]
dt = 0.01
end = 0.4
[simple]
tolerance = 1e-8
max_outer_iterations = 400
)",
                            "test");
}

/// The system's momentum (per unit depth).
Vec<2> momentum(const Simulation<2>& sim)
{
    const MacGrid<2>& grid = sim.grid();
    Vec<2> p = Vec<2>::Zero();
    for (int a = 0; a < 2; ++a) {
        const GridArray<2>& u = sim.fluid().u[a];
        double sum = 0.0;
        // Faces 0..n−1 along a: a periodic axis's face n is face 0; a wall's faces 0 and n
        // carry u = 0.
        for_each_cell_in_vtk_order(grid.cell_box(), [&](const Index<2>& c) { sum += u(c); });
        p[a] = sum * grid.cell_volume();
    }
    p *= sim.fluid_properties().density;
    const Particle<2>& body = sim.bodies().front();
    return p + (body.density - sim.fluid_properties().density) * body.volume() * body.velocity;
}

TEST(Momentum, ConservedWithNothingOutsideTheSystem)
{
    Simulation<2> sim(thrown_disk("[true, true]"));
    const Vec<2> initial = momentum(sim);
    double worst = 0.0;
    StepReport report;
    do {
        report = sim.advance();
        worst = std::max(worst, (momentum(sim) - initial).norm() / initial.norm());
    } while (!sim.is_finished(report));
    const Vec<2> u = sim.bodies().front().velocity;
    std::printf("periodic: P0 = (%.6f, %.6f), worst relative change %.3e; disk U = (%.4f, %.4f)\n",
                initial[0], initial[1], worst, u[0], u[1]);
    // Conserved to the outer-iteration tolerance (1e-8): the marker forces are spread with the
    // weights they are interpolated with, so the fluid gets what the body loses.
    EXPECT_LT(worst, 1e-6);
    // Not trivially: the disk has slowed, its momentum handed to the fluid.
    EXPECT_LT(u.norm(), 0.9 * std::hypot(1.0, 0.5));
}

TEST(Momentum, AClosedBoxTakesItThroughTheWallsTheFluidKeepsNone)
{
    Simulation<2> sim(thrown_disk("[false, false]"));
    const double initial = momentum(sim).norm();
    double fluid_worst = 0.0;
    double previous = initial;
    bool is_decaying = true;
    StepReport report;
    do {
        report = sim.advance();
        const Particle<2>& body = sim.bodies().front();
        const Vec<2> body_part = (body.density - 1.0) * body.volume() * body.velocity;
        // Incompressible fluid in a rigid closed box: Σ u ΔV = 0 (the divergence theorem with
        // u·n = 0 on the walls, exact on the MAC grid: Σ u ΔV = −Σ x_c (∇·u)_c ΔV, which the
        // mass tolerance 1e-8 U/h bounds by about 1e-5 P0 here).
        fluid_worst = std::max(fluid_worst, (momentum(sim) - body_part).norm() / initial);
        const double now = momentum(sim).norm();
        is_decaying = is_decaying && now <= previous * (1.0 + 1e-9);
        previous = now;
    } while (!sim.is_finished(report));
    std::printf("closed box: |P| %.6f -> %.6f, worst fluid momentum / P0 %.3e\n", initial, previous,
                fluid_worst);
    EXPECT_LT(fluid_worst, 1e-5);
    EXPECT_TRUE(is_decaying);
    EXPECT_LT(previous, 0.5 * initial);
}

} // namespace
} // namespace fddem
