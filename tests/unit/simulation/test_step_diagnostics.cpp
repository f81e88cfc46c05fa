// SPDX-License-Identifier: MIT
// The blow-up message says where the flow stopped being finite, or where the fastest fluid is.

#include "fddem/fluid/fluid_state.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/simulation/step_diagnostics.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using fddem::Vec;

TEST(LocateNonFinite, AFluidAtRestIsSaidToBeAtRestNotToMoveAtZeroNowhere)
{
    // Issue 17: "largest |u| 0 at ()".
    const fddem::MacGrid<2> grid({8, 8}, Vec<2>::Zero(), Vec<2>::Ones());
    const fddem::FluidState<2> state(grid);
    const std::string text = fddem::locate_non_finite(grid, state);
    EXPECT_EQ(text.find("()"), std::string::npos) << text;
    EXPECT_NE(text.find("the fluid at rest (|u| = 0 everywhere)"), std::string::npos) << text;
}

TEST(LocateNonFinite, AMovingFluidIsLocatedAtItsFastestFace)
{
    const fddem::MacGrid<2> grid({8, 8}, Vec<2>::Zero(), Vec<2>::Ones());
    fddem::FluidState<2> state(grid);
    state.u[1](fddem::Index<2>{2, 3}) = -4.0; // the v face below cell (2, 3): x = 0.3125, y = 0.375
    EXPECT_EQ(fddem::locate_non_finite(grid, state),
              "the momentum residual is not finite (largest |u| 4 at (0.3125, 0.375))");
}

} // namespace
