// SPDX-License-Identifier: MIT
// The pressure-correction Poisson problem on a grid split across MPI ranks (issue 15): hypre's
// PFMG-preconditioned CG on the ranks' blocks gives the one-process solution, to far below the
// solver's tolerance, and FFTW-MPI's slab transforms give the one-process FFT solution to
// round-off, with walls and periodic sides, in 2D and 3D, on several layouts; the two split
// solvers agree. Run under mpirun -n 1, 2, 4.

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/hypre_poisson.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "support/split_compare.hpp"

namespace fddem {
namespace {

template <class T>
class SplitPoissonTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SplitPoissonTest, Dimensions);

template <int Dim>
Index<Dim> poisson_cells()
{
    if constexpr (Dim == 2) {
        return {26, 20};
    } else {
        return {14, 13, 12};
    }
}

/// A right-hand side with structure at every scale, from the global index alone.
template <int Dim>
double source(const Index<Dim>& c)
{
    double phase = 0.0;
    for (int d = 0; d < Dim; ++d) {
        phase += (1.7 + d) * c[static_cast<std::size_t>(d)] * (1.0 + 0.05 * d);
    }
    return std::sin(phase) + 0.3 * std::cos(0.21 * phase * phase);
}

/// A box of unequal sides, so that the axes are not interchangeable.
template <int Dim>
Vec<Dim> box_lengths()
{
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        length[d] = 1.0 + 0.5 * d;
    }
    return length;
}

/// Solves for source() on `grid` with `settings`, `repeats` times with the same solver (a
/// later solve must not depend on what an earlier one left behind); returns the solver.
template <int Dim>
std::unique_ptr<PoissonSolver<Dim>>
solve_source(const MacGrid<Dim>& grid, const std::array<bool, Dim>& periodic,
             const PoissonSettings& settings, CellField<Dim>& phi, int repeats = 1)
{
    CellField<Dim> rhs(grid);
    for_each_cell_in_vtk_order(grid.owned_cells(),
                               [&](const Index<Dim>& c) { rhs(c) = source<Dim>(c); });
    auto solver = make_poisson_solver<Dim>(grid, periodic, settings);
    for (int k = 0; k < repeats; ++k) {
        solver->solve(rhs, phi);
    }
    return solver;
}

TYPED_TEST(SplitPoissonTest, HypreOnTheBlocksGivesTheOneProcessSolution)
{
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    const Index<Dim> cells = poisson_cells<Dim>();
    for (int code : {0, 1, (1 << Dim) - 1}) {
        const std::array<bool, Dim> periodic = test::periodic_from<Dim>(code);
        SCOPED_TRACE("periodic code " + std::to_string(code));
        const Vec<Dim> origin = Vec<Dim>::Zero();
        const Vec<Dim> length = box_lengths<Dim>();
        const MacGrid<Dim> whole(cells, origin, length, periodic);
        const Index<Dim> ranks = choose_rank_layout<Dim>(cells, world.size());
        const MacGrid<Dim> split(cells, origin, length, periodic,
                                 partition_grid<Dim>(world, cells, periodic, ranks));
        PoissonSettings settings;
        settings.kind = PoissonSolverKind::hypre;
        settings.tolerance = 1e-12;
        settings.max_iterations = 500;

        CellField<Dim> phi_whole(whole);
        const auto solver_whole = solve_source<Dim>(whole, periodic, settings, phi_whole);
        CellField<Dim> phi_split(split);
        const auto solver_split = solve_source<Dim>(split, periodic, settings, phi_split);
        const auto [worst, largest] =
            test::compare_owned<Dim>(world, split.owned_cells(), phi_split, phi_whole);
        EXPECT_GT(largest, 1e-3);
        EXPECT_LE(worst, 1e-9 * largest)
            << "iterations: one process " << solver_whole->last_iterations() << ", split "
            << solver_split->last_iterations();
        if (world.rank() == 0) {
            std::printf("[ info ] %dD periodic code %d on %d ranks: max |Δφ|/max|φ| = %.2e, "
                        "iterations %d (one process) and %d (split)\n",
                        Dim, code, world.size(), worst / largest, solver_whole->last_iterations(),
                        solver_split->last_iterations());
        }
    }
}

/// The layouts the FFTW-MPI solver is checked on for `n` ranks: the automatic one, slabs
/// across x (every cell changes rank on the way to FFTW's slabs), slabs across the last axis
/// (FFTW's own), and on 4 ranks 2 × 2 blocks.
template <int Dim>
std::vector<Index<Dim>> fft_layouts(const Index<Dim>& cells, int n)
{
    std::vector<Index<Dim>> layouts{choose_rank_layout<Dim>(cells, n)};
    Index<Dim> across_x;
    across_x.fill(1);
    across_x[0] = n;
    layouts.push_back(across_x);
    Index<Dim> across_last; // FFTW-MPI's own slabs where the counts agree: local copies
    across_last.fill(1);
    across_last[Dim - 1] = n;
    layouts.push_back(across_last);
    if (n == 4) {
        Index<Dim> square;
        square.fill(1);
        square[0] = 2;
        square[1] = 2;
        layouts.push_back(square);
    }
    return layouts;
}

TYPED_TEST(SplitPoissonTest, FftwMpiOnSlabsGivesTheOneProcessFftSolution)
{
    // The same transforms as the one-process solver in another order: the answers agree to
    // round-off, on every layout of the blocks, with walls and periodic sides.
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    const Index<Dim> cells = poisson_cells<Dim>();
    for (int code : {0, 1, (1 << Dim) - 1}) {
        const std::array<bool, Dim> periodic = test::periodic_from<Dim>(code);
        const Vec<Dim> origin = Vec<Dim>::Zero();
        const Vec<Dim> length = box_lengths<Dim>();
        const MacGrid<Dim> whole(cells, origin, length, periodic);
        PoissonSettings settings;
        settings.kind = PoissonSolverKind::fft;
        CellField<Dim> phi_whole(whole);
        static_cast<void>(solve_source<Dim>(whole, periodic, settings, phi_whole));
        const double largest =
            test::compare_owned<Dim>(world, whole.owned_cells(), phi_whole, phi_whole).second;
        ASSERT_GT(largest, 1e-3);

        for (const Index<Dim>& ranks : fft_layouts<Dim>(cells, world.size())) {
            std::string layout;
            for (const int r : ranks) {
                layout += std::to_string(r) + " ";
            }
            SCOPED_TRACE("periodic code " + std::to_string(code) + ", layout " + layout);
            check_rank_layout<Dim>(cells, ranks, world.size());
            const MacGrid<Dim> split(cells, origin, length, periodic,
                                     partition_grid<Dim>(world, cells, periodic, ranks));
            CellField<Dim> phi_split(split);
            const auto solver_split = solve_source<Dim>(split, periodic, settings, phi_split, 2);
            if (world.size() > 1) {
                EXPECT_EQ(solver_split->name(), "FFTW-MPI direct (slabs)");
            }
            const double worst =
                test::compare_owned<Dim>(world, split.owned_cells(), phi_split, phi_whole).first;
            EXPECT_LE(worst, 1e-13 * largest);
            if (world.rank() == 0) {
                std::printf("[ info ] %dD periodic code %d, layout %son %d ranks: FFTW-MPI "
                            "against one process, max |Δφ|/max|φ| = %.2e\n",
                            Dim, code, layout.c_str(), world.size(), worst / largest);
            }
        }
    }
}

TYPED_TEST(SplitPoissonTest, FftwMpiAndHypreAgreeOnTheSameSplitGrid)
{
    // The two split solvers tested against each other (issue 15): hypre to its tolerance.
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    const Index<Dim> cells = poisson_cells<Dim>();
    std::array<bool, Dim> periodic{};
    periodic[0] = true;
    const MacGrid<Dim> split(
        cells, Vec<Dim>::Zero(), box_lengths<Dim>(), periodic,
        partition_grid<Dim>(world, cells, periodic, choose_rank_layout<Dim>(cells, world.size())));
    PoissonSettings settings;
    settings.kind = PoissonSolverKind::fft;
    CellField<Dim> phi_fft(split);
    static_cast<void>(solve_source<Dim>(split, periodic, settings, phi_fft));
    settings.kind = PoissonSolverKind::hypre;
    settings.tolerance = 1e-12;
    settings.max_iterations = 500;
    CellField<Dim> phi_hypre(split);
    static_cast<void>(solve_source<Dim>(split, periodic, settings, phi_hypre));
    const auto [worst, largest] =
        test::compare_owned<Dim>(world, split.owned_cells(), phi_hypre, phi_fft);
    EXPECT_GT(largest, 1e-3);
    EXPECT_LE(worst, 1e-9 * largest);
}

TEST(SplitPoisson, AutomaticChoiceIsFftwMpiUnlessRanksOutnumberItsPlanes)
{
    const Communicator world = Communicator::world();
    if (world.size() == 1) {
        GTEST_SKIP() << "needs more than one rank";
    }
    const std::array<bool, 2> periodic{true, false};
    PoissonSettings settings; // automatic
    const auto solver_name = [&](const Index<2>& cells, const Index<2>& ranks) {
        const MacGrid<2> split(cells, Vec<2>::Zero(), Vec<2>::Ones(), periodic,
                               partition_grid<2>(world, cells, periodic, ranks));
        return make_poisson_solver<2>(split, periodic, settings)->name();
    };
    const int n = world.size();
    EXPECT_EQ(solver_name({26, 20}, {1, n}), "FFTW-MPI direct (slabs)");
    if (n >= 4) {
        // Split along x with fewer y planes than ranks: FFTW-MPI would leave ranks idle.
        EXPECT_EQ(solver_name({3 * n, n - 1}, {n, 1}), "hypre PFMG-PCG");
    }
}

} // namespace
} // namespace fddem
