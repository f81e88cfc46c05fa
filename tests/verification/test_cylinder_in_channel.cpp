// SPDX-License-Identifier: MIT
// Steady flow past a fixed cylinder in a channel, Schäfer & Turek (1996) benchmark 2D-1, Re = 20,
// at the coarse resolution h = D/20 (cases/verification/cylinder_re20): the inflow/outflow
// boundaries and the force on a fixed body together. The finer resolution and the trend are in
// tests/validation/test_cylinder_in_channel.cpp.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/cylinder_wake.hpp"
#include "support/run_to_end.hpp"

namespace fddem {
namespace {

TEST(CylinderInChannel, SchaferTurekDragWakeAndMassAtCoarseResolution)
{
    const std::string path =
        std::string(FDDEM_SOURCE_DIR) + "/cases/verification/cylinder_re20/case.toml";
    Simulation<2> sim(read_case(path));
    test::run_to_end(sim);
    const test::CylinderWake wake = test::measure_cylinder_wake(sim, 0.2, 0.1);
    ASSERT_TRUE(wake.recirculation_length.has_value());
    std::printf("h = D/20: C_D %.4f  C_L %.5f  L_a %.5f  dp %.5f  flux in %.15f out %.15f\n",
                wake.drag_coefficient, wake.lift_coefficient, *wake.recirculation_length,
                wake.pressure_difference, wake.inflow_flux, wake.outflow_flux);
    // Schäfer & Turek (1996), Table 4: C_D 5.57–5.59, L_a 0.0842–0.0852, Δp 0.1172–0.1176.
    // Measured at D/20: C_D 5.321 (−4.6 %), L_a 0.0760 (−10 %), Δp 0.1188 (+1.2 %), C_L 0.0097:
    // the diffuse interface makes the body hydrodynamically smaller (the towed cylinder: −5.4 %
    // at D/16). Bounds for C_D and L_a: the measured error plus about a third of it, so a real
    // change fails. Δp depends on Δt by up to 27 % at this h (reference/SOURCE.md), so its
    // bound is wider than its measured error.
    EXPECT_NEAR(wake.drag_coefficient / 5.58, 1.0, 0.06);
    EXPECT_NEAR(*wake.recirculation_length / 0.0847, 1.0, 0.14);
    EXPECT_NEAR(wake.pressure_difference / 0.1174, 1.0, 0.07);
    // The cylinder sits 0.005 below the centre line, which gives a small positive lift
    // (reference 0.0104–0.0110; measured 0.0097).
    EXPECT_GT(wake.lift_coefficient, 0.008);
    EXPECT_LT(wake.lift_coefficient, 0.013);
    // Mass: the outflow carries the inflow's flux to round-off.
    EXPECT_NEAR(wake.outflow_flux, wake.inflow_flux, 1e-13 * wake.inflow_flux);
}

TEST(CylinderInChannel, TheSurfaceRingWithTheRomaKernelMeetsTheDragAtD20)
{
    // Issue 13's 2D-1 target, C_D within 2 % of 5.58 at D/20, with one ring of markers h apart
    // 0.3 h inside the surface (Uhlmann 2005's spacing, Breugem 2012's retraction) and the
    // three-point kernel of Roma, Peskin & Berger (1999) that both used. With the hat kernel
    // the same ring gives 5.496 (−1.5 %) and the default layout 5.321 (docs/method.md §4, "The
    // surface ring's kernel at D/20"). Measured: C_D 5.581 at t = 20; L_a 0.0826 (−2.5 %). Not
    // a check: Δp between the front and back points of the surface is 0.078 (−34 %) with either
    // kernel's ring (hat 0.076), where the default layout gives 0.116: with no markers inside,
    // the pressure jump is smeared across the ring's kernel band, in which the nominal surface
    // points lie.
    const std::string path =
        std::string(FDDEM_SOURCE_DIR) + "/cases/verification/cylinder_re20/case.toml";
    Simulation<2> sim(
        read_case(path, {"time.end=20", "coupling.markers=surface", "coupling.kernel=roma3",
                         "coupling.marker_spacing_ratio=1.0"}));
    test::run_to_end(sim);
    const test::CylinderWake wake = test::measure_cylinder_wake(sim, 0.2, 0.1);
    ASSERT_TRUE(wake.recirculation_length.has_value());
    std::printf("surface ring, roma3, h = D/20: C_D %.4f  C_L %.5f  L_a %.5f  dp %.5f\n",
                wake.drag_coefficient, wake.lift_coefficient, *wake.recirculation_length,
                wake.pressure_difference);
    EXPECT_NEAR(wake.drag_coefficient / 5.58, 1.0, 0.02);
}

} // namespace
} // namespace fddem
