// SPDX-License-Identifier: MIT
// The blow-up message on a grid split across MPI ranks (issue 15): every rank searches what it
// owns, and every rank must say the one-process message, wherever the bad value sits. Run under
// mpirun -n 1, 2, 4.

#include "fddem/fluid/fluid_state.hpp"
#include "fddem/grid/grid_partition.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/simulation/step_diagnostics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace fddem {
namespace {

/// The one-process grid and the same grid split over the world's ranks.
struct TwoGrids {
    TwoGrids()
        : whole(cells, Vec<3>::Zero(), Vec<3>::Ones(), periodic),
          split(cells, Vec<3>::Zero(), Vec<3>::Ones(), periodic,
                partition_grid<3>(Communicator::world(), cells, periodic,
                                  choose_rank_layout<3>(cells, Communicator::world().size())))
    {
    }
    Index<3> cells{10, 9, 8};
    std::array<bool, 3> periodic{true, false, false};
    MacGrid<3> whole;
    MacGrid<3> split;
};

/// Sets entry `at` of the field that `pick` chooses, on the one-process state and on the rank
/// that holds it in the split state (storage entries of other ranks do not exist there).
template <class Pick>
void plant(const TwoGrids& grids, FluidState<3>& whole, FluidState<3>& split, Pick pick,
           const Index<3>& at, double value)
{
    pick(whole)(at) = value;
    const Box<3> storage = grids.split.storage_box();
    bool is_held = true;
    for (std::size_t d = 0; d < 3; ++d) {
        is_held = is_held && at[d] >= storage.lo[d] && at[d] < storage.hi[d];
    }
    if (is_held) {
        pick(split)(at) = value;
    }
}

TEST(SplitDiagnostics, EveryRankSaysTheOneProcessMessage)
{
    const TwoGrids grids;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Planted {
        int field; // 0, 1, 2: u components; 3: body force x; 4: pressure
        Index<3> at;
        double value;
    };
    // Two bad values in different blocks (on 4 ranks): the first in storage order must win.
    // Then a finite field with its fastest face at a block's corner.
    const std::vector<std::vector<Planted>> cases = {
        {{1, {8, 7, 6}, nan}, {1, {2, 3, 5}, nan}},
        {{4, {9, 8, 7}, nan}, {4, {0, 0, 0}, std::numeric_limits<double>::infinity()}},
        {{3, {5, 4, 4}, nan}},
        {{2, {4, 4, 4}, -7.0}, {0, {9, 0, 7}, 7.0}},
    };
    for (const auto& planted : cases) {
        FluidState<3> whole(grids.whole);
        FluidState<3> split(grids.split);
        for (const Planted& p : planted) {
            const auto pick = [&p](FluidState<3>& s) -> GridArray<3>& {
                if (p.field < 3) {
                    return s.u[static_cast<std::size_t>(p.field)];
                }
                return p.field == 3 ? s.body_force[0] : s.p;
            };
            plant(grids, whole, split, pick, p.at, p.value);
        }
        const std::string expected = locate_non_finite(grids.whole, whole);
        const std::string said = locate_non_finite(grids.split, split);
        EXPECT_EQ(said, expected) << "rank " << Communicator::world().rank();
        EXPECT_EQ(expected.find("()"), std::string::npos);
    }
}

} // namespace
} // namespace fddem
