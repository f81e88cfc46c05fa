// SPDX-License-Identifier: MIT
// The pieces a split grid's checkpoint is written in (grid/storage_pieces.hpp, issue 15): each
// rank's contributed box, and a block's storage set from the pieces it overlaps. The ranks are
// made by hand on one process (only the blocks matter here), for layouts of 2 × 3 (× 2) ranks
// with a periodic axis, against the one-process array.

#include "fddem/grid/box_values.hpp"
#include "fddem/grid/grid_partition.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/grid/storage_pieces.hpp"

#include <gtest/gtest.h>

#include <type_traits>
#include <vector>

namespace fddem {
namespace {

template <class T>
class StoragePiecesTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(StoragePiecesTest, Dimensions);

constexpr std::array<int, 3> n_cells{11, 15, 7};
constexpr std::array<int, 3> n_ranks{2, 3, 2};

template <int Dim>
std::array<bool, Dim> periodic_axes()
{
    std::array<bool, Dim> periodic{};
    periodic[0] = true; // x periodic, the others bounded
    return periodic;
}

template <int Dim>
Index<Dim> cells()
{
    Index<Dim> n{};
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        n[d] = n_cells[d];
    }
    return n;
}

/// Every rank's block of the grid split n_ranks ways, made on this process.
template <int Dim>
std::vector<MacGrid<Dim>> blocks()
{
    Index<Dim> ranks{};
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        ranks[d] = n_ranks[d];
    }
    const GridPartition<Dim> whole = whole_grid<Dim>(cells<Dim>(), periodic_axes<Dim>());
    std::vector<MacGrid<Dim>> grids;
    Box<Dim> all;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        all.hi[d] = ranks[d];
    }
    for_each_cell_in_vtk_order(all, [&](const Index<Dim>& coords) {
        GridPartition<Dim> part = whole;
        part.ranks = ranks;
        part.coords = coords;
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
            // n cells in p runs, the first n mod p one longer (grid_partition.hpp's rule; any
            // tiling would do here)
            const int n = n_cells[d];
            const int p = ranks[d];
            const int c = coords[d];
            part.block.lo[d] = c * (n / p) + std::min(c, n % p);
            part.block.hi[d] = part.block.lo[d] + n / p + (c < n % p ? 1 : 0);
        }
        grids.emplace_back(cells<Dim>(), Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic_axes<Dim>(),
                           part);
    });
    return grids;
}

TYPED_TEST(StoragePiecesTest, ContributedBoxesTileTheOneProcessStorage)
{
    constexpr int Dim = TypeParam::value;
    const MacGrid<Dim> one(cells<Dim>(), Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic_axes<Dim>());
    EXPECT_EQ(contributed_box(one).lo, one.storage_box().lo);
    EXPECT_EQ(contributed_box(one).hi, one.storage_box().hi);
    GridArray<Dim> covered(one);
    std::size_t total = 0;
    for (const MacGrid<Dim>& block : blocks<Dim>()) {
        const Box<Dim> box = contributed_box(block);
        total += box.size();
        for_each_cell_in_vtk_order(box, [&](const Index<Dim>& i) { covered(i) += 1.0; });
    }
    EXPECT_EQ(total, one.storage_box().size());
    for_each_cell_in_vtk_order(one.storage_box(),
                               [&](const Index<Dim>& i) { ASSERT_EQ(covered(i), 1.0); });
}

TYPED_TEST(StoragePiecesTest, EveryBlockIsSetEntryForEntryFromThePiecesItOverlaps)
{
    // The one-process array with a distinct value in every storage entry (ghosts included),
    // cut into the ranks' pieces; each block's storage set from them must be the one-process
    // array's entries there, every entry set once; the first block (5 cells along y, of 15
    // on 3 ranks) does not reach the last row of pieces.
    constexpr int Dim = TypeParam::value;
    const MacGrid<Dim> one(cells<Dim>(), Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic_axes<Dim>());
    GridArray<Dim> whole(one);
    double value = 1.0;
    for_each_cell_in_vtk_order(one.storage_box(), [&](const Index<Dim>& i) { whole(i) = value++; });
    const std::vector<MacGrid<Dim>> grids = blocks<Dim>();
    std::vector<Box<Dim>> boxes;
    std::vector<std::vector<double>> pieces;
    for (const MacGrid<Dim>& block : grids) {
        boxes.push_back(contributed_box(block));
        pieces.push_back(pack(whole, boxes.back()));
    }
    for (std::size_t b = 0; b < grids.size(); ++b) {
        const MacGrid<Dim>& block = grids[b];
        GridArray<Dim> part(block, -1.0);
        std::size_t taken = 0;
        int overlapping = 0;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            const std::size_t n = take_overlap<Dim>(block, boxes[k], pieces[k], part);
            EXPECT_EQ(n, intersection(boxes[k], block.storage_box()).size());
            overlapping += n > 0 ? 1 : 0;
            taken += n;
        }
        EXPECT_EQ(taken, block.storage_box().size());
        if (b == 0) {
            EXPECT_EQ(overlapping, static_cast<int>(grids.size()) * 2 / 3);
        }
        for_each_cell_in_vtk_order(block.storage_box(),
                                   [&](const Index<Dim>& i) { ASSERT_EQ(part(i), whole(i)); });
    }
}

TEST(StoragePieces, IntersectionOfDisjointBoxesIsEmpty)
{
    const Box<2> a{{0, 0}, {4, 3}};
    const Box<2> b{{4, 0}, {6, 3}};
    const Box<2> c{{2, 1}, {9, 2}};
    EXPECT_EQ(intersection(a, b).size(), 0U);
    EXPECT_EQ(intersection(a, c).size(), 2U); // x 2..4, y 1..2
    EXPECT_EQ(intersection(b, c).size(), 2U);
}

} // namespace
} // namespace fddem
