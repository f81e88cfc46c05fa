// SPDX-License-Identifier: MIT
// The FFTW Poisson solver against the exact eigenfunctions of the discrete operator: on walled
// axes cos(πm(i+½)/n) (zero-gradient, DCT-II), on periodic axes cos(2πk(i+½)/n + φ); the
// discrete Laplacian multiplies their product by Σ_d −(2 − 2cos θ_d)/h_d². So rhs = that
// product must give back product/λ to round-off, whatever the mix of walls and periodicity.

#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/fft_poisson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class FftPoisson : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(FftPoisson, Dimensions);

template <int Dim>
double max_error_for_mode(const std::array<bool, Dim>& periodic, bool is_measured)
{
    Index<Dim> cells{};
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = 12 + 4 * d;
        length[d] = 1.0 + 0.5 * d; // non-square cells
    }
    const MacGrid<Dim> grid(cells, Vec<Dim>::Zero(), length);
    constexpr double pi = std::numbers::pi;
    std::array<double, Dim> theta{};
    double lambda = 0.0;
    for (int d = 0; d < Dim; ++d) {
        const int n = grid.cells(d);
        const bool p = periodic[static_cast<std::size_t>(d)];
        theta[static_cast<std::size_t>(d)] = p ? 2.0 * pi * (d + 1) / n : pi * (d + 2) / n;
        lambda -= (2.0 - 2.0 * std::cos(theta[static_cast<std::size_t>(d)])) /
                  (grid.spacing(d) * grid.spacing(d));
    }
    const auto mode = [&](const Index<Dim>& c) {
        double value = 1.0;
        for (int d = 0; d < Dim; ++d) {
            const auto k = static_cast<std::size_t>(d);
            const double phase = periodic[k] ? 0.3 : 0.0;
            value *= std::cos(theta[k] * (c[k] + 0.5) + phase);
        }
        return value;
    };
    CellField<Dim> rhs(grid);
    CellField<Dim> phi(grid);
    // A constant added to rhs lies in the operator's null space: the solver must drop it.
    for_each_index(grid.cell_box(), [&](const Index<Dim>& c) { rhs(c) = mode(c) + 7.0; });
    FftPoissonSolver<Dim> solver(grid, periodic, is_measured);
    solver.solve(rhs, phi);
    return max_over(grid.communicator(), grid.owned_cells(),
                    [&](const Index<Dim>& c) { return std::abs(phi(c) - mode(c) / lambda); }) *
           std::abs(lambda);
}

TYPED_TEST(FftPoisson, InvertsDiscreteEigenfunctionsForEveryBoundaryMix)
{
    constexpr int Dim = TypeParam::value;
    for (int mask = 0; mask < (1 << Dim); ++mask) {
        std::array<bool, Dim> periodic{};
        for (int d = 0; d < Dim; ++d) {
            periodic[static_cast<std::size_t>(d)] = ((mask >> d) & 1) != 0;
        }
        // Round-off of two transforms of O(100) points: 1e-12 relative to the mode amplitude.
        EXPECT_LT(max_error_for_mode<Dim>(periodic, false), 1e-12) << "periodic mask " << mask;
        EXPECT_LT(max_error_for_mode<Dim>(periodic, true), 1e-12) << "measured, mask " << mask;
    }
}

TEST(FftPoisson, EstimatedPlansGiveBitIdenticalRepeats)
{
    const MacGrid<2> grid({32, 24}, Vec<2>::Zero(), Vec<2>(1.0, 0.75));
    CellField<2> rhs(grid);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) {
        rhs(c) = std::sin(0.3 * c[0]) * std::cos(0.2 * c[1]);
    });
    CellField<2> first(grid);
    CellField<2> second(grid);
    FftPoissonSolver<2>(grid, {false, true}, false).solve(rhs, first);
    FftPoissonSolver<2>(grid, {false, true}, false).solve(rhs, second);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) { EXPECT_EQ(first(c), second(c)); });
}

TEST(FftPoisson, RestoredPlansSolveAsTheRecordedOnes)
{
    // A checkpoint carries the measured plans (FFTW wisdom) so that the continuing process
    // transforms exactly as the one that wrote it. Within one process the measurement may well
    // pick the same plan anyway; what is checked is that the record exists for measured plans,
    // is empty for estimated ones (identical everywhere), and that restoring it replans a
    // working solver with identical answers.
    const MacGrid<2> grid({40, 24}, Vec<2>::Zero(), Vec<2>(1.0, 0.6));
    CellField<2> rhs(grid);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) {
        rhs(c) = std::sin(0.3 * c[0]) * std::cos(0.2 * c[1]);
    });
    FftPoissonSolver<2> recorded(grid, {false, true}, true);
    const std::string record = recorded.plan_record();
    EXPECT_NE(record.find("fftw_wisdom"), std::string::npos) << record;
    EXPECT_TRUE(FftPoissonSolver<2>(grid, {false, true}, false).plan_record().empty());

    FftPoissonSolver<2> restored(grid, {false, true}, true);
    restored.restore_plans(record);
    CellField<2> first(grid);
    CellField<2> second(grid);
    recorded.solve(rhs, first);
    restored.solve(rhs, second);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) { EXPECT_EQ(first(c), second(c)); });
}

} // namespace
} // namespace fddem
