// SPDX-License-Identifier: MIT
// The force on a prescribed body: a cylinder towed between walls at Re = 0.1 against Faxén's
// creeping-flow drag (cases/verification/towed_cylinder_stokes).

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/run_to_end.hpp"

namespace fddem {
namespace {

const std::string towed =
    std::string(FDDEM_SOURCE_DIR) + "/cases/verification/towed_cylinder_stokes/case.toml";

/// F/(μU) at the end of the case, the grid refined `refinement` times.
double drag_coefficient(int refinement, int n_rings)
{
    CaseConfig config = read_case(towed, {"domain.cells=[" + std::to_string(64 * refinement) + "," +
                                          std::to_string(320 * refinement) + "]"});
    config.bodies.front().n_rings = n_rings;
    Simulation<2> sim(config);
    test::run_to_end(sim);
    return sim.bodies().front().force[1] / (config.fluid.viscosity * 1.0); // U = 1, drag along +y
}

TEST(TowedCylinder, DragApproachesFaxenWithRefinement)
{
    // Faxén / Happel & Brenner (paper eq. (20)): F = 4π K μ U, K(W/D = 4) = 1.747861.
    const double faxen = 4.0 * M_PI * 1.747861;
    const double coarse = drag_coefficient(1, 6); // h = D/16
    const double fine = drag_coefficient(2, 12);  // h = D/32
    std::printf("F/(muU): h = D/16 %.3f, h = D/32 %.3f, Faxen %.3f\n", coarse, fine, faxen);
    // Measured 20.77 (-5.4 %) and 21.28 (-3.1 %): the interior markers make the body slightly
    // smaller hydrodynamically; the error falls at about first order.
    EXPECT_NEAR(coarse / faxen, 1.0, 0.07);
    EXPECT_NEAR(fine / faxen, 1.0, 0.04);
    EXPECT_LT(std::abs(fine - faxen), 0.75 * std::abs(coarse - faxen));
}

} // namespace
} // namespace fddem
