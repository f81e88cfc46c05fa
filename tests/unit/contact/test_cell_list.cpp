// SPDX-License-Identifier: MIT
#include "fddem/contact/cell_list.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class CellListTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(CellListTest, Dimensions);

/// `n` centres at random in the box [−1, 3)^Dim.
template <int Dim>
std::vector<Vec<Dim>> random_centres(std::size_t n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 3.0);
    std::vector<Vec<Dim>> centres(n);
    for (auto& c : centres) {
        for (int d = 0; d < Dim; ++d) {
            c[d] = coordinate(rng);
        }
    }
    return centres;
}

TYPED_TEST(CellListTest, FindsExactlyThePairsBruteForceFinds)
{
    constexpr int Dim = TypeParam::value;
    const Vec<Dim> origin = Vec<Dim>::Constant(-1.0);
    const Vec<Dim> length = Vec<Dim>::Constant(4.0);
    std::vector<Vec<Dim>> centres = random_centres<Dim>(1500, 12345);
    // A few bodies just outside the box must still be found (clamped into edge cells).
    centres[0] = Vec<Dim>::Constant(-1.01);
    centres[1] = Vec<Dim>::Constant(-0.99);
    const double range = Dim == 2 ? 0.1 : 0.3;
    CellList<Dim> list(origin, length, range);
    std::vector<std::pair<int, int>> pairs;
    list.find_pairs(centres, pairs);
    const auto expected = brute_force_pairs<Dim>(centres, range);
    EXPECT_GT(expected.size(), 100U); // the test must exercise many pairs
    EXPECT_EQ(pairs, expected);
}

TYPED_TEST(CellListTest, FindsPairsAcrossPeriodicSidesAsBruteForceWithNearestImages)
{
    constexpr int Dim = TypeParam::value;
    const Vec<Dim> origin = Vec<Dim>::Constant(-1.0);
    const Vec<Dim> length = Vec<Dim>::Constant(4.0);
    std::vector<Vec<Dim>> centres = random_centres<Dim>(Dim == 2 ? 1500 : 600, 54321);
    // Bodies a little outside the box are found too (wrapped on periodic axes).
    centres[0] = Vec<Dim>::Constant(-1.01);
    centres[1] = Vec<Dim>::Constant(2.99);
    // Ranges giving many cells per axis, and 2 and 1 (where one cell is its own neighbour
    // across the seam: each pair must still come once).
    for (const double range : {Dim == 2 ? 0.1 : 0.3, 1.5, 2.5}) {
        for (int axis = 0; axis < Dim; ++axis) {
            PeriodicDomain<Dim> domain{origin, length, {}};
            domain.is_periodic[static_cast<std::size_t>(axis)] = true;
            domain.is_periodic[0] = true; // axis 0 alone, or with another
            CellList<Dim> list(domain, range);
            std::vector<std::pair<int, int>> pairs;
            list.find_pairs(centres, pairs);
            const auto expected = brute_force_pairs<Dim>(centres, range, domain);
            const auto without_images = brute_force_pairs<Dim>(centres, range);
            // the test must exercise pairs across the seam
            EXPECT_GT(expected.size(), without_images.size()) << range;
            EXPECT_EQ(pairs, expected) << "range " << range << ", axis " << axis;
        }
    }
}

TEST(CellList, APairAcrossThePeriodicSideIsFoundAtItsNearestDistance)
{
    const PeriodicDomain<2> channel{Vec<2>::Zero(), Vec<2>(2.0, 1.0), {true, false}};
    CellList<2> list(channel, 0.3);
    // 0.05 from the left side and 0.1 from the right: 0.15 apart across it. Two bodies by the
    // bottom and top walls are 0.96 apart: y is not periodic.
    const std::vector<Vec<2>> centres{Vec<2>(0.05, 0.5), Vec<2>(1.9, 0.5), Vec<2>(1.0, 0.02),
                                      Vec<2>(1.0, 0.98)};
    std::vector<std::pair<int, int>> pairs;
    list.find_pairs(centres, pairs);
    EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 1}}));
}

} // namespace
} // namespace fddem
