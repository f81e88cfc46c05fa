// SPDX-License-Identifier: MIT
#include "fddem/grid/mac_grid.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
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

namespace fddem {
namespace {

/// A block of a grid split by hand (no MPI needed: only the block matters to owns_point and
/// may_own_near): 12 × 10 (× 8) cells, periodic along x (and z), the block x ∈ [4, 8),
/// y ∈ [0, 5) (a bounded side), z ∈ [6, 8) (the periodic high side).
template <int Dim>
MacGrid<Dim> block_of_split_grid()
{
    Index<Dim> cells{};
    std::array<bool, Dim> periodic{};
    GridPartition<Dim> part;
    const std::array<int, 3> n{12, 10, 8};
    const std::array<int, 3> lo{4, 0, 6};
    const std::array<int, 3> hi{8, 5, 8};
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        cells[d] = n[d];
        part.ranks[d] = 2;
        part.block.lo[d] = lo[d];
        part.block.hi[d] = hi[d];
        periodic[d] = d != 1;
    }
    return MacGrid<Dim>(cells, Vec<Dim>::Constant(-0.5), Vec<Dim>::Ones(), periodic, part);
}

TYPED_TEST(MacGridTest, MayOwnNearIsTrueWheneverAPointWithinReachIsOwned)
{
    // The rank's marker loops skip a body for which may_own_near is false (issue 15); a body
    // with a marker in the rank's cells must never be skipped. Points within `reach` of random
    // centres (inside the box, across the periodic sides and beyond the bounded ones), wrapped
    // as markers are: whenever one of them is owned, may_own_near says yes.
    constexpr int Dim = TypeParam::value;
    const MacGrid<Dim> grid = block_of_split_grid<Dim>();
    const PeriodicDomain<Dim> domain = grid.domain();
    std::uint64_t state = 12345;
    const auto uniform = [&state] { // a fixed LCG: the test draws the same points everywhere
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    int said_no = 0;
    int owned_bodies = 0;
    for (int body = 0; body < 3000; ++body) {
        Vec<Dim> centre;
        for (int d = 0; d < Dim; ++d) {
            centre[d] = -0.7 + 1.4 * uniform(); // up to 0.2 beyond each side
        }
        const double reach = 0.35 * uniform();
        bool is_owned = false;
        for (int k = 0; k < 200 && !is_owned; ++k) {
            Vec<Dim> x;
            for (int d = 0; d < Dim; ++d) {
                x[d] = centre[d] + reach * (2.0 * uniform() - 1.0);
            }
            is_owned = grid.owns_point(domain.wrap(x));
        }
        const bool may = grid.may_own_near(centre, reach);
        ASSERT_TRUE(!is_owned || may) << "body " << body;
        owned_bodies += is_owned ? 1 : 0;
        said_no += may ? 0 : 1;
    }
    // It is a filter: most bodies far from the block are skipped.
    EXPECT_GT(owned_bodies, 100);
    EXPECT_GT(said_no, Dim == 2 ? 1000 : 1500);
    // Far from the block along the bounded axis, and beside it across the periodic x side.
    Vec<Dim> far = Vec<Dim>::Zero();
    far[1] = 0.45; // the cells y ∈ [9, 10), above the block
    EXPECT_FALSE(grid.may_own_near(far, 0.1));
    EXPECT_TRUE(grid.may_own_near(far, 0.6));
    Vec<Dim> across = Vec<Dim>::Zero();
    across[0] = 0.49; // by the high x side; the block is x ∈ [-0.17, 0.17)
    EXPECT_FALSE(grid.may_own_near(across, 0.1));
    EXPECT_TRUE(grid.may_own_near(across, 0.4));
    Vec<Dim> nan = Vec<Dim>::Constant(std::nan(""));
    EXPECT_TRUE(grid.may_own_near(nan, 0.1));
}

} // namespace
} // namespace fddem
