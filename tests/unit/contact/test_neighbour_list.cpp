// SPDX-License-Identifier: MIT
// The DEM's Verlet neighbour list (contact/neighbour_list.hpp): while bodies wander, every pair
// and every wall closer than the margin is among its candidates at every refresh, as brute
// force finds them, and the list is rebuilt only when some body has moved half the skin.

#include "fddem/contact/neighbour_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace fddem {
namespace {

struct Wander {
    std::vector<Vec<2>> centres;
    std::vector<double> radii;
};

Wander random_bodies(int n, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> x(0.1, 1.9);
    std::uniform_real_distribution<double> y(0.1, 3.9);
    std::uniform_real_distribution<double> r(0.03, 0.06);
    Wander w;
    for (int i = 0; i < n; ++i) {
        w.centres.emplace_back(x(random), y(random));
        w.radii.push_back(r(random));
    }
    return w;
}

TEST(NeighbourList, NeverMissesAContactOrANearMissWhileBodiesMove)
{
    const double margin = 0.01;
    const double largest = 0.06;
    const double skin = 0.04;
    const Vec<2> origin = Vec<2>::Zero();
    const Vec<2> length(2.0, 4.0);
    CellList<2> cells(origin, length, 2.0 * largest + margin + skin);
    NeighbourList<2> list(margin, largest, cells);
    EXPECT_NEAR(list.skin(), skin, 1e-15);
    list.set_walls(origin, length, {true, true});

    Wander w = random_bodies(400, 3);
    std::mt19937 random(5);
    std::normal_distribution<double> step(0.0, 0.002);
    int refreshes = 0;
    int near_pairs = 0;
    int near_walls = 0;
    for (int s = 0; s < 300; ++s) {
        for (Vec<2>& c : w.centres) {
            c += Vec<2>(step(random), step(random));
        }
        list.refresh(w.centres, w.radii, cells);
        ++refreshes;
        const auto& pairs = list.pairs();
        for (std::size_t i = 0; i < w.centres.size(); ++i) {
            for (std::size_t j = i + 1; j < w.centres.size(); ++j) {
                const double gap = (w.centres[i] - w.centres[j]).norm() - w.radii[i] - w.radii[j];
                if (gap < margin) {
                    ++near_pairs;
                    ASSERT_TRUE(std::binary_search(
                        pairs.begin(), pairs.end(),
                        std::make_pair(static_cast<int>(i), static_cast<int>(j))))
                        << "pair " << i << "-" << j << " at gap " << gap << ", refresh " << s;
                }
            }
            for (int d = 0; d < 2; ++d) {
                for (int side = 0; side < 2; ++side) {
                    const double gap = side == 0
                                           ? w.centres[i][d] - origin[d] - w.radii[i]
                                           : origin[d] + length[d] - w.centres[i][d] - w.radii[i];
                    if (gap < margin) {
                        ++near_walls;
                        const auto& walls = list.walls();
                        ASSERT_TRUE(std::any_of(walls.begin(), walls.end(),
                                                [&](const auto& c) {
                                                    return c.body == static_cast<int>(i) &&
                                                           c.axis == d && c.side == side;
                                                }))
                            << "body " << i << " wall " << d << "/" << side << ", refresh " << s;
                    }
                }
            }
        }
    }
    EXPECT_GT(near_pairs, 100); // the test saw contacts and near misses to check
    EXPECT_GT(near_walls, 10);
    // Each body moves 0.002·√2 per refresh on average: half the skin after about 50 refreshes
    // for a typical body, sooner for the fastest of 400; far fewer builds than refreshes.
    EXPECT_LT(list.builds(), refreshes / 3);
    EXPECT_GT(list.builds(), 1);
}

TEST(NeighbourList, WithoutSkinItRebuildsEveryTime)
{
    const Vec<2> origin = Vec<2>::Zero();
    const Vec<2> length(1.0, 1.0);
    CellList<2> cells(origin, length, 0.2); // exactly 2 r + margin
    NeighbourList<2> list(0.0, 0.1, cells);
    EXPECT_EQ(list.skin(), 0.0);
    const std::vector<Vec<2>> centres{Vec<2>(0.3, 0.3), Vec<2>(0.45, 0.3)};
    const std::vector<double> radii{0.1, 0.1};
    EXPECT_TRUE(list.refresh(centres, radii, cells));
    EXPECT_TRUE(list.refresh(centres, radii, cells));
    ASSERT_EQ(list.pairs().size(), 1U);
    EXPECT_EQ(list.pairs().front(), std::make_pair(0, 1));
}

} // namespace
} // namespace fddem
