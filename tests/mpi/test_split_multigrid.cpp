// SPDX-License-Identifier: MIT
// The momentum multigrid's coarse levels split over MPI ranks (issue 15,
// linsolve/split_multigrid.hpp): a split level's ghosts filled from their owners and accumulated
// on them across rank faces, corners and periodic sides, and the split hierarchy's operator and
// V-cycle against the one-process hierarchy of the same system. Run under mpirun -n 1, 2, 4.

#include "fddem/grid/loops.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/linsolve/split_multigrid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace fddem {
namespace {

/// A value in [0, 1) that depends on the whole-level index and a salt, the same on every rank.
template <int Dim>
double hashed(const Index<Dim>& i, int salt)
{
    unsigned h = 2166136261u ^ static_cast<unsigned>(salt) * 16777619u;
    for (const int c : i) {
        h = (h ^ static_cast<unsigned>(c + 7)) * 16777619u;
    }
    return static_cast<double>(h % 10007u) / 10007.0;
}

/// The whole index that a stored index stands for (its periodic image wrapped back), or false
/// beyond a bounded side.
template <int Dim>
bool wrapped(const Index<Dim>& i, const Index<Dim>& n, const std::array<bool, Dim>& periodic,
             Index<Dim>& out)
{
    out = i;
    for (std::size_t d = 0; d < i.size(); ++d) {
        if (out[d] < 0 || out[d] >= n[d]) {
            if (!periodic[d]) {
                return false;
            }
            out[d] = (out[d] + n[d]) % n[d];
        }
    }
    return true;
}

template <int Dim>
MacGrid<Dim> split_grid(const Index<Dim>& cells, const std::array<bool, Dim>& periodic)
{
    const Communicator world = Communicator::world();
    return MacGrid<Dim>(
        cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic,
        partition_grid<Dim>(world, cells, periodic, choose_rank_layout<Dim>(cells, world.size())));
}

template <int Dim>
void expect_ghosts_filled_and_accumulated(const Index<Dim>& cells,
                                          const std::array<bool, Dim>& periodic)
{
    const MacGrid<Dim> grid = split_grid<Dim>(cells, periodic);
    const Communicator& ranks = grid.communicator();
    // The first coarse level of the cells, split as split_multigrid splits it.
    const std::vector<Box<Dim>> boxes =
        gather_owned_boxes<Dim>(ranks, coarse_owned_box<Dim>(grid.owned_cells()));
    const Index<Dim> n = coarse_extent<Dim>(cells);
    SplitLevel<Dim> level = make_split_level<Dim>(boxes, ranks.rank(), n, periodic);

    // Fill: every ghost with an owner takes the owner's value; the others keep theirs (−1).
    std::vector<double> values(level.stored.size(), -1.0);
    for_each_cell_in_vtk_order<Dim>(
        level.owned, [&](const Index<Dim>& i) { values[level.offset(i)] = hashed<Dim>(i, 1); });
    fill_ghosts(ranks, level, values);
    long wrong = 0;
    for_each_cell_in_vtk_order<Dim>(level.stored, [&](const Index<Dim>& i) {
        Index<Dim> w{};
        const double expected = wrapped<Dim>(i, n, periodic, w) ? hashed<Dim>(w, 1) : -1.0;
        wrong += values[level.offset(i)] != expected ? 1 : 0;
    });
    EXPECT_EQ(ranks.sum(static_cast<double>(wrong)), 0.0) << "fill";

    // The fill of one colour's face ghosts: exactly the ghosts outside the owned box along one
    // axis whose owner's index sum has the colour's parity take the owner's value.
    for (int colour = 0; colour < 2; ++colour) {
        std::fill(values.begin(), values.end(), -1.0);
        for_each_cell_in_vtk_order<Dim>(
            level.owned, [&](const Index<Dim>& i) { values[level.offset(i)] = hashed<Dim>(i, 1); });
        fill_face_ghosts_of_colour(ranks, level, values, colour);
        wrong = 0;
        long filled = 0;
        for_each_cell_in_vtk_order<Dim>(level.stored, [&](const Index<Dim>& i) {
            if (level.owned.contains(i)) {
                return;
            }
            int outside = 0;
            for (std::size_t d = 0; d < i.size(); ++d) {
                outside += i[d] < level.owned.lo[d] || i[d] >= level.owned.hi[d] ? 1 : 0;
            }
            Index<Dim> w{};
            int sum = 0;
            const bool has_owner = wrapped<Dim>(i, n, periodic, w);
            for (const int c : w) {
                sum += c;
            }
            const bool is_filled = has_owner && outside == 1 && sum % 2 == colour;
            filled += is_filled ? 1 : 0;
            wrong += values[level.offset(i)] != (is_filled ? hashed<Dim>(w, 1) : -1.0) ? 1 : 0;
        });
        EXPECT_EQ(ranks.sum(static_cast<double>(wrong)), 0.0) << "fill of colour " << colour;
        EXPECT_GT(ranks.sum(static_cast<double>(filled)), 0.0);
    }

    // Accumulate: each rank puts 1 in every ghost with an owner; each owned entry then counts
    // the ghosts that stand for it, which every rank can count from the boxes.
    std::fill(values.begin(), values.end(), 0.0);
    for_each_cell_in_vtk_order<Dim>(level.stored, [&](const Index<Dim>& i) {
        Index<Dim> w{};
        if (!level.owned.contains(i) && wrapped<Dim>(i, n, periodic, w)) {
            values[level.offset(i)] = 1.0;
        }
    });
    accumulate_ghosts(ranks, level, values);
    wrong = 0;
    long ghosts_with_owners = 0;
    for_each_cell_in_vtk_order<Dim>(level.owned, [&](const Index<Dim>& c) {
        double expected = 0.0;
        for (const Box<Dim>& box : boxes) {
            for_each_cell_in_vtk_order<Dim>(box.grown(1), [&](const Index<Dim>& i) {
                Index<Dim> w{};
                if (!box.contains(i) && wrapped<Dim>(i, n, periodic, w) && w == c) {
                    expected += 1.0;
                }
            });
        }
        ghosts_with_owners += static_cast<long>(expected);
        wrong += values[level.offset(c)] != expected ? 1 : 0;
    });
    EXPECT_EQ(ranks.sum(static_cast<double>(wrong)), 0.0) << "accumulate";
    EXPECT_GT(ranks.sum(static_cast<double>(ghosts_with_owners)), 0.0);
}

TEST(SplitMultigrid, GhostsAreFilledAndAccumulatedAcrossFacesCornersAndPeriodicSides)
{
    expect_ghosts_filled_and_accumulated<2>({26, 23}, {true, false});
    expect_ghosts_filled_and_accumulated<2>({27, 22}, {false, true});
    expect_ghosts_filled_and_accumulated<3>({14, 11, 12}, {false, true, true});
}

/// A (2·Dim + 1)-point system over the whole level (x fastest), diagonally dominant, with
/// links that differ at every unknown, as a StencilView of `arrays`.
template <int Dim>
StencilView<Dim> make_system(const Box<Dim>& box, const std::array<bool, Dim>& periodic,
                             std::vector<std::vector<double>>& arrays)
{
    arrays.assign(2 * Dim + 1, std::vector<double>(box.size()));
    StencilView<Dim> view;
    view.periodic = periodic;
    std::ptrdiff_t stride = 1;
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        view.n[sd] = box.extent(d);
        view.stride[sd] = stride;
        stride *= box.extent(d);
    }
    std::size_t o = 0;
    for_each_cell_in_vtk_order<Dim>(box, [&](const Index<Dim>& i) {
        double links = 0.0;
        for (std::size_t k = 0; k < 2 * Dim; ++k) {
            arrays[k][o] = 0.5 + hashed<Dim>(i, static_cast<int>(k) + 2);
            links += arrays[k][o];
        }
        arrays[2 * Dim][o] = links + 0.05 + 0.1 * hashed<Dim>(i, 20);
        ++o;
    });
    for (std::size_t k = 0; k < 2 * Dim; ++k) {
        view.a_nb[k] = arrays[k].data();
    }
    view.diagonal = arrays[2 * Dim].data();
    return view;
}

/// Returns the extent of the level gathered onto the root.
template <int Dim>
Index<Dim> expect_split_cycle_matches(const Index<Dim>& cells,
                                      const std::array<bool, Dim>& periodic)
{
    const MacGrid<Dim> grid = split_grid<Dim>(cells, periodic);
    const Communicator& ranks = grid.communicator();
    Box<Dim> whole;
    whole.hi = cells;
    std::vector<std::vector<double>> whole_arrays;
    const StencilView<Dim> whole_view = make_system<Dim>(whole, periodic, whole_arrays);
    std::vector<std::vector<double>> part_arrays;
    const Box<Dim> owned = grid.owned_cells();
    const StencilView<Dim> part_view = make_system<Dim>(owned, periodic, part_arrays);
    const LevelPart<Dim> part{owned.lo, cells};

    std::vector<CoarseLevel<Dim>> reference;
    build_coarse_levels<Dim>(whole_view, reference);
    SplitHierarchy<Dim> split;
    build_split_levels<Dim>(ranks, part_view, part, split);
    if (split.levels.empty()) {
        ADD_FAILURE() << "no coarse levels";
        return {};
    }

    // The first coarse level's operator: the ranks' shares added on the owners.
    const SplitLevel<Dim>& first = split.levels.front();
    double worst_operator = 0.0;
    double largest_operator = 0.0;
    for_each_cell_in_vtk_order<Dim>(first.owned, [&](const Index<Dim>& c) {
        const std::size_t o = reference.front().offset(c);
        const std::size_t s = first.offset(c);
        worst_operator = std::max(
            worst_operator, std::abs(first.local.diagonal[s] - reference.front().diagonal[o]));
        largest_operator = std::max(largest_operator, std::abs(reference.front().diagonal[o]));
        for (std::size_t k = 0; k < 2 * Dim; ++k) {
            worst_operator = std::max(
                worst_operator, std::abs(first.local.a_nb[k][s] - reference.front().a_nb[k][o]));
        }
    });
    EXPECT_LE(ranks.max(worst_operator), 1e-14 * ranks.max(largest_operator));

    // One V-cycle on the restriction of a residual that differs at every fine unknown.
    restrict_sum<Dim>(
        cells, [&](const Index<Dim>& i) { return hashed<Dim>(i, 30) - 0.5; }, reference.front());
    coarse_v_cycle<Dim>(reference, 0, 2);
    SplitLevel<Dim>& mine = split.levels.front();
    std::fill(mine.local.rhs.begin(), mine.local.rhs.end(), 0.0);
    for_each_cell_in_vtk_order<Dim>(owned, [&](const Index<Dim>& i) {
        mine.local.rhs[mine.offset(coarse_index<Dim>(i))] += hashed<Dim>(i, 30) - 0.5;
    });
    split_v_cycle<Dim>(ranks, split, 2);
    double worst = 0.0;
    double largest = 0.0;
    for_each_cell_in_vtk_order<Dim>(mine.owned, [&](const Index<Dim>& c) {
        const double x = reference.front().x[reference.front().offset(c)];
        worst = std::max(worst, std::abs(mine.local.x[mine.offset(c)] - x));
        largest = std::max(largest, std::abs(x));
    });
    worst = ranks.max(worst);
    largest = ranks.max(largest);
    EXPECT_GT(largest, 1e-3);
    EXPECT_LE(worst, 1e-12 * largest);

    // Split below the first coarse level, and no rank holding a whole level but the small one
    // gathered on the root.
    EXPECT_GE(split.levels.size(), 2U);
    Box<Dim> gathered;
    gathered.hi = split.levels.back().whole_n;
    EXPECT_LE(gathered.size(), coarsest_level_size * static_cast<std::size_t>(1 << Dim) *
                                   static_cast<std::size_t>(ranks.size()));
    EXPECT_EQ(split.root_levels.empty(), ranks.rank() != split_coarse_root(ranks));
    // How many ranks a full fill and a colour's face fill reach (printed).
    const SplitLevelRoutes& routes = *split.levels.front().routes;
    const std::size_t all_ranks = routes.all.sends.size();
    const std::size_t face_ranks =
        std::max(routes.colour_faces[0].sends.size(), routes.colour_faces[1].sends.size());
    if (ranks.rank() == 0) {
        std::printf("[ info ] %dD split multigrid on %d ranks: %zu split levels, gathered %zu "
                    "unknowns; max |Δx|/max|x| = %.2e; rank 0 sends a full fill to %zu ranks, "
                    "a colour's face fill to %zu\n",
                    Dim, ranks.size(), split.levels.size(), gathered.size(), worst / largest,
                    all_ranks, face_ranks);
    }
    return split.levels.back().whole_n;
}

/// One split V-cycle on the system of make_system over `grid`'s cells with the hierarchy
/// `split`: this rank's owned correction, VTK order.
template <int Dim>
std::vector<double> split_cycle(const MacGrid<Dim>& grid, SplitHierarchy<Dim>& split)
{
    const Communicator& ranks = grid.communicator();
    std::vector<std::vector<double>> part_arrays;
    const Box<Dim> owned = grid.owned_cells();
    std::array<bool, Dim> periodic{};
    for (int d = 0; d < Dim; ++d) {
        periodic[static_cast<std::size_t>(d)] = grid.is_periodic(d);
    }
    const StencilView<Dim> part_view = make_system<Dim>(owned, periodic, part_arrays);
    build_split_levels<Dim>(ranks, part_view, LevelPart<Dim>{owned.lo, grid.cell_box().hi}, split);
    SplitLevel<Dim>& first = split.levels.front();
    std::fill(first.local.rhs.begin(), first.local.rhs.end(), 0.0);
    for_each_cell_in_vtk_order<Dim>(owned, [&](const Index<Dim>& i) {
        first.local.rhs[first.offset(coarse_index<Dim>(i))] += hashed<Dim>(i, 30) - 0.5;
    });
    split_v_cycle<Dim>(ranks, split, 2);
    std::vector<double> x;
    for_each_cell_in_vtk_order<Dim>(
        first.owned, [&](const Index<Dim>& c) { x.push_back(first.local.x[first.offset(c)]); });
    return x;
}

TEST(SplitMultigrid, TheLayoutIsKeptAndMadeAgainForAnotherPart)
{
    const std::array<bool, 3> periodic{false, false, true};
    const MacGrid<3> a = split_grid<3>({24, 19, 16}, periodic);
    const MacGrid<3> b = split_grid<3>({20, 18, 14}, periodic);
    SplitHierarchy<3> fresh_a;
    SplitHierarchy<3> fresh_b;
    const std::vector<double> expected_a = split_cycle<3>(a, fresh_a);
    const std::vector<double> expected_b = split_cycle<3>(b, fresh_b);

    // One hierarchy built again and again: a kept layout (the same routes, and no gather of
    // the boxes) must give the fresh cycle exactly, and another part must get its own layout.
    SplitHierarchy<3> kept;
    long wrong = split_cycle<3>(a, kept) != expected_a ? 1 : 0;
    const SplitLevelRoutes* routes_a = kept.levels.front().routes.get();
    const long made = a.communicator().traffic().collectives;
    wrong += split_cycle<3>(a, kept) != expected_a ? 1 : 0;
    const long kept_build = a.communicator().traffic().collectives - made;
    EXPECT_EQ(kept.levels.front().routes.get(), routes_a) << "the layout was made again";
    wrong += split_cycle<3>(b, kept) != expected_b ? 1 : 0;
    EXPECT_NE(kept.levels.front().routes.get(), routes_a) << "the layout was kept for another part";
    const long before_a = a.communicator().traffic().collectives;
    wrong += split_cycle<3>(a, kept) != expected_a ? 1 : 0;
    EXPECT_EQ(a.communicator().traffic().collectives - before_a, kept_build + 1)
        << "one gather of the boxes";
    EXPECT_EQ(a.communicator().sum(static_cast<double>(wrong)), 0.0);
}

TEST(SplitMultigrid, VCycleMatchesOneProcess)
{
    expect_split_cycle_matches<2>({40, 29}, {true, false});
    expect_split_cycle_matches<2>({41, 36}, {false, false});
    expect_split_cycle_matches<3>({24, 19, 16}, {false, false, true});
    // The second coarse level, 11 × 10, is odd across the periodic side: smoothed on the
    // blocks, its colours would not be the one-process sweep's; it is the gathered one.
    const Index<2> gathered = expect_split_cycle_matches<2>({44, 40}, {true, false});
    EXPECT_EQ(gathered, (Index<2>{11, 10}));
}

} // namespace
} // namespace fddem
