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

TYPED_TEST(CellListTest, FindsExactlyThePairsBruteForceFinds)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(12345);
    const Vec<Dim> origin = Vec<Dim>::Constant(-1.0);
    const Vec<Dim> length = Vec<Dim>::Constant(4.0);
    std::uniform_real_distribution<double> coordinate(-1.0, 3.0);
    std::vector<Vec<Dim>> centres(1500);
    for (auto& c : centres) {
        for (int d = 0; d < Dim; ++d) {
            c[d] = coordinate(rng);
        }
    }
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

} // namespace
} // namespace fddem
