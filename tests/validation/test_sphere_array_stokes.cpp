// SPDX-License-Identifier: MIT
// The 3D coupling against an exact solution: Stokes flow through a simple cubic array of fixed
// spheres, driven by a uniform force on the fluid.
#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "support/run_to_end.hpp"
#include "support/stokes_array.hpp"

namespace fddem {
namespace {

TEST(SphereArrayStokes, MeanVelocityForTheForceIsSanganiAcrivosWithTheRetractedMarkers)
{
    // d = 1 in a periodic cube of side 4 (φ = 0.0082), d/h = 8, μ = ρ = 1, f = 0.01: Re = 0.04.
    // Implicit Euler with Δt = 0.5 to t = 30 (the flow settles in a few time units; the
    // unconverged marker constraint makes it creep on for about 20, docs/method.md §4).
    const CaseConfig config = read_case_string(R"([domain]
size = [4.0, 4.0, 4.0]
cells = [32, 32, 32]
periodic = [true, true, true]
[fluid]
density = 1.0
viscosity = 1.0
body_force = [0.01, 0.0, 0.0]
[[bodies]]
shape = "sphere"
diameter = 1.0
density = 1.0
position = [2.0, 2.0, 2.0]
motion = "fixed"
[coupling]
markers = "retracted"
[time]
dt = 0.5
end = 30.0
)",
                                               "sphere_array.toml");
    Simulation<3> sim(config);
    test::run_to_end(sim);
    const double mean_u = test::mean_x_velocity(sim);
    const double pi = std::numbers::pi;
    const double phi = pi / 6.0 / 64.0;
    const double force = 0.01 * 64.0; // the whole cube's drive, held by the sphere
    const double exact = force / (6.0 * pi * 0.5 * test::sphere_array_k(phi));
    std::printf("mean u / exact = %.4f (Sangani & Acrivos 1982, K = %.4f); sphere force / drive "
                "= %.6f\n",
                mean_u / exact, test::sphere_array_k(phi), sim.bodies().front().force[0] / force);
    // Measured 1.013. 3 % is the first-order interface error at d/h = 8 (the 2D towed cylinder
    // at D/16 is 1.2 % off); the paper's layout gives 1.25 here (not asserted: docs/method.md).
    EXPECT_NEAR(mean_u / exact, 1.0, 0.03);
    // The force balance: at steady state the sphere holds the drive of the whole cube.
    EXPECT_NEAR(sim.bodies().front().force[0] / force, 1.0, 2e-3);
}

} // namespace
} // namespace fddem
