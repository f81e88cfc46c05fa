// SPDX-License-Identifier: MIT
// The pressure update of eq. (10), standard and rotational (fluid/pressure_correction.hpp).
//
// On a periodic grid (2D and 3D), a pressure error of one Fourier mode p_e reaches the predicted
// velocity the way the momentum equations pass it on: u* = (ρf/Δt + μλ)⁻¹ ∇p_e, with λ the
// mode's eigenvalue of the discrete −∇². The standard update then recovers the fraction
// (ρf/Δt)/(ρf/Δt + μλ) of p_e (0.05 for the shortest waves of the paper's cases: the slow
// outer iterations this update was made for), the rotational update all of it; both leave the
// same, discretely divergence-free velocity.

#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <type_traits>

namespace fddem {
namespace {

template <int Dim>
struct Outcome {
    double max_error = 0.0;      ///< max |p − expected|
    double max_pressure = 0.0;   ///< max |p|
    double max_divergence = 0.0; ///< of the corrected velocity
    FaceField<Dim> velocity;
};

/// A short pressure wave on a periodic unit box: the paper's h = 1/64 in 2D (48 cells a side in
/// 3D), wavenumbers near the grid's shortest.
template <int Dim>
struct ModeSetup {
    int n = Dim == 2 ? 64 : 48;
    std::array<int, 3> m =
        Dim == 2 ? std::array<int, 3>{27, 23, 0} : std::array<int, 3>{23, 21, 19};
    double density = 1.0;
    double viscosity = 0.1;
    double dt = 0.005;

    [[nodiscard]] double h() const { return 1.0 / n; }
    /// λ of the mode for the (2·Dim + 1)-point −∇² (cells) and for the face Laplacian alike.
    [[nodiscard]] double eigenvalue() const
    {
        double sum = 0.0;
        for (int d = 0; d < Dim; ++d) {
            const double s = std::sin(std::numbers::pi * m[static_cast<std::size_t>(d)] * h());
            sum += s * s;
        }
        return 4.0 / (h() * h()) * sum;
    }
    /// The fraction of the pressure error the standard update recovers.
    [[nodiscard]] double standard_fraction() const
    {
        const double time = density / dt;
        return time / (time + viscosity * eigenvalue());
    }
};

template <int Dim>
Outcome<Dim> run_update(const ModeSetup<Dim>& s, PressureUpdate update, double expected_fraction)
{
    Index<Dim> cells{};
    cells.fill(s.n);
    auto bc = BoundaryConditions<Dim>::closed_box();
    bc.is_periodic.fill(true);
    const MacGrid<Dim> grid(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), bc.is_periodic);
    const FluidProperties fluid{s.density, s.viscosity};
    FluidState<Dim> state(grid);
    CellField<Dim> mode(grid);
    for_each_index(grid.cell_box(), [&](const Index<Dim>& c) {
        const Vec<Dim> x = grid.cell_centre(c);
        double value = 1.0;
        for (int d = 0; d < Dim; ++d) {
            value *= std::cos(2.0 * std::numbers::pi * s.m[static_cast<std::size_t>(d)] * x[d] +
                              0.3 * d);
        }
        mode(c) = value;
    });
    fill_cell_ghosts(grid, bc, mode);
    const double response = 1.0 / (s.density / s.dt + s.viscosity * s.eigenvalue());
    for (int a = 0; a < Dim; ++a) {
        const std::ptrdiff_t stride = grid.stride(a);
        for_each_index(unknown_faces(grid, bc, a), [&](const Index<Dim>& c) {
            const std::ptrdiff_t o = grid.offset(c);
            state.u[a][o] = response * (mode[o] - mode[o - stride]) / s.h();
        });
    }
    fill_velocity_ghosts(grid, bc, state.u);
    state.p.fill(0.0);
    auto poisson = make_poisson_solver<Dim>(grid, bc.is_periodic, PoissonSettings{});
    correct_pressure_and_velocity(grid, bc, fluid, s.dt, 1.0, update, *poisson, state);

    Outcome<Dim> out{0.0, 0.0, 0.0, state.u};
    CellField<Dim> divergence(grid);
    out.max_divergence = compute_divergence(grid, state.u, divergence);
    for_each_index(grid.owned_cells(), [&](const Index<Dim>& c) {
        out.max_error = std::max(out.max_error, std::abs(state.p(c) - expected_fraction * mode(c)));
        out.max_pressure = std::max(out.max_pressure, std::abs(state.p(c)));
    });
    return out;
}

template <class T>
class PressureUpdateTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(PressureUpdateTest, Dimensions);

TYPED_TEST(PressureUpdateTest, RotationalRecoversThePressureErrorOfAStokesModeInOneIteration)
{
    constexpr int Dim = TypeParam::value;
    const ModeSetup<Dim> s;
    const Outcome<Dim> rotational = run_update(s, PressureUpdate::rotational, 1.0);
    EXPECT_LT(rotational.max_error, 1e-10);
    EXPECT_GT(rotational.max_pressure, 0.9);
    EXPECT_LT(rotational.max_divergence, 1e-9);
}

TYPED_TEST(PressureUpdateTest, StandardRecoversOnlyTheTimeTermsShare)
{
    constexpr int Dim = TypeParam::value;
    const ModeSetup<Dim> s;
    const double fraction = s.standard_fraction();
    EXPECT_LT(fraction, 0.1); // μλ dominates ρf/Δt for this short wave
    const Outcome<Dim> standard = run_update(s, PressureUpdate::standard, fraction);
    EXPECT_LT(standard.max_error, 1e-10);
    const Outcome<Dim> rotational = run_update(s, PressureUpdate::rotational, 1.0);
    for (int a = 0; a < Dim; ++a) { // the velocity correction is the same projection
        for (std::size_t i = 0; i < standard.velocity[a].size(); ++i) {
            ASSERT_NEAR(standard.velocity[a].values()[i], rotational.velocity[a].values()[i],
                        1e-12);
        }
    }
}

} // namespace
} // namespace fddem
