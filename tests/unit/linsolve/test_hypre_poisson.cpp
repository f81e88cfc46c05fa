// SPDX-License-Identifier: MIT
// hypre's PFMG-preconditioned CG against the FFTW direct solver on the same discrete problem:
// the two solvers behind one interface must agree (issue 2).

#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/fft_poisson.hpp"
#include "fddem/linsolve/hypre_poisson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class HyprePoisson : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(HyprePoisson, Dimensions);

template <int Dim>
MacGrid<Dim> test_grid()
{
    Index<Dim> cells{};
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = Dim == 2 ? 48 + 16 * d : 12 + 4 * d;
        length[d] = 1.0 + 0.25 * d;
    }
    return MacGrid<Dim>(cells, Vec<Dim>::Zero(), length);
}

template <int Dim>
void fill_rhs(const MacGrid<Dim>& grid, CellField<Dim>& rhs)
{
    for_each_index(grid.cell_box(), [&](const Index<Dim>& c) {
        const Vec<Dim> x = grid.cell_centre(c);
        double value = std::exp(-10.0 * (x - Vec<Dim>::Constant(0.4)).squaredNorm());
        value += std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]);
        rhs(c) = value;
    });
}

TYPED_TEST(HyprePoisson, AgreesWithTheFftSolverForEveryBoundaryMix)
{
    constexpr int Dim = TypeParam::value;
    const MacGrid<Dim> grid = test_grid<Dim>();
    CellField<Dim> rhs(grid);
    fill_rhs(grid, rhs);
    for (const bool periodic_x : {false, true}) {
        std::array<bool, Dim> periodic{};
        periodic[0] = periodic_x;
        CellField<Dim> direct(grid);
        CellField<Dim> iterative(grid);
        FftPoissonSolver<Dim>(grid, periodic).solve(rhs, direct);
        HyprePoissonSolver<Dim> hypre(grid, periodic, 1e-12, 500);
        hypre.solve(rhs, iterative);
        const double scale = max_over(grid.communicator(), grid.owned_cells(),
                                      [&](const Index<Dim>& c) { return std::abs(direct(c)); });
        const double difference =
            max_over(grid.communicator(), grid.owned_cells(),
                     [&](const Index<Dim>& c) { return std::abs(direct(c) - iterative(c)); });
        // CG stopped at a relative residual of 1e-12; with the operator's condition number
        // O(n²) ≈ 1e4 the solution error is below 1e-8 of its size.
        EXPECT_LT(difference, 1e-8 * scale) << "periodic x: " << periodic_x;
        EXPECT_LE(hypre.last_relative_residual(), 1e-12);
        EXPECT_LT(hypre.last_iterations(), 60); // multigrid: iterations do not grow with n

        // Warm start from the converged answer: nothing left to do.
        hypre.solve(rhs, iterative);
        EXPECT_LE(hypre.last_iterations(), 1);
    }
}

} // namespace
} // namespace fddem
