// SPDX-License-Identifier: MIT
// The DEM's Verlet neighbour list (contact/neighbour_list.hpp): while bodies wander, every pair
// and every wall closer than the margin is among its candidates at every refresh, as brute
// force finds them, and the list is rebuilt only when some body has moved half the skin.

#include "fddem/contact/neighbour_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class NeighbourListTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(NeighbourListTest, Dimensions);

template <int Dim>
struct Wander {
    std::vector<Vec<Dim>> centres;
    std::vector<double> radii;
};

/// `n` bodies of radius 0.03-0.06 at random in the box [0, length).
template <int Dim>
Wander<Dim> random_bodies(int n, const Vec<Dim>& length, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> r(0.03, 0.06);
    Wander<Dim> w;
    for (int i = 0; i < n; ++i) {
        Vec<Dim> c;
        for (int d = 0; d < Dim; ++d) {
            c[d] = 0.1 + (length[d] - 0.2) * unit(random);
        }
        w.centres.push_back(c);
        w.radii.push_back(r(random));
    }
    return w;
}

TYPED_TEST(NeighbourListTest, NeverMissesAContactOrANearMissWhileBodiesMove)
{
    constexpr int Dim = TypeParam::value;
    const double margin = 0.01;
    const double largest = 0.06;
    const double skin = 0.04;
    const Vec<Dim> origin = Vec<Dim>::Zero();
    Vec<Dim> length = Vec<Dim>::Constant(Dim == 2 ? 2.0 : 0.8);
    length[1] *= 2.0;
    CellList<Dim> cells(origin, length, 2.0 * largest + margin + skin);
    NeighbourList<Dim> list(margin, largest, cells);
    EXPECT_NEAR(list.skin(), skin, 1e-15);
    std::array<bool, Dim> walls{};
    walls.fill(true);
    list.set_walls(origin, length, walls);

    Wander<Dim> w = random_bodies<Dim>(400, length, 3);
    std::mt19937 random(5);
    std::normal_distribution<double> step(0.0, 0.002);
    int refreshes = 0;
    int near_pairs = 0;
    int near_walls = 0;
    for (int s = 0; s < 300; ++s) {
        for (Vec<Dim>& c : w.centres) {
            for (int d = 0; d < Dim; ++d) {
                c[d] += step(random);
            }
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
            for (int d = 0; d < Dim; ++d) {
                for (int side = 0; side < 2; ++side) {
                    const double gap = side == 0
                                           ? w.centres[i][d] - origin[d] - w.radii[i]
                                           : origin[d] + length[d] - w.centres[i][d] - w.radii[i];
                    if (gap < margin) {
                        ++near_walls;
                        const auto& candidates = list.walls();
                        ASSERT_TRUE(std::any_of(candidates.begin(), candidates.end(),
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
    // A body moves about 0.002·√Dim per refresh: half the skin after tens of refreshes for a
    // typical body, sooner for the fastest of 400; far fewer builds than refreshes.
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
