// SPDX-License-Identifier: MIT
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/grid/sampling.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class Sampling : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Sampling, Dimensions);

TYPED_TEST(Sampling, ReproducesLinearFieldsExactlyEverywhereInTheBox)
{
    constexpr int Dim = TypeParam::value;
    Index<Dim> cells{};
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = 6 + d;
        length[d] = 1.0 + d;
    }
    const MacGrid<Dim> grid(cells, Vec<Dim>::Constant(-0.5), length);
    // The ghosts hold the linear field too: the interpolation, not the wall condition, is
    // under test (boundary conditions have their own tests).
    const Vec<Dim> gradient = Vec<Dim>::LinSpaced(0.3, 1.7);
    const auto linear = [&](const Vec<Dim>& x, int a) {
        return a + 1.0 + gradient.dot(x) * (a + 1);
    };
    FaceField<Dim> u(grid);
    CellField<Dim> p(grid);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            u[a](c) = linear(grid.face_centre(a, c), a);
        }
        p(c) = linear(grid.cell_centre(c), Dim);
    });
    std::mt19937 rng(7);
    for (int k = 0; k < 200; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            x[d] = std::uniform_real_distribution<double>(-0.5, -0.5 + length[d])(rng);
        }
        if (k == 0) {
            x = grid.origin(); // a corner of the box
        }
        const Vec<Dim> v = sample_velocity(grid, u, x);
        for (int a = 0; a < Dim; ++a) {
            EXPECT_NEAR(v[a], linear(x, a), 1e-12);
        }
        EXPECT_NEAR(sample_cell_field(grid, p, x), linear(x, Dim), 1e-12);
    }
}

TEST(Vorticity, SolidRotationHasVorticityTwiceTheRate)
{
    const MacGrid<2> grid({8, 8}, Vec<2>::Zero(), Vec<2>::Ones());
    FaceField<2> u(grid);
    for_each_index(grid.storage_box(), [&](const Index<2>& c) {
        u[0](c) = -grid.face_centre(0, c)[1];
        u[1](c) = grid.face_centre(1, c)[0];
    });
    CellField<2> omega(grid);
    cell_centred_vorticity(grid, u, 0, 1, omega);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) { EXPECT_NEAR(omega(c), 2.0, 1e-12); });
}

} // namespace
} // namespace fddem
