// SPDX-License-Identifier: MIT
// The pressure-correction Poisson problem on a grid split across MPI ranks (issue 15): hypre's
// PFMG-preconditioned CG on the ranks' blocks gives the one-process solution, to far below the
// solver's tolerance, with walls and periodic sides, in 2D and 3D. Run under mpirun -n 1, 2, 4.

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/hypre_poisson.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

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

TYPED_TEST(SplitPoissonTest, HypreOnTheBlocksGivesTheOneProcessSolution)
{
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    const Index<Dim> cells = poisson_cells<Dim>();
    for (int code : {0, 1, (1 << Dim) - 1}) {
        std::array<bool, Dim> periodic{};
        for (int d = 0; d < Dim; ++d) {
            periodic[static_cast<std::size_t>(d)] = ((code >> d) & 1) != 0;
        }
        SCOPED_TRACE("periodic code " + std::to_string(code));
        const Vec<Dim> origin = Vec<Dim>::Zero();
        Vec<Dim> length;
        for (int d = 0; d < Dim; ++d) {
            length[d] = 1.0 + 0.5 * d;
        }
        const MacGrid<Dim> whole(cells, origin, length, periodic);
        const Index<Dim> ranks = choose_rank_layout<Dim>(cells, world.size());
        const MacGrid<Dim> split(cells, origin, length, periodic,
                                 partition_grid<Dim>(world, cells, periodic, ranks));
        PoissonSettings settings;
        settings.kind = PoissonSolverKind::hypre;
        settings.tolerance = 1e-12;
        settings.max_iterations = 500;

        CellField<Dim> rhs_whole(whole);
        CellField<Dim> phi_whole(whole);
        for_each_cell_in_vtk_order(whole.owned_cells(),
                                   [&](const Index<Dim>& c) { rhs_whole(c) = source<Dim>(c); });
        auto solver_whole = make_poisson_solver<Dim>(whole, periodic, settings);
        solver_whole->solve(rhs_whole, phi_whole);

        CellField<Dim> rhs_split(split);
        CellField<Dim> phi_split(split);
        for_each_cell_in_vtk_order(split.owned_cells(),
                                   [&](const Index<Dim>& c) { rhs_split(c) = source<Dim>(c); });
        auto solver_split = make_poisson_solver<Dim>(split, periodic, settings);
        solver_split->solve(rhs_split, phi_split);

        double largest = 0.0;
        for_each_cell_in_vtk_order(whole.owned_cells(), [&](const Index<Dim>& c) {
            largest = std::max(largest, std::abs(phi_whole(c)));
        });
        double worst = 0.0;
        for_each_cell_in_vtk_order(split.owned_cells(), [&](const Index<Dim>& c) {
            worst = std::max(worst, std::abs(phi_split(c) - phi_whole(c)));
        });
        worst = world.max(worst);
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

TEST(SplitPoisson, TheFftSolverIsRefusedOnASplitGrid)
{
    const Communicator world = Communicator::world();
    if (world.size() == 1) {
        GTEST_SKIP() << "needs more than one rank";
    }
    const Index<2> cells{26, 20};
    const std::array<bool, 2> periodic{true, false};
    const MacGrid<2> split(
        cells, Vec<2>::Zero(), Vec<2>::Ones(), periodic,
        partition_grid<2>(world, cells, periodic, choose_rank_layout<2>(cells, world.size())));
    PoissonSettings settings;
    settings.kind = PoissonSolverKind::fft;
    try {
        static_cast<void>(make_poisson_solver<2>(split, periodic, settings));
        FAIL() << "fft on a split grid";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "simple.pressure_solver");
    }
}

} // namespace
} // namespace fddem
