// SPDX-License-Identifier: MIT
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class Transfer : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Transfer, Dimensions);

template <int Dim>
MacGrid<Dim> grid_for_test()
{
    Index<Dim> cells{};
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = 10;
        length[d] = 1.0;
    }
    return MacGrid<Dim>(cells, Vec<Dim>::Zero(), length);
}

TYPED_TEST(Transfer, HatInterpolationIsExactForLinearFields)
{
    constexpr int Dim = TypeParam::value;
    const auto grid = grid_for_test<Dim>();
    FaceField<Dim> u(grid);
    const Vec<Dim> g = Vec<Dim>::LinSpaced(0.5, 2.0);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            u[a](c) = a + g.dot(grid.face_centre(a, c));
        }
    });
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(0.2, 0.8);
    for (int k = 0; k < 100; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            x[d] = coordinate(rng);
        }
        const Vec<Dim> v = interpolate_velocity<Dim, HatKernel>(grid, u, x);
        for (int a = 0; a < Dim; ++a) {
            EXPECT_NEAR(v[a], a + g.dot(x), 1e-12);
        }
    }
}

template <int Dim, class Kernel>
void check_adjoint_and_conservation()
{
    const auto grid = grid_for_test<Dim>();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_real_distribution<double> coordinate(0.3, 0.7);
    FaceField<Dim> u(grid);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            u[a](c) = value(rng);
        }
    });
    FaceField<Dim> spread(grid);
    double lagrangian = 0.0;
    Vec<Dim> total = Vec<Dim>::Zero();
    for (int l = 0; l < 20; ++l) {
        Vec<Dim> x;
        Vec<Dim> f;
        for (int d = 0; d < Dim; ++d) {
            x[d] = coordinate(rng);
            f[d] = value(rng);
        }
        const double volume = 0.001 * (1 + l);
        spread_vector<Dim, Kernel>(grid, spread, x, f, volume);
        lagrangian += volume * f.dot(interpolate_velocity<Dim, Kernel>(grid, u, x));
        total += volume * f;
    }
    double eulerian = 0.0;
    Vec<Dim> spread_total = Vec<Dim>::Zero();
    for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            eulerian += spread[a](c) * u[a](c) * grid.cell_volume();
            spread_total[a] += spread[a](c) * grid.cell_volume();
        }
    });
    // ⟨D F, u⟩ = ⟨F, I u⟩ with the ΔV weights: the same sums in another order.
    EXPECT_NEAR(eulerian, lagrangian, 1e-12 * std::abs(lagrangian) + 1e-15);
    // Momentum added by eq. (16) is Σ ΔV_l F_l exactly (partition of unity).
    EXPECT_LT((spread_total - total).norm(), 1e-14);
}

TYPED_TEST(Transfer, SpreadIsTheAdjointOfInterpolationAndConservesMomentum)
{
    constexpr int Dim = TypeParam::value;
    check_adjoint_and_conservation<Dim, HatKernel>();
    check_adjoint_and_conservation<Dim, RomaPeskin3Kernel>();
    check_adjoint_and_conservation<Dim, Peskin4Kernel>();
}

} // namespace
} // namespace fddem
