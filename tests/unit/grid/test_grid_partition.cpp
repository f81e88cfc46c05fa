// SPDX-License-Identifier: MIT
// The split of the grid into blocks (grid/grid_partition.hpp), without MPI: the blocks tile the
// axis evenly, the layout chosen has the least interface area of all the valid ones, a layout
// that cannot be made (or is asked for wrongly) is an InputError naming the key, and a grid on
// one process owns everything.

#include "fddem/core/errors.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <gtest/gtest.h>

namespace fddem {
namespace {

TEST(GridPartition, BlocksTileTheAxisAndDifferByAtMostOneCell)
{
    for (int n = 1; n <= 40; ++n) {
        for (int parts = 1; parts <= n; ++parts) {
            int next = 0;
            int smallest = n;
            int largest = 0;
            for (int p = 0; p < parts; ++p) {
                const auto [lo, hi] = block_range(n, parts, p);
                EXPECT_EQ(lo, next);
                next = hi;
                smallest = std::min(smallest, hi - lo);
                largest = std::max(largest, hi - lo);
            }
            EXPECT_EQ(next, n);
            EXPECT_LE(largest - smallest, 1);
        }
    }
    EXPECT_EQ(block_range(10, 4, 0), (std::pair<int, int>{0, 3}));
    EXPECT_EQ(block_range(10, 4, 3), (std::pair<int, int>{8, 10}));
}

TEST(GridPartition, LayoutHasTheLeastInterfaceArea)
{
    // 4 ranks on a 64 × 16 strip: cutting x into 4 costs 3·16 faces, 2 × 2 costs 64 + 16.
    EXPECT_EQ(choose_rank_layout<2>({64, 16}, 4), (Index<2>{4, 1}));
    EXPECT_EQ(choose_rank_layout<2>({64, 64}, 4), (Index<2>{2, 2}));
    EXPECT_EQ(choose_rank_layout<3>({32, 32, 32}, 8), (Index<3>{2, 2, 2}));
    EXPECT_EQ(choose_rank_layout<3>({96, 48, 48}, 2), (Index<3>{2, 1, 1}));
    // Equal areas: the later axis is split.
    EXPECT_EQ(choose_rank_layout<2>({12, 12}, 2), (Index<2>{1, 2}));
    // Blocks must stay at least min_block_cells thick: on 64 × 5, 2 × 2 and 1 × 4 would give
    // blocks 2 and 1 cells thick.
    EXPECT_EQ(choose_rank_layout<2>({8, 8}, 2), (Index<2>{1, 2}));
    EXPECT_EQ(choose_rank_layout<2>({64, 5}, 4), (Index<2>{4, 1}));
    EXPECT_EQ(choose_rank_layout<2>({7, 7}, 1), (Index<2>{1, 1}));
}

TEST(GridPartition, ImpossibleOrWrongLayoutsNameTheKey)
{
    try {
        static_cast<void>(choose_rank_layout<2>({8, 5}, 7));
        FAIL() << "7 ranks cannot split 8 × 5 into blocks of 3 cells";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "domain.cells");
        EXPECT_NE(std::string(e.what()).find("7 ranks"), std::string::npos) << e.what();
    }
    try {
        check_rank_layout<2>({64, 64}, {2, 3}, 4);
        FAIL() << "2 × 3 is not 4 ranks";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "parallel.ranks");
        EXPECT_NE(std::string(e.what()).find("6 blocks"), std::string::npos) << e.what();
    }
    EXPECT_THROW(check_rank_layout<2>({64, 8}, {1, 4}, 4), InputError);
    EXPECT_NO_THROW(check_rank_layout<2>({64, 12}, {1, 4}, 4));
}

TEST(GridPartition, OneProcessOwnsTheWholeGrid)
{
    const MacGrid<3> grid({5, 6, 7}, Vec<3>::Zero(), Vec<3>::Ones(), {true, false, false});
    EXPECT_EQ(grid.owned_cells().lo, (Index<3>{0, 0, 0}));
    EXPECT_EQ(grid.owned_cells().hi, (Index<3>{5, 6, 7}));
    EXPECT_EQ(grid.owned_faces(0).hi, (Index<3>{5, 6, 7}));
    EXPECT_EQ(grid.owned_faces(1).hi, (Index<3>{5, 7, 7}));
    EXPECT_EQ(grid.storage_lo(), (Index<3>{-2, -2, -2}));
    EXPECT_FALSE(grid.is_split(0));
    EXPECT_EQ(grid.partition().neighbours[0], (std::pair<int, int>{0, 0}));
    EXPECT_EQ(grid.partition().neighbours[1].first, Communicator::no_rank);
    EXPECT_TRUE(grid.owns_point(Vec<3>(0.99, 0.01, 0.5)));
    EXPECT_FALSE(grid.communicator().uses_mpi());
}

} // namespace
} // namespace fddem
