// SPDX-License-Identifier: MIT
// Steady flow past a fixed cylinder: the drag, the lift and the recirculation behind it against
// published numbers, at two resolutions each, and the error shrinking with refinement.
//  - Re = 20 in a channel: Schäfer & Turek (1996) benchmark 2D-1 (cases/verification/
//    cylinder_re20), h = D/20 and D/40;
//  - Re = 40 in a wide tunnel: Dennis & Chang (1970), Fornberg (1980), Coutanceau & Bouard
//    (1977) (cases/verification/cylinder_re40), h = D/16 and D/32.
// References, sources and the reasons for the tolerances: the cases' reference/SOURCE.md.

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

test::CylinderWake run_case(const std::string& name, const std::string& cells, double mean_velocity,
                            double search_length)
{
    const std::string path =
        std::string(FDDEM_SOURCE_DIR) + "/cases/verification/" + name + "/case.toml";
    Simulation<2> sim(read_case(path, {"domain.cells=" + cells}));
    test::run_to_end(sim);
    test::CylinderWake wake = test::measure_cylinder_wake(sim, mean_velocity, search_length);
    EXPECT_TRUE(wake.recirculation_length.has_value());
    if (!wake.recirculation_length) {
        wake.recirculation_length = 0.0;
    }
    std::printf("%s %s: C_D %.4f  C_L %.5f  L %.5f  dp %.5f\n", name.c_str(), cells.c_str(),
                wake.drag_coefficient, wake.lift_coefficient, *wake.recirculation_length,
                wake.pressure_difference);
    return wake;
}

TEST(CylinderInChannel, SchaferTurekNumbersApproachTheBenchmarkWithRefinement)
{
    // Schäfer & Turek (1996), Table 4 (reference bounds): C_D 5.57–5.59, C_L 0.0104–0.0110,
    // L_a 0.0842–0.0852, Δp 0.1172–0.1176; the middles are the reference values here.
    const double drag = 5.58;
    const double length = 0.0847;
    const double pressure = 0.1174;
    const test::CylinderWake coarse = run_case("cylinder_re20", "[440,82]", 0.2, 0.1);
    const test::CylinderWake fine = run_case("cylinder_re20", "[880,164]", 0.2, 0.1);
    // Measured at D/40: C_D 5.441 (−2.5 %), L_a 0.0810 (−4.4 %), Δp 0.1154 (−1.7 %),
    // C_L 0.0095 (−11 %; the 0.0105 of Gauss–Seidel alone at tolerance 1e-4 was not converged:
    // both momentum solvers give 0.0095 at tolerance 1e-6). The bounds leave about a third of
    // the error for round-off-level changes.
    EXPECT_NEAR(fine.drag_coefficient / drag, 1.0, 0.035);
    EXPECT_NEAR(*fine.recirculation_length / length, 1.0, 0.06);
    EXPECT_NEAR(fine.pressure_difference / pressure, 1.0, 0.03);
    EXPECT_GT(fine.lift_coefficient, 0.0088);
    EXPECT_LT(fine.lift_coefficient, 0.0115);
    // First order in h (the diffuse interface): the errors of C_D and L_a fall by about half
    // from D/20 to D/40 (measured 0.54 and 0.43).
    EXPECT_LT(std::abs(fine.drag_coefficient - drag),
              0.7 * std::abs(coarse.drag_coefficient - drag));
    EXPECT_LT(std::abs(*fine.recirculation_length - length),
              0.7 * std::abs(*coarse.recirculation_length - length));
}

TEST(CylinderInTunnel, ReynoldsFortyDragAndEddyLengthNearTheUnboundedValues)
{
    const test::CylinderWake coarse = run_case("cylinder_re40", "[384,256]", 1.0, 4.0);
    const test::CylinderWake fine = run_case("cylinder_re40", "[768,512]", 1.0, 4.0);
    // Unbounded references (reference/SOURCE.md): C_D 1.498 (Fornberg 1980) – 1.522 (Dennis &
    // Chang 1970); eddy length L/D 2.13 (Coutanceau & Bouard 1977, experiment) – 2.24
    // (Fornberg) – 2.345 (Dennis & Chang). Measured: D/16 C_D 1.585, L/D 1.867; D/32 C_D 1.630,
    // L/D 2.087.
    // Eddy length: within 10 % below the shortest and 5 % above the longest reference, and the
    // distance to Fornberg's value falls by more than half with h (measured 0.41).
    EXPECT_GT(*fine.recirculation_length, 0.9 * 2.13);
    EXPECT_LT(*fine.recirculation_length, 1.05 * 2.345);
    EXPECT_LT(std::abs(*fine.recirculation_length - 2.24),
              0.5 * std::abs(*coarse.recirculation_length - 2.24));
    // Drag: the tunnel's walls (blockage D/W = 1/16) raise it above the unbounded value —
    // fddem measured +5.7 % (+5.6 %) from W = 32 D to 16 D at D/16 (D/32) — while the diffuse
    // interface lowers it (−2.5 % at D/40 in the Re 20 benchmark). So it must lie above the
    // unbounded references and below Dennis & Chang's value raised by the measured blockage
    // effect and 5 % more. C_D rises with refinement (1.585 → 1.630) as the body's effective
    // size grows: this test cannot show the error to the unbounded value shrinking (the 32 D
    // tunnel at D/32, 8 minutes, gave 1.543: reference/SOURCE.md).
    EXPECT_GT(fine.drag_coefficient, 1.498);
    EXPECT_LT(fine.drag_coefficient, 1.522 * 1.057 * 1.05);
    EXPECT_GT(fine.drag_coefficient, coarse.drag_coefficient);
    // The flow is symmetric about the axis: no lift.
    EXPECT_LT(std::abs(fine.lift_coefficient), 1e-3);
}

} // namespace
} // namespace fddem
