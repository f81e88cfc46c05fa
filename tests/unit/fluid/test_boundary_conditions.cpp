// SPDX-License-Identifier: MIT
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fddem {
namespace {

TEST(BoundaryConditions, TangentialGhostContinuesTheQuadraticThroughTheWallValue)
{
    // u(y) = 1 + 2y − 3y² on a sliding bottom wall (u_w = u(0) = 1) and a top wall moving at
    // u(1) = 0: the first ghost must equal the quadratic at y = −h/2 and 1 + h/2.
    const MacGrid<2> grid({4, 8}, Vec<2>::Zero(), Vec<2>::Ones());
    auto bc = BoundaryConditions<2>::closed_box();
    bc.wall_velocity[1][0] = Vec<2>(1.0, 0.0);
    bc.wall_velocity[1][1] = Vec<2>(0.0, 0.0);
    const auto profile = [](double y) { return 1.0 + 2.0 * y - 3.0 * y * y; };
    FaceField<2> u(grid);
    for_each_index(grid.face_box(0),
                   [&](const Index<2>& c) { u[0](c) = profile(grid.face_centre(0, c)[1]); });
    fill_velocity_ghosts(grid, bc, u);
    const double h = grid.spacing(1);
    EXPECT_NEAR(u[0]({2, -1}), profile(-0.5 * h), 1e-14);
    EXPECT_NEAR(u[0]({2, 8}), profile(1.0 + 0.5 * h), 1e-14);
    // Wall-normal faces carry the wall's normal velocity (zero).
    EXPECT_EQ(u[1]({1, 0}), 0.0);
    EXPECT_EQ(u[1]({1, 8}), 0.0);
}

TEST(BoundaryConditions, PeriodicGhostsAreImages)
{
    const MacGrid<2> grid({5, 4}, Vec<2>::Zero(), Vec<2>::Ones(), {true, false});
    auto bc = BoundaryConditions<2>::closed_box();
    bc.is_periodic = {true, false};
    FaceField<2> u(grid);
    CellField<2> p(grid);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) {
        u[0](c) = 10.0 * c[0] + c[1];
        p(c) = 100.0 + 10.0 * c[0] + c[1];
    });
    fill_velocity_ghosts(grid, bc, u);
    fill_cell_ghosts(grid, bc, p);
    for (int j = 0; j < 4; ++j) {
        EXPECT_EQ(u[0]({-1, j}), u[0]({4, j}));
        EXPECT_EQ(u[0]({5, j}), u[0]({0, j})); // face n is face 0
        EXPECT_EQ(u[0]({-2, j}), u[0]({3, j}));
        EXPECT_EQ(p({-1, j}), p({4, j}));
        EXPECT_EQ(p({5, j}), p({0, j}));
    }
    // Walls in y: zero normal gradient of p.
    EXPECT_EQ(p({2, -1}), p({2, 0}));
    EXPECT_EQ(p({2, 4}), p({2, 3}));
}

TEST(BoundaryConditions, UnknownFacesExcludeWallFacesOnly)
{
    const MacGrid<3> grid({4, 5, 6}, Vec<3>::Zero(), Vec<3>::Ones(), {false, true, false});
    auto bc = BoundaryConditions<3>::closed_box();
    bc.is_periodic = {false, true, false};
    EXPECT_EQ(unknown_faces(grid, bc, 0).size(), static_cast<std::size_t>(3 * 5 * 6));
    EXPECT_EQ(unknown_faces(grid, bc, 1).size(), static_cast<std::size_t>(4 * 5 * 6));
    EXPECT_EQ(unknown_faces(grid, bc, 2).size(), static_cast<std::size_t>(4 * 5 * 5));
}

TEST(BoundaryConditions, ParabolicInflowAndOutflowCarryTheSameVolumeFlux)
{
    // Inflow on x_low (parabola, maximum 1.5), outflow on x_high, walls in y; an interior
    // field with an arbitrary flux: the outflow takes the last interior faces' velocity plus
    // one uniform correction, after which inflow and outflow fluxes agree to round-off.
    const MacGrid<2> grid({8, 10}, Vec<2>::Zero(), Vec<2>(2.0, 1.0));
    auto bc = BoundaryConditions<2>::closed_box();
    bc.kind[0] = {BoundaryKind::inflow, BoundaryKind::outflow};
    bc.inflow = {InflowShape::parabolic, 1.5};
    FaceField<2> u(grid);
    for_each_index(grid.face_box(0), [&](const Index<2>& c) {
        u[0](c) = 0.3 + 0.1 * c[1]; // not the inflow's flux
    });
    fill_velocity_ghosts(grid, bc, u);
    for (int j = 0; j < 10; ++j) {
        const double y = grid.face_centre(0, {0, j})[1];
        EXPECT_DOUBLE_EQ(u[0]({0, j}), 1.5 * 4.0 * y * (1.0 - y));
    }
    const double correction = set_outflow_velocity(grid, bc, u);
    const auto [inflow, outflow] = boundary_fluxes(grid, bc, u);
    EXPECT_NEAR(outflow, inflow, 1e-15);
    for (int j = 0; j < 10; ++j) {
        EXPECT_DOUBLE_EQ(u[0]({8, j}), u[0]({7, j}) + correction);
        EXPECT_EQ(u[0]({9, j}), u[0]({8, j})); // zero gradient beyond the outflow
        EXPECT_EQ(u[1]({8, j}), u[1]({7, j}));
    }
    // The inflow's tangential velocity is zero: the quadratic ghost about 0.
    fill_velocity_ghosts(grid, bc, u);
    for (int j = 1; j < 10; ++j) {
        EXPECT_DOUBLE_EQ(u[1]({-1, j}), (-6.0 * u[1]({0, j}) + u[1]({1, j})) / 3.0);
    }
}

TEST(BoundaryConditions, HighSideInflowPointsIntoTheBox)
{
    const MacGrid<3> grid({4, 4, 4}, Vec<3>::Zero(), Vec<3>::Ones(), {true, false, false});
    auto bc = BoundaryConditions<3>::closed_box();
    bc.kind[2] = {BoundaryKind::outflow, BoundaryKind::inflow};
    bc.is_periodic = {true, false, false};
    bc.inflow = {InflowShape::parabolic, 2.0};
    // Parabolic over the walled transverse axis y only (x is periodic): 2 · 4 · ½ · ½ = 2.
    EXPECT_DOUBLE_EQ(inflow_velocity(grid, bc, 2, 1, Vec<3>(0.3, 0.5, 1.0)), -2.0);
    EXPECT_DOUBLE_EQ(inflow_velocity(grid, bc, 2, 1, Vec<3>(0.3, 0.25, 1.0)), -1.5);
}

} // namespace
} // namespace fddem
