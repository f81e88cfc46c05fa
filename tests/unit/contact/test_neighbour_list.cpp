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

/// Bodies wander (and are wrapped back into the box across its periodic sides, as the
/// simulation does after each step); at every refresh each pair and each wall closer than the
/// margin must be a candidate.
template <int Dim>
void check_never_misses(const std::array<bool, Dim>& periodic)
{
    const double margin = 0.01;
    const double largest = 0.06;
    const double skin = 0.04;
    const Vec<Dim> origin = Vec<Dim>::Zero();
    Vec<Dim> length = Vec<Dim>::Constant(Dim == 2 ? 2.0 : 0.8);
    length[1] *= 2.0;
    const PeriodicDomain<Dim> domain{origin, length, periodic};
    CellList<Dim> cells(domain, 2.0 * largest + margin + skin);
    NeighbourList<Dim> list(margin, largest, cells);
    EXPECT_NEAR(list.skin(), skin, 1e-15);
    std::array<bool, Dim> walls{};
    for (std::size_t d = 0; d < walls.size(); ++d) {
        walls[d] = !periodic[d];
    }
    list.set_walls(origin, length, walls);

    Wander<Dim> w = random_bodies<Dim>(400, length, 3);
    if (domain.has_periodic_axis()) {
        // Spread over the whole length of a periodic axis (there are no walls to keep off),
        // and closer to the walls of the others (fewer walls are left to come near).
        for (Vec<Dim>& c : w.centres) {
            for (int d = 0; d < Dim; ++d) {
                const double margin_from_side = periodic[static_cast<std::size_t>(d)] ? 0.0 : 0.05;
                c[d] = margin_from_side +
                       (c[d] - 0.1) * (length[d] - 2.0 * margin_from_side) / (length[d] - 0.2);
            }
        }
    }
    std::mt19937 random(5);
    std::normal_distribution<double> step(0.0, 0.002);
    int refreshes = 0;
    int near_pairs = 0;
    int near_walls = 0;
    int across_seam = 0;
    for (int s = 0; s < 300; ++s) {
        for (Vec<Dim>& c : w.centres) {
            for (int d = 0; d < Dim; ++d) {
                c[d] += step(random);
            }
            c = domain.wrap(c);
        }
        list.refresh(w.centres, w.radii, cells);
        ++refreshes;
        const auto& pairs = list.pairs();
        for (std::size_t i = 0; i < w.centres.size(); ++i) {
            for (std::size_t j = i + 1; j < w.centres.size(); ++j) {
                const Vec<Dim> apart = w.centres[i] - w.centres[j];
                const double gap = domain.minimum_image(apart).norm() - w.radii[i] - w.radii[j];
                if (gap < margin) {
                    ++near_pairs;
                    across_seam += domain.minimum_image(apart) != apart ? 1 : 0;
                    ASSERT_TRUE(std::binary_search(
                        pairs.begin(), pairs.end(),
                        std::make_pair(static_cast<int>(i), static_cast<int>(j))))
                        << "pair " << i << "-" << j << " at gap " << gap << ", refresh " << s;
                }
            }
            for (int d = 0; d < Dim; ++d) {
                for (int side = 0; side < 2 && walls[static_cast<std::size_t>(d)]; ++side) {
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
        for (const WallCandidate& c : list.walls()) {
            EXPECT_TRUE(walls[static_cast<std::size_t>(c.axis)]); // no wall on a periodic axis
        }
    }
    EXPECT_GT(near_pairs, 100); // the test saw contacts and near misses to check
    EXPECT_GT(near_walls, 10);
    EXPECT_EQ(across_seam > 10, domain.has_periodic_axis()); // and pairs across the seam
    // A body moves about 0.002·√Dim per refresh: half the skin after tens of refreshes for a
    // typical body, sooner for the fastest of 400; far fewer builds than refreshes.
    EXPECT_LT(list.builds(), refreshes / 3);
    EXPECT_GT(list.builds(), 1);
}

TYPED_TEST(NeighbourListTest, NeverMissesAContactOrANearMissWhileBodiesMove)
{
    constexpr int Dim = TypeParam::value;
    check_never_misses<Dim>({});
}

TYPED_TEST(NeighbourListTest, NeverMissesAContactAcrossAPeriodicSide)
{
    constexpr int Dim = TypeParam::value;
    std::array<bool, Dim> periodic{};
    periodic[0] = true; // a side across which bodies wander, and walls across the others
    check_never_misses<Dim>(periodic);
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
