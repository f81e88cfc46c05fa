// SPDX-License-Identifier: MIT
#include "fddem/grid/mac_grid.hpp"

#include <gtest/gtest.h>

#include <type_traits>

namespace fddem {
namespace {

template <class T>
class MacGridTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(MacGridTest, Dimensions);

template <int Dim>
MacGrid<Dim> make_grid()
{
    Index<Dim> cells{};
    Vec<Dim> origin;
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = 4 + d;
        origin[d] = -1.0 + d;
        length[d] = 2.0 * (d + 1);
    }
    return MacGrid<Dim>(cells, origin, length);
}

TYPED_TEST(MacGridTest, SpacingAndVolumeFollowFromCellsAndLength)
{
    constexpr int Dim = TypeParam::value;
    const auto grid = make_grid<Dim>();
    double volume = 1.0;
    for (int d = 0; d < Dim; ++d) {
        EXPECT_DOUBLE_EQ(grid.spacing(d), 2.0 * (d + 1) / (4 + d));
        volume *= grid.spacing(d);
    }
    EXPECT_DOUBLE_EQ(grid.cell_volume(), volume);
}

TYPED_TEST(MacGridTest, LowFaceSitsHalfACellBelowTheCentre)
{
    constexpr int Dim = TypeParam::value;
    const auto grid = make_grid<Dim>();
    Index<Dim> cell{};
    cell[0] = 2;
    for (int axis = 0; axis < Dim; ++axis) {
        const Vec<Dim> c = grid.cell_centre(cell);
        const Vec<Dim> f = grid.face_centre(axis, cell);
        EXPECT_DOUBLE_EQ(c[axis] - f[axis], 0.5 * grid.spacing(axis));
        // the first face of axis 0 lies on the box's low side
        Index<Dim> first{};
        EXPECT_DOUBLE_EQ(grid.face_centre(axis, first)[axis], grid.origin()[axis]);
    }
}

TYPED_TEST(MacGridTest, OffsetsAreUniqueAndNeighboursAreOneStrideApart)
{
    constexpr int Dim = TypeParam::value;
    const auto grid = make_grid<Dim>();
    const Box<Dim> storage = grid.storage_box();
    EXPECT_EQ(storage.size(), grid.storage_size());
    EXPECT_EQ(grid.offset(storage.lo), 0);
    Index<Dim> last = storage.hi;
    for (auto& x : last) {
        --x;
    }
    EXPECT_EQ(grid.offset(last), static_cast<std::ptrdiff_t>(grid.storage_size()) - 1);
    const Index<Dim> cell{};
    for (int axis = 0; axis < Dim; ++axis) {
        EXPECT_EQ(grid.offset(cell + unit<Dim>(axis)) - grid.offset(cell), grid.stride(axis));
    }
}

} // namespace
} // namespace fddem
