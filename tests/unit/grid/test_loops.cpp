// SPDX-License-Identifier: MIT
// The plane wavefront of grid/loops.hpp: stages run as a wavefront over the slices across the
// outermost axis give the stages one after the other, bit for bit, for a stencil that reads a
// slice and the two beside it (here red-black Gauss–Seidel colours of a 7-point stencil with
// irrational weights, so that any change in the order of the updates shows in the last bits),
// on one thread and on two (ctest runs the tests with OMP_NUM_THREADS=1, so the tests set the
// count themselves), and on a grid periodic across the slices' axes with the periodic images
// refreshed slice by slice (HaloExchange::fill_plane), as the momentum sweeps use it.

#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace fddem {
namespace {

/// A 3D array over `box` widened by one layer on each side (the stencil's reach).
struct Field {
    explicit Field(const Box<3>& box)
        : lo(box.lo), n{box.extent(0) + 2, box.extent(1) + 2, box.extent(2) + 2},
          values(static_cast<std::size_t>(n[0] * n[1] * n[2]))
    {
    }
    [[nodiscard]] std::size_t at(int i, int j, int k) const
    {
        return static_cast<std::size_t>(((k - lo[2] + 1) * n[1] + (j - lo[1] + 1)) * n[0] +
                                        (i - lo[0] + 1));
    }
    Index<3> lo;
    std::array<int, 3> n;
    std::vector<double> values;
};

/// Relaxes the points of colour `stage % 2` in the row starting at `row`: v ← a weighted mean of
/// the six neighbours plus a source.
void relax(const Box<3>& box, int stage, const Index<3>& row, Field& f)
{
    const int j = row[1];
    const int k = row[2];
    for (int i = box.lo[0]; i < box.hi[0]; ++i) {
        if ((i + j + k + stage) % 2 != 0) {
            continue;
        }
        const std::vector<double>& v = f.values;
        f.values[f.at(i, j, k)] =
            std::sqrt(2.0) / 7.0 * (v[f.at(i - 1, j, k)] + v[f.at(i + 1, j, k)]) +
            std::sqrt(3.0) / 11.0 * (v[f.at(i, j - 1, k)] + v[f.at(i, j + 1, k)]) +
            std::sqrt(5.0) / 13.0 * (v[f.at(i, j, k - 1)] + v[f.at(i, j, k + 1)]) + 0.1 * i -
            0.03 * k;
    }
}

Field random_field(const Box<3>& box)
{
    Field f(box);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (double& x : f.values) {
        x = value(rng);
    }
    return f;
}

/// Runs `check` on one thread and on two (without OpenMP: once).
template <class F>
void on_one_and_two_threads(F&& check)
{
#ifdef FDDEM_HAVE_OPENMP
    const int threads = omp_get_max_threads();
    for (const int n : {1, 2}) {
        omp_set_num_threads(n);
        SCOPED_TRACE(::testing::Message() << n << " thread(s)");
        check();
    }
    omp_set_num_threads(threads);
#else
    check();
#endif
}

TEST(PlaneWavefront, GivesTheStagesOneAfterTheOtherBitForBit)
{
    on_one_and_two_threads([] {
        const Box<3> box{{1, 2, 3}, {40, 23, 21}}; // large enough to run on threads
        const int stages = 7;
        Field one_by_one = random_field(box);
        for (int stage = 0; stage < stages; ++stage) {
            for_each_row(box, [&](const Index<3>& row) { relax(box, stage, row, one_by_one); });
        }
        Field wavefront = random_field(box);
        std::vector<std::array<int, 2>> done;
        for_each_plane_wavefront(
            box, stages, [&](int stage, const Index<3>& row) { relax(box, stage, row, wavefront); },
            [&](int stage, int plane) {
                done.push_back({stage, plane});
            });
        ASSERT_EQ(wavefront.values.size(), one_by_one.values.size());
        for (std::size_t i = 0; i < wavefront.values.size(); ++i) {
            ASSERT_EQ(wavefront.values[i], one_by_one.values[i]) << "at entry " << i;
        }
        // Every stage visits every slice once, and reports it before the next stage reaches it.
        ASSERT_EQ(done.size(), static_cast<std::size_t>(stages * box.extent(2)));
        for (std::size_t a = 0; a < done.size(); ++a) {
            for (std::size_t b = a + 1; b < done.size(); ++b) {
                EXPECT_FALSE(done[b][0] == done[a][0] && done[b][1] == done[a][1]);
                EXPECT_FALSE(done[b][0] + 1 == done[a][0] && done[b][1] == done[a][1]);
            }
        }
        // Without the report (nullptr), the same values.
        Field unreported = random_field(box);
        for_each_plane_wavefront(
            box, stages,
            [&](int stage, const Index<3>& row) { relax(box, stage, row, unreported); }, nullptr);
        EXPECT_EQ(unreported.values, one_by_one.values);
    });
}

/// One colour of a red-black sweep of a 7-point stencil on the row of `box` at `row`, in place
/// on a grid array (its ghosts read across the periodic sides).
void relax_grid_row(const MacGrid<3>& grid, const Box<3>& box, int colour, const Index<3>& row,
                    GridArray<3>& u)
{
    double* v = u.data();
    const std::ptrdiff_t sx = grid.stride(0);
    const std::ptrdiff_t sy = grid.stride(1);
    const std::ptrdiff_t sz = grid.stride(2);
    for (int i = box.lo[0]; i < box.hi[0]; ++i) {
        if ((i + row[1] + row[2] + colour) % 2 != 0) {
            continue;
        }
        const std::ptrdiff_t o = grid.offset(Index<3>{i, row[1], row[2]});
        v[o] = std::sqrt(2.0) / 7.0 * (v[o - sx] + v[o + sx]) +
               std::sqrt(3.0) / 11.0 * (v[o - sy] + v[o + sy]) +
               std::sqrt(5.0) / 13.0 * (v[o - sz] + v[o + sz]) + 0.1 * i;
    }
}

/// Red-black colours of the 7-point stencil over a grid periodic along `periodic`, `stages`
/// of them, (a) one after the other with a full fill after each, and (b) as the wavefront the
/// momentum sweeps use: slices' images refreshed slice by slice, and, where z goes on beyond the
/// ends (periodic z), from the middle with the ends exchanged along z after each colour. Both
/// must give the same bits everywhere once the ghosts are filled; with the refresh or the
/// exchange left out they must not.
void check_sweeps_on(const Index<3>& cells, const std::array<bool, 3>& periodic)
{
    const MacGrid<3> grid(cells, Vec<3>::Zero(), Vec<3>::Ones(), periodic);
    const HaloExchange<3> halo(grid);
    ASSERT_TRUE(halo.keeps_slices_apart());
    const Box<3> box = grid.owned_cells();
    const int stages = 8;
    GridArray<3> start(grid);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for_each_cell_in_vtk_order(grid.storage_box(),
                               [&](const Index<3>& i) { start(i) = value(rng); });
    halo.fill(start);
    GridArray<3> whole = start;
    for (int stage = 0; stage < stages; ++stage) {
        for_each_row(
            box, [&](const Index<3>& row) { relax_grid_row(grid, box, stage % 2, row, whole); });
        halo.fill(whole);
    }
    const bool has_ends = periodic[2];
    const auto sweep = [&](GridArray<3>& a, bool refresh, bool exchange) {
        for_each_plane_wavefront(
            box, stages, has_ends,
            [&](int stage, const Index<3>& row) { relax_grid_row(grid, box, stage % 2, row, a); },
            [&](int, int plane) {
                if (refresh) {
                    halo.fill_plane(a, plane);
                }
            },
            [&](int) {
                if (exchange) {
                    halo.fill_axis(a, 2);
                }
            });
        halo.fill(a);
    };
    on_one_and_two_threads([&] {
        GridArray<3> sliced = start;
        sweep(sliced, true, true);
        for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<3>& i) {
            ASSERT_EQ(sliced(i), whole(i)) << i[0] << " " << i[1] << " " << i[2];
        });
        // Without the refresh (or the exchange) the seams read stale images.
        for (const bool refresh : {false, true}) {
            // Without the refresh where there are images within the slices; without the exchange
            // where z goes on beyond the ends.
            if ((refresh && !has_ends) || (!refresh && !periodic[0] && !periodic[1])) {
                continue;
            }
            GridArray<3> stale = start;
            sweep(stale, refresh, !refresh);
            std::size_t differing = 0;
            for_each_cell_in_vtk_order(
                box, [&](const Index<3>& i) { differing += stale(i) != whole(i) ? 1 : 0; });
            EXPECT_GT(differing, box.size() / 20) << "refresh " << refresh;
        }
    });
}

TEST(PlaneWavefront, RefreshingPeriodicImagesSliceBySliceGivesTheSweepsOfTheWholeGrid)
{
    // Periodic along x and y with odd counts (the colouring is then not consistent across the
    // seam, and a face reads its own colour's image there), walls along z.
    check_sweeps_on(Index<3>{33, 27, 12}, {true, true, false});
}

TEST(PlaneWavefront, FromTheMiddleWithTheEndsExchangedGivesTheSweepsAcrossAPeriodicZ)
{
    // z periodic: the wavefront from the middle, the end slices exchanged along z after each
    // colour (as with z split over ranks); an even and an odd number of slices (the halves then
    // differ by one), x periodic as well in the second.
    check_sweeps_on(Index<3>{32, 26, 14}, {false, false, true});
    check_sweeps_on(Index<3>{31, 26, 13}, {true, false, true});
}

TEST(PlaneWavefront, FromTheMiddleEveryStageMeetsBothEndsAtOneFront)
{
    // 13 slices (halves of 6 and 7), and 1, 2 and 3 (one half empty, or of one slice each).
    for (const int slices : {13, 1, 2, 3}) {
        SCOPED_TRACE(::testing::Message() << slices << " slices");
        const Box<3> box{{0, 0, 3}, {40, 23, 3 + slices}};
        const int stages = 5;
        Field one_by_one = random_field(box);
        for (int stage = 0; stage < stages; ++stage) {
            for_each_row(box, [&](const Index<3>& row) { relax(box, stage, row, one_by_one); });
        }
        on_one_and_two_threads([&] {
            Field middle = random_field(box);
            std::vector<std::array<int, 2>> visits; // (stage, plane) in order
            std::vector<int> ends;
            for_each_plane_wavefront(
                box, stages, true,
                [&](int stage, const Index<3>& row) { relax(box, stage, row, middle); },
                [&](int stage, int plane) {
                    visits.push_back({stage, plane});
                },
                [&](int stage) {
                    // Both end slices have had this stage, and neither the next.
                    int at_ends = 0;
                    for (const auto& v : visits) {
                        if (v[1] == box.lo[2] || v[1] == box.hi[2] - 1) {
                            EXPECT_LE(v[0], stage);
                            at_ends += v[0] == stage ? 1 : 0;
                        }
                    }
                    EXPECT_EQ(at_ends, box.extent(2) == 1 ? 1 : 2);
                    ends.push_back(stage);
                });
            EXPECT_EQ(middle.values, one_by_one.values);
            EXPECT_EQ(ends, (std::vector<int>{0, 1, 2, 3, 4}));
            EXPECT_EQ(visits.size(), static_cast<std::size_t>(stages * box.extent(2)));
        });
    }
}

TEST(PlaneWavefront, TheTestStencilSeesAStageRunAheadOfTheOneBefore)
{
    // All the stages over one slice before the next slice (the order a wavefront without its
    // lag would take): a stage then reads the slice above before the stage before has been
    // there, and the values differ. So this stencil tells a wrong order from the right one.
    const Box<3> box{{0, 0, 0}, {12, 9, 8}};
    const int stages = 4;
    Field one_by_one = random_field(box);
    for (int stage = 0; stage < stages; ++stage) {
        for_each_row(box, [&](const Index<3>& row) { relax(box, stage, row, one_by_one); });
    }
    Field slice_by_slice = random_field(box);
    for (int k = box.lo[2]; k < box.hi[2]; ++k) {
        for (int stage = 0; stage < stages; ++stage) {
            for (int j = box.lo[1]; j < box.hi[1]; ++j) {
                relax(box, stage, Index<3>{box.lo[0], j, k}, slice_by_slice);
            }
        }
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i < one_by_one.values.size(); ++i) {
        differing += slice_by_slice.values[i] != one_by_one.values[i] ? 1 : 0;
    }
    EXPECT_GT(differing, one_by_one.values.size() / 4);
}

TEST(PlaneWavefront, AnEmptyBoxOrNoStageCallsNothing)
{
    int calls = 0;
    const auto count = [&](int, const Index<3>&) { ++calls; };
    const auto done = [&](int, int) { ++calls; };
    for_each_plane_wavefront(Box<3>{{0, 0, 0}, {4, 4, 0}}, 3, count, done);
    for_each_plane_wavefront(Box<3>{{0, 0, 0}, {0, 4, 4}}, 3, count, done);
    for_each_plane_wavefront(Box<3>{{0, 0, 0}, {4, 0, 4}}, 3, count, done);
    for_each_plane_wavefront(Box<3>{{0, 0, 0}, {4, 4, 4}}, 0, count, done);
    EXPECT_EQ(calls, 0);
    // With an exchange at the ends, an empty block still makes every stage's (its neighbours'
    // exchanges wait for it), and nothing else.
    std::vector<int> ends;
    for_each_plane_wavefront(Box<3>{{0, 0, 0}, {4, 0, 4}}, 3, true, count, done,
                             [&](int q) { ends.push_back(q); });
    EXPECT_EQ(calls, 0);
    EXPECT_EQ(ends, (std::vector<int>{0, 1, 2}));
}

} // namespace
} // namespace fddem
