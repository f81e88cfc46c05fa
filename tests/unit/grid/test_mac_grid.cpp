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

TYPED_TEST(MacGridTest, OwnedFacesIncludeTheBoundaryFacesOfWalledAxesOnly)
{
    constexpr int Dim = TypeParam::value;
    const auto walled = make_grid<Dim>();
    std::array<bool, Dim> periodic{};
    periodic[0] = true;
    const MacGrid<Dim> channel(walled.cells(), walled.origin(), walled.length(), periodic);
    EXPECT_TRUE(channel.is_periodic(0));
    EXPECT_TRUE(channel.domain().periodic(0));
    for (const MacGrid<Dim>* grid : {&walled, &channel}) {
        EXPECT_EQ(grid->owned_cells().lo, grid->cell_box().lo);
        EXPECT_EQ(grid->owned_cells().hi, grid->cell_box().hi);
        for (int axis = 0; axis < Dim; ++axis) {
            const Box<Dim> owned = grid->owned_faces(axis);
            for (int d = 0; d < Dim; ++d) {
                const auto k = static_cast<std::size_t>(d);
                EXPECT_EQ(owned.lo[k], 0);
                // n + 1 faces normal to a walled axis (both boundary faces), n on a periodic
                // one (face n is face 0), n along the other axes.
                const bool has_boundary_face = d == axis && !grid->is_periodic(d);
                EXPECT_EQ(owned.hi[k], grid->cells(d) + (has_boundary_face ? 1 : 0));
            }
        }
    }
    // Every owned face is a distinct face: n per axis of a fully periodic box.
    std::array<bool, Dim> all{};
    all.fill(true);
    const MacGrid<Dim> torus(walled.cells(), walled.origin(), walled.length(), all);
    for (int axis = 0; axis < Dim; ++axis) {
        EXPECT_EQ(torus.owned_faces(axis).size(), torus.n_cells());
    }
}

} // namespace
} // namespace fddem
