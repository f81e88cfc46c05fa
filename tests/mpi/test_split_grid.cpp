// SPDX-License-Identifier: MIT
// The grid split across MPI ranks (issue 15, DESIGN.md §6), run by CTest under
// `mpirun -n 1`, `-n 2` and `-n 4` (tests/CMakeLists.txt). Every rank builds the whole grid on
// its own as the one-process reference, and the split grid with its block, and checks its own
// entries against the reference:
//
// - fill makes every entry of the block's storage (owned, ghosts from other ranks, ghosts across
//   periodic sides, ghosts left to the boundary conditions) equal to the one-process grid's
//   entry of the same global index after its fill: bit for bit, for cells and faces;
// - accumulate is fill's adjoint over all ranks and entries (exact, on integers);
// - markers spread by the rank that owns their cell, then accumulated, give the one-process
//   spreading on every owned entry, to round-off (the additions come in another order);
//   interpolation at a rank's own markers after a fill is bit for bit the one-process value;
//   every marker has exactly one owner.
//
// The markers include points around the corner that four ranks share and next to the
// periodic seam, and each layout is tried with every combination of periodic axes.

#include "fddem/core/errors.hpp"
#include "fddem/core/phase_timer.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "support/split_compare.hpp"
#include "support/storage_sums.hpp"

namespace fddem {
namespace {

template <class T>
class SplitGridTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SplitGridTest, Dimensions);

constexpr std::size_t ax(int d)
{
    return static_cast<std::size_t>(d);
}

/// Cells with uneven splits on 2 and 4 ranks, every block ≥ min_block_cells thick.
template <int Dim>
Index<Dim> test_cells()
{
    if constexpr (Dim == 2) {
        return {13, 12};
    } else {
        return {13, 12, 14};
    }
}

/// Every layout of `n` ranks with at most two axes split, and the automatic one.
template <int Dim>
std::vector<Index<Dim>> layouts(int n)
{
    std::vector<Index<Dim>> result;
    Index<Dim> ones{};
    ones.fill(1);
    for (int a = 0; a < Dim; ++a) {
        Index<Dim> one_axis = ones;
        one_axis[ax(a)] = n;
        result.push_back(one_axis);
        if (n == 4) {
            for (int b = a + 1; b < Dim; ++b) {
                Index<Dim> two_axes = ones;
                two_axes[ax(a)] = 2;
                two_axes[ax(b)] = 2;
                result.push_back(two_axes);
            }
        }
    }
    result.push_back(choose_rank_layout<Dim>(test_cells<Dim>(), n));
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
}

template <int Dim>
std::string describe(const Index<Dim>& ranks, const std::array<bool, Dim>& periodic)
{
    std::ostringstream text;
    text << "ranks";
    for (int d = 0; d < Dim; ++d) {
        text << ' ' << ranks[ax(d)];
    }
    text << ", periodic";
    for (int d = 0; d < Dim; ++d) {
        text << (periodic[ax(d)] ? " y" : " n");
    }
    return text.str();
}

/// The whole grid on this process, and the same grid split with `ranks`.
template <int Dim>
struct GridPair {
    MacGrid<Dim> whole;
    MacGrid<Dim> split;
};

template <int Dim>
GridPair<Dim> make_grids(const Index<Dim>& ranks, const std::array<bool, Dim>& periodic)
{
    const Index<Dim> cells = test_cells<Dim>();
    Vec<Dim> origin;
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        origin[d] = -0.5 + 0.25 * d;
        length[d] = 1.0 + 0.3 * d;
    }
    return {MacGrid<Dim>(cells, origin, length, periodic),
            MacGrid<Dim>(cells, origin, length, periodic,
                         partition_grid<Dim>(Communicator::world(), cells, periodic, ranks))};
}

/// The box of entries `grid` owns in an array of kind `kind` (−1: cells, a: faces normal to a).
template <int Dim>
Box<Dim> owned(const MacGrid<Dim>& grid, int kind)
{
    return kind < 0 ? grid.owned_cells() : grid.owned_faces(kind);
}

/// A whole number made from a global index and the array kind, different for nearby entries.
template <int Dim>
double label(const Index<Dim>& i, int kind)
{
    double value = kind + 2;
    for (int d = 0; d < Dim; ++d) {
        value = 37.0 * value + (i[ax(d)] + 5);
    }
    return value;
}

/// Owned entries hold +label, every other entry −label.
template <int Dim>
GridArray<Dim> labelled(const MacGrid<Dim>& grid, int kind)
{
    GridArray<Dim> a(grid);
    const Box<Dim> mine = owned(grid, kind);
    for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) {
        a(i) = mine.contains(i) ? label<Dim>(i, kind) : -label<Dim>(i, kind);
    });
    return a;
}

TYPED_TEST(SplitGridTest, TrafficCountsEachHaloMessageAndCollective)
{
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    // Slabs along the first axis, bounded: a rank sends one message per array and block side
    // that faces another block (none on one process).
    Index<Dim> ranks;
    ranks.fill(1);
    ranks[0] = world.size();
    std::array<bool, Dim> periodic{};
    const GridPair<Dim> g = make_grids<Dim>(ranks, periodic);
    const Communicator& comm = g.split.communicator();
    const Traffic before = comm.traffic();
    GridArray<Dim> a(g.split);
    HaloExchange<Dim>(g.split).fill(a);
    const Traffic after_fill = comm.traffic();
    const auto [below, above] = g.split.partition().neighbours[0];
    const long sides =
        (below != Communicator::no_rank ? 1 : 0) + (above != Communicator::no_rank ? 1 : 0);
    EXPECT_EQ(after_fill.messages - before.messages, sides);
    // Layers sent: the first 3 down and the last 2 up, each over the storage across the axis.
    const Box<Dim> storage = g.split.storage_box();
    const long layer = static_cast<long>(storage.size()) / storage.extent(0);
    const long layers =
        (below != Communicator::no_rank ? 3 : 0) + (above != Communicator::no_rank ? 2 : 0);
    EXPECT_EQ(after_fill.bytes - before.bytes, layers * layer * static_cast<long>(sizeof(double)));
    EXPECT_EQ(after_fill.collectives, before.collectives);
    std::vector<double> totals(5, 1.0);
    comm.sum(totals);
    const Traffic after_sum = comm.traffic();
    EXPECT_EQ(after_sum.messages, after_fill.messages);
    // Counted whenever the communicator is MPI's (one process through mpirun included).
    EXPECT_EQ(after_sum.collectives - after_fill.collectives, comm.uses_mpi() ? 1 : 0);
    EXPECT_EQ(after_sum.collective_bytes - after_fill.collective_bytes,
              comm.uses_mpi() ? 5 * static_cast<long>(sizeof(double)) : 0);
    // A sum is a gather of every rank's values: it brings each rank the ranks' number times them.
    EXPECT_EQ(after_sum.collective_received_bytes - after_fill.collective_received_bytes,
              comm.uses_mpi() ? 5 * comm.size() * static_cast<long>(sizeof(double)) : 0);
    EXPECT_DOUBLE_EQ(totals[0], world.size());
    // The time inside those calls grows with them, and a phase that encloses the sum gets it.
    EXPECT_GT(after_sum.seconds, after_fill.seconds);
    EXPECT_GE(after_fill.seconds, before.seconds);
    PhaseTimes times;
    times.communication_clock = comm.seconds_counter();
    {
        const ScopedPhase pressure(times, Phase::pressure);
        comm.sum(totals);
    }
    const double pressure = times.communication[static_cast<std::size_t>(Phase::pressure)];
    EXPECT_DOUBLE_EQ(pressure, comm.traffic().seconds - after_sum.seconds);
    EXPECT_LE(pressure, times[Phase::pressure]);
    EXPECT_EQ(times.communication[static_cast<std::size_t>(Phase::momentum)], 0.0);
}

TEST(SplitCommunicator, AllGatherHandsEveryRankEachRanksValuesBitForBitInRankOrder)
{
    // Rank r gives r + 1 values (rank 1 none on more than two ranks), the first of them −0;
    // every rank must hold all of them, in rank order, with their bits (a sum would turn −0
    // into +0), and count one collective of what it gave.
    const Communicator world = Communicator::world();
    const int n = world.size();
    const int me = world.rank();
    const auto count = [n](int r) { return n > 2 && r == 1 ? 0 : r + 1; };
    const auto value = [](int r, int k) { return k == 0 ? -0.0 : 1e3 * r + k + 0.125; };
    std::vector<int> counts;
    for (int q = 0; q < n; ++q) {
        counts.push_back(count(q));
    }
    std::vector<double> mine;
    for (int k = 0; k < count(me); ++k) {
        mine.push_back(value(me, k));
    }
    std::vector<double> all(
        static_cast<std::size_t>(std::accumulate(counts.begin(), counts.end(), 0)));
    const Traffic before = world.traffic();
    world.all_gather(mine, counts, all);
    const Traffic after = world.traffic();
    std::size_t at = 0;
    int n_wrong = 0;
    for (int q = 0; q < n; ++q) {
        for (int k = 0; k < count(q); ++k) {
            const double v = all[at++];
            n_wrong += (v == value(q, k) && std::signbit(v) == std::signbit(value(q, k))) ? 0 : 1;
        }
    }
    EXPECT_EQ(n_wrong, 0);
    if (n > 1) {
        EXPECT_EQ(after.collectives - before.collectives, 1);
        EXPECT_EQ(after.collective_bytes - before.collective_bytes,
                  static_cast<long>(mine.size() * sizeof(double)));
        EXPECT_EQ(after.collective_received_bytes - before.collective_received_bytes,
                  static_cast<long>(all.size() * sizeof(double)));
    }
    // Counts that do not add up to the values are an internal error, on every rank alike.
    std::vector<double> short_all(all.size() + 1);
    EXPECT_THROW(world.all_gather(mine, counts, short_all), InternalError);
}

TEST(SplitCommunicator, AllToAllDeliversEachRanksShareInRankOrderAndIsCounted)
{
    // Rank r sends (r + 1)(q + 2) values to rank q, each naming r, q and its place; every rank
    // must receive exactly what was meant for it, in rank order, and count one all-to-all of
    // what left it (not what it kept).
    const Communicator world = Communicator::world();
    const int n = world.size();
    const int me = world.rank();
    const auto count = [](int from, int to) { return (from + 1) * (to + 2); };
    const auto value = [](int from, int to, int k) { return 1e6 * from + 1e3 * to + k; };
    std::vector<int> send_counts;
    std::vector<int> receive_counts;
    std::vector<double> send;
    for (int q = 0; q < n; ++q) {
        send_counts.push_back(count(me, q));
        receive_counts.push_back(count(q, me));
        for (int k = 0; k < count(me, q); ++k) {
            send.push_back(value(me, q, k));
        }
    }
    std::vector<double> receive(
        static_cast<std::size_t>(std::accumulate(receive_counts.begin(), receive_counts.end(), 0)));
    const Traffic before = world.traffic();
    world.all_to_all(send, send_counts, receive, receive_counts);
    const Traffic after = world.traffic();
    std::size_t at = 0;
    int n_wrong = 0;
    for (int q = 0; q < n; ++q) {
        for (int k = 0; k < count(q, me); ++k) {
            n_wrong += receive[at++] == value(q, me, k) ? 0 : 1;
        }
    }
    EXPECT_EQ(n_wrong, 0);
    EXPECT_EQ(after.all_to_alls - before.all_to_alls, 1);
    const long kept = count(me, me);
    EXPECT_EQ(after.all_to_all_bytes - before.all_to_all_bytes,
              (static_cast<long>(send.size()) - kept) * static_cast<long>(sizeof(double)));
    EXPECT_EQ(after.collectives, before.collectives);

    // send_and_receive: rank r sends to the next and the previous rank (once if they are the
    // same), each message naming sender and receiver; one message counted per destination.
    if (n > 1) {
        const int next = (me + 1) % n;
        const int previous = (me + n - 1) % n;
        std::vector<int> peers{next};
        if (previous != next) {
            peers.push_back(previous);
        }
        std::vector<std::vector<double>> out;
        std::vector<std::vector<double>> in;
        for (const int q : peers) {
            out.push_back({value(me, q, 0), value(me, q, 1)});
            in.push_back(std::vector<double>(2, -1.0));
        }
        std::vector<Communicator::Outgoing> sends;
        std::vector<Communicator::Incoming> receives;
        for (std::size_t k = 0; k < peers.size(); ++k) {
            sends.push_back({peers[k], out[k]});
            receives.push_back({peers[k], in[k]});
        }
        const Traffic ahead = world.traffic();
        world.send_and_receive(sends, receives, 7);
        EXPECT_EQ(world.traffic().messages - ahead.messages, static_cast<long>(peers.size()));
        for (std::size_t k = 0; k < peers.size(); ++k) {
            EXPECT_EQ(in[k][0], value(peers[k], me, 0));
            EXPECT_EQ(in[k][1], value(peers[k], me, 1));
        }
    }

    // all_gather: every rank's values, rank after rank.
    const std::vector<int> mine{me, 10 * me + 1};
    const std::vector<int> all = world.all_gather(mine);
    ASSERT_EQ(all.size(), static_cast<std::size_t>(2 * n));
    for (int q = 0; q < n; ++q) {
        EXPECT_EQ(all[static_cast<std::size_t>(2 * q)], q);
        EXPECT_EQ(all[static_cast<std::size_t>(2 * q + 1)], 10 * q + 1);
    }
}

TYPED_TEST(SplitGridTest, FillGivesEveryEntryItsOneProcessValue)
{
    constexpr int Dim = TypeParam::value;
    const int n_ranks = Communicator::world().size();
    for (const Index<Dim>& ranks : layouts<Dim>(n_ranks)) {
        for (int code = 0; code < (1 << Dim); ++code) {
            const auto periodic = test::periodic_from<Dim>(code);
            SCOPED_TRACE(describe<Dim>(ranks, periodic));
            const GridPair<Dim> g = make_grids<Dim>(ranks, periodic);
            for (int kind = -1; kind < Dim; ++kind) {
                GridArray<Dim> reference = labelled<Dim>(g.whole, kind);
                HaloExchange<Dim>(g.whole).fill(reference);
                GridArray<Dim> a = labelled<Dim>(g.split, kind);
                HaloExchange<Dim>(g.split).fill(a);
                int n_wrong = 0;
                for_each_cell_in_vtk_order(g.split.storage_box(), [&](const Index<Dim>& i) {
                    n_wrong += a(i) == reference(i) ? 0 : 1;
                });
                EXPECT_EQ(n_wrong, 0) << "array kind " << kind;
            }
        }
    }
}

TYPED_TEST(SplitGridTest, FillFacesGivesTheFaceGhostsTheirOneProcessValuesAndNothingElse)
{
    constexpr int Dim = TypeParam::value;
    const int n_ranks = Communicator::world().size();
    const Index<Dim> cells = test_cells<Dim>();
    for (const Index<Dim>& ranks : layouts<Dim>(n_ranks)) {
        for (int code = 0; code < (1 << Dim); ++code) {
            const auto periodic = test::periodic_from<Dim>(code);
            SCOPED_TRACE(describe<Dim>(ranks, periodic));
            const GridPair<Dim> g = make_grids<Dim>(ranks, periodic);
            const Box<Dim>& block = g.split.owned_cells();
            // The one layer across a face of the block, where that layer has an owner.
            const auto is_face_ghost = [&](const Index<Dim>& i) {
                int outside = 0;
                bool has_owner = true;
                for (int d = 0; d < Dim; ++d) {
                    const int at = i[ax(d)];
                    if (at >= block.lo[ax(d)] && at < block.hi[ax(d)]) {
                        continue;
                    }
                    ++outside;
                    has_owner = has_owner && (at == block.lo[ax(d)] - 1 || at == block.hi[ax(d)]) &&
                                (periodic[ax(d)] || (at >= 0 && at < cells[ax(d)]));
                }
                return outside == 1 && has_owner;
            };
            for (int kind = -1; kind < Dim; ++kind) {
                GridArray<Dim> reference = labelled<Dim>(g.whole, kind);
                HaloExchange<Dim>(g.whole).fill(reference);
                const GridArray<Dim> before = labelled<Dim>(g.split, kind);
                GridArray<Dim> a = before;
                HaloExchange<Dim>(g.split).fill_faces(a);
                int n_wrong = 0;
                int n_filled = 0;
                for_each_cell_in_vtk_order(g.split.storage_box(), [&](const Index<Dim>& i) {
                    const bool is_filled = is_face_ghost(i);
                    n_filled += is_filled ? 1 : 0;
                    n_wrong += a(i) == (is_filled ? reference(i) : before(i)) ? 0 : 1;
                });
                EXPECT_EQ(n_wrong, 0) << "array kind " << kind;
                if (n_ranks > 1 || code != 0) {
                    EXPECT_GT(n_filled, 0) << "array kind " << kind;
                }
            }
        }
    }
}

TYPED_TEST(SplitGridTest, AccumulateIsTheAdjointOfFillOverAllRanks)
{
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    std::mt19937 rng(7 + static_cast<unsigned>(world.rank()));
    std::uniform_int_distribution<int> value(-20, 20);
    for (const Index<Dim>& ranks : layouts<Dim>(world.size())) {
        for (int code = 0; code < (1 << Dim); ++code) {
            const auto periodic = test::periodic_from<Dim>(code);
            SCOPED_TRACE(describe<Dim>(ranks, periodic));
            const GridPair<Dim> g = make_grids<Dim>(ranks, periodic);
            const HaloExchange<Dim> halo(g.split);
            GridArray<Dim> x(g.split);
            GridArray<Dim> y(g.split);
            for_each_cell_in_vtk_order(g.split.storage_box(), [&](const Index<Dim>& i) {
                x(i) = value(rng);
                y(i) = value(rng);
            });
            const double sum_before = world.sum(test::storage_total(g.split, y));
            GridArray<Dim> filled = x;
            halo.fill(filled);
            GridArray<Dim> accumulated = y;
            halo.accumulate(accumulated);
            // Integers: every sum is exact, so the identity holds bit for bit.
            EXPECT_EQ(world.sum(test::storage_dot(g.split, filled, y)),
                      world.sum(test::storage_dot(g.split, x, accumulated)));
            EXPECT_EQ(world.sum(test::storage_total(g.split, accumulated)), sum_before);
        }
    }
}

/// Marker positions: random points, points around the corner where the blocks of `ranks` meet
/// (the low corner of the block at coordinates 1 along each split axis), and points next to
/// the domain's low and high sides (the seam of a periodic axis). The same on every rank.
template <int Dim>
std::vector<Vec<Dim>> markers(const MacGrid<Dim>& grid, const Index<Dim>& ranks)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec<Dim>> points;
    for (int k = 0; k < 60; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            x[d] = grid.origin()[d] + unit(rng) * grid.length()[d];
        }
        points.push_back(x);
    }
    Vec<Dim> corner;
    for (int d = 0; d < Dim; ++d) {
        const int lo = ranks[ax(d)] > 1 ? block_range(grid.cells(d), ranks[ax(d)], 1).first
                                        : grid.cells(d) / 2;
        corner[d] = grid.origin()[d] + lo * grid.spacing(d);
    }
    for (int k = 0; k < 40; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            x[d] = corner[d] + (unit(rng) - 0.5) * 3.0 * grid.spacing(d);
        }
        points.push_back(x);
    }
    for (int k = 0; k < 20; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            const double near_side = unit(rng) * 1.5 * grid.spacing(d);
            x[d] = k % 2 == 0 ? grid.origin()[d] + near_side
                              : grid.origin()[d] + grid.length()[d] - near_side;
        }
        points.push_back(x);
    }
    return points;
}

TYPED_TEST(SplitGridTest, MarkersSpreadAndInterpolatedByTheirOwnersMatchOneProcess)
{
    constexpr int Dim = TypeParam::value;
    using Kernel = Peskin4Kernel;
    const Communicator world = Communicator::world();
    for (const Index<Dim>& ranks : layouts<Dim>(world.size())) {
        for (int code = 0; code < (1 << Dim); ++code) {
            const auto periodic = test::periodic_from<Dim>(code);
            SCOPED_TRACE(describe<Dim>(ranks, periodic));
            const GridPair<Dim> g = make_grids<Dim>(ranks, periodic);
            const std::vector<Vec<Dim>> points = markers<Dim>(g.whole, ranks);
            std::mt19937 rng(13);
            std::uniform_real_distribution<double> force(-1.0, 1.0);
            std::vector<Vec<Dim>> forces(points.size());
            for (auto& f : forces) {
                for (int d = 0; d < Dim; ++d) {
                    f[d] = force(rng);
                }
            }
            // Spreading (D), then the reverse halo sum.
            FaceField<Dim> reference(g.whole);
            FaceField<Dim> spread(g.split);
            int n_owned = 0;
            int n_misnamed = 0; // points whose owner rank_of_point names wrongly
            for (std::size_t m = 0; m < points.size(); ++m) {
                spread_vector<Dim, Kernel>(g.whole, reference, points[m], forces[m], 0.01);
                n_misnamed += (g.split.rank_of_point(points[m]) == world.rank()) ==
                                      g.split.owns_point(points[m])
                                  ? 0
                                  : 1;
                if (g.split.owns_point(points[m])) {
                    ASSERT_TRUE((fits_in_storage<Dim, Kernel>(g.split, points[m])));
                    spread_vector<Dim, Kernel>(g.split, spread, points[m], forces[m], 0.01);
                    ++n_owned;
                }
            }
            EXPECT_EQ(world.sum(n_owned), static_cast<double>(points.size()));
            EXPECT_EQ(n_misnamed, 0);
            HaloExchange<Dim>(g.whole).accumulate(reference);
            HaloExchange<Dim>(g.split).accumulate(spread);
            for (int a = 0; a < Dim; ++a) {
                double largest = 0.0;
                for_each_cell_in_vtk_order(g.whole.owned_faces(a), [&](const Index<Dim>& i) {
                    largest = std::max(largest, std::abs(reference[a](i)));
                });
                double worst = 0.0;
                for_each_cell_in_vtk_order(g.split.owned_faces(a), [&](const Index<Dim>& i) {
                    worst = std::max(worst, std::abs(spread[a](i) - reference[a](i)));
                });
                EXPECT_GT(largest, 0.01);
                EXPECT_LE(worst, 1e-14 * largest) << "component " << a;
            }
            // Interpolation (I) after a fill of the same owned values.
            FaceField<Dim> u_whole(g.whole);
            FaceField<Dim> u_split(g.split);
            for (int a = 0; a < Dim; ++a) {
                auto smooth = [&](const Index<Dim>& i) {
                    const Vec<Dim> x = g.whole.face_centre(a, i);
                    double v = a + 1.0;
                    for (int d = 0; d < Dim; ++d) {
                        v *= std::cos(2.0 + (d + 1) * x[d] + 0.3 * a);
                    }
                    return v;
                };
                for_each_cell_in_vtk_order(g.whole.owned_faces(a),
                                           [&](const Index<Dim>& i) { u_whole[a](i) = smooth(i); });
                for_each_cell_in_vtk_order(g.split.owned_faces(a),
                                           [&](const Index<Dim>& i) { u_split[a](i) = smooth(i); });
            }
            HaloExchange<Dim>(g.whole).fill(u_whole);
            HaloExchange<Dim>(g.split).fill(u_split);
            int n_different = 0;
            for (const Vec<Dim>& x : points) {
                if (!g.split.owns_point(x)) {
                    continue;
                }
                const Vec<Dim> expected = interpolate_velocity<Dim, Kernel>(g.whole, u_whole, x);
                const Vec<Dim> got = interpolate_velocity<Dim, Kernel>(g.split, u_split, x);
                n_different += expected == got ? 0 : 1;
            }
            EXPECT_EQ(n_different, 0);
        }
    }
}

} // namespace
} // namespace fddem
