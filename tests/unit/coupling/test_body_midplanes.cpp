// SPDX-License-Identifier: MIT
// The planes midway between the surfaces of two close bodies (coupling/body_midplanes.hpp), for
// coupling.markers_off_between_bodies.

#include "fddem/coupling/body_midplanes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fddem {
namespace {

Particle<3> sphere(const Vec<3>& centre, double diameter)
{
    Particle<3> p;
    p.shape = Ball<3>{diameter};
    p.centre = centre;
    return p;
}

TEST(BodyMidplanes, LieHalfWayAcrossTheGapFacingTheNeighbour)
{
    // Radii 0.5 and 0.25, centres 1.0 apart along a skew direction: gap 0.25, so the plane is
    // 0.5 + 0.125 from the first centre and 0.25 + 0.125 from the second, each facing the other.
    const Vec<3> n = Vec<3>(1.0, 2.0, 2.0) / 3.0;
    const Vec<3> a(2.0, 2.0, 2.0);
    const std::vector<Particle<3>> bodies{sphere(a, 1.0), sphere(a + n, 0.5),
                                          sphere(Vec<3>(0.5, 3.5, 0.5), 1.0)}; // far away
    const PeriodicDomain<3> box{Vec<3>::Zero(), Vec<3>(4.0, 4.0, 4.0), {}};
    // reach 1.5 cells of 0.06: along n, 1.5 · 0.06 · (1 + 2 + 2)/3 = 0.15, so gaps below 0.3
    const Vec<3> spacing(0.06, 0.06, 0.06);
    const auto planes = body_midplanes<3>(bodies, box, spacing, 1.5);
    ASSERT_EQ(planes.size(), 3u);
    ASSERT_EQ(planes[0].size(), 1u);
    ASSERT_EQ(planes[1].size(), 1u);
    EXPECT_TRUE(planes[2].empty());
    EXPECT_NEAR((planes[0][0].normal - n).norm(), 0.0, 1e-15);
    EXPECT_NEAR(planes[0][0].distance, 0.625, 1e-15);
    EXPECT_NEAR(planes[0][0].reach, 0.15, 1e-15);
    EXPECT_NEAR((planes[1][0].normal + n).norm(), 0.0, 1e-15);
    EXPECT_NEAR(planes[1][0].distance, 0.375, 1e-15);
    // The two planes are the same plane: the foot of each on its line of centres is one point.
    const Vec<3> foot_a = a + planes[0][0].distance * planes[0][0].normal;
    const Vec<3> foot_b = (a + n) + planes[1][0].distance * planes[1][0].normal;
    EXPECT_NEAR((foot_a - foot_b).norm(), 0.0, 1e-15);
    // A gap of twice the reach or more has no plane: with 1.2 cells the reach is 0.12, with 1.3
    // 0.13, against half the gap 0.125.
    EXPECT_TRUE(body_midplanes<3>(bodies, box, spacing, 1.2)[0].empty());
    EXPECT_FALSE(body_midplanes<3>(bodies, box, spacing, 1.3)[0].empty());
}

TEST(BodyMidplanes, FindTheNeighbourAcrossAPeriodicSide)
{
    // Two unit spheres 0.1 apart across x = 0 of a box periodic in x: the plane faces −x from
    // the sphere near x = 4 only through the periodic side; in a box with walls there is none.
    const std::vector<Particle<3>> bodies{sphere(Vec<3>(0.55, 1.0, 1.0), 1.0),
                                          sphere(Vec<3>(3.45, 1.0, 1.0), 1.0)};
    const PeriodicDomain<3> periodic{Vec<3>::Zero(), Vec<3>(4.0, 4.0, 4.0), {true, false, false}};
    const Vec<3> spacing(0.1, 0.1, 0.1);
    const auto planes = body_midplanes<3>(bodies, periodic, spacing, 1.5);
    ASSERT_EQ(planes[0].size(), 1u);
    ASSERT_EQ(planes[1].size(), 1u);
    EXPECT_NEAR((planes[0][0].normal - Vec<3>(-1.0, 0.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(planes[0][0].distance, 0.55, 1e-12);
    EXPECT_NEAR((planes[1][0].normal - Vec<3>(1.0, 0.0, 0.0)).norm(), 0.0, 1e-12);
    const PeriodicDomain<3> walled{Vec<3>::Zero(), Vec<3>(4.0, 4.0, 4.0), {}};
    EXPECT_TRUE(body_midplanes<3>(bodies, walled, spacing, 1.5)[0].empty());
}

TEST(BodyMidplanes, AMarkerIsWithinReachOnlyNearItsSideOfAPlane)
{
    const std::vector<Midplane<2>> planes{{Vec<2>(1.0, 0.0), 1.2, 0.35}};
    const std::vector<Midplane<2>> shorter{{Vec<2>(1.0, 0.0), 1.2, 0.25}};
    EXPECT_TRUE(reaches_midplane<2>(Vec<2>(0.9, 0.0), planes));   // 0.3 from it
    EXPECT_FALSE(reaches_midplane<2>(Vec<2>(0.8, 0.0), planes));  // 0.4 from it
    EXPECT_FALSE(reaches_midplane<2>(Vec<2>(0.9, 0.0), shorter)); // reach shorter
    EXPECT_FALSE(reaches_midplane<2>(Vec<2>(-0.9, 0.0), planes)); // far side of the body
    EXPECT_TRUE(reaches_midplane<2>(Vec<2>(1.5, 0.0), planes));   // beyond the plane
    EXPECT_FALSE(reaches_midplane<2>(Vec<2>(0.9, 0.0), {}));      // no neighbour
}

TEST(BodyMidplanes, TheReachFollowsTheKernelsBoxAlongTheNormal)
{
    // Along an axis the wall's reach (cells of that axis); on a diagonal √2 (2D) or √3 (3D)
    // times it, as far as a box-shaped support reaches along the normal.
    const Vec<2> spacing(0.1, 0.2);
    EXPECT_NEAR(reach_along<2>(Vec<2>(1.0, 0.0), spacing, 1.5), 0.15, 1e-15);
    EXPECT_NEAR(reach_along<2>(Vec<2>(0.0, -1.0), spacing, 1.5), 0.3, 1e-15);
    const double c = std::sqrt(0.5);
    EXPECT_NEAR(reach_along<2>(Vec<2>(c, -c), Vec<2>(0.1, 0.1), 1.5), 0.15 * std::sqrt(2.0), 1e-15);
    const Vec<3> n = Vec<3>(1.0, 1.0, 1.0).normalized();
    EXPECT_NEAR(reach_along<3>(n, Vec<3>(0.1, 0.1, 0.1), 1.5), 0.15 * std::sqrt(3.0), 1e-15);
}

} // namespace
} // namespace fddem
