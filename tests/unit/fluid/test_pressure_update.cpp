// SPDX-License-Identifier: MIT
// The pressure update of eq. (10), standard and rotational (fluid/pressure_correction.hpp).
//
// On a doubly periodic grid, a pressure error of one Fourier mode p_e reaches the predicted
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

namespace fddem {
namespace {

struct Outcome {
    double max_error = 0.0;      ///< max |p − expected|
    double max_pressure = 0.0;   ///< max |p|
    double max_divergence = 0.0; ///< of the corrected velocity
    FaceField<2> velocity;
};

struct ModeSetup {
    int n = 64;  // the paper's h = 1/64
    int mx = 27; ///< wavenumbers (periods over the unit box): short waves
    int my = 23;
    double density = 1.0;
    double viscosity = 0.1;
    double dt = 0.005;

    [[nodiscard]] double h() const { return 1.0 / n; }
    /// λ of the mode for the 5-point −∇² (cells) and for the face Laplacian alike.
    [[nodiscard]] double eigenvalue() const
    {
        const double pi = std::numbers::pi;
        const double sx = std::sin(pi * mx * h());
        const double sy = std::sin(pi * my * h());
        return 4.0 / (h() * h()) * (sx * sx + sy * sy);
    }
    /// The fraction of the pressure error the standard update recovers.
    [[nodiscard]] double standard_fraction() const
    {
        const double time = density / dt;
        return time / (time + viscosity * eigenvalue());
    }
};

Outcome run_update(const ModeSetup& s, PressureUpdate update, double expected_fraction)
{
    const MacGrid<2> grid({s.n, s.n}, Vec<2>::Zero(), Vec<2>::Ones());
    auto bc = BoundaryConditions<2>::closed_box();
    bc.is_periodic = {true, true};
    const FluidProperties fluid{s.density, s.viscosity};
    FluidState<2> state(grid);
    CellField<2> mode(grid);
    const double pi = std::numbers::pi;
    for_each_index(grid.cell_box(), [&](const Index<2>& c) {
        const Vec<2> x = grid.cell_centre(c);
        mode(c) = std::cos(2.0 * pi * s.mx * x[0]) * std::cos(2.0 * pi * s.my * x[1] + 0.3);
    });
    fill_cell_ghosts(grid, bc, mode);
    const double response = 1.0 / (s.density / s.dt + s.viscosity * s.eigenvalue());
    for (int a = 0; a < 2; ++a) {
        const std::ptrdiff_t stride = grid.stride(a);
        for_each_index(unknown_faces(grid, bc, a), [&](const Index<2>& c) {
            const std::ptrdiff_t o = grid.offset(c);
            state.u[a][o] = response * (mode[o] - mode[o - stride]) / s.h();
        });
    }
    fill_velocity_ghosts(grid, bc, state.u);
    state.p.fill(0.0);
    auto poisson = make_poisson_solver<2>(grid, bc.is_periodic, PoissonSettings{});
    correct_pressure_and_velocity(grid, bc, fluid, s.dt, 1.0, update, *poisson, state);

    Outcome out{0.0, 0.0, 0.0, state.u};
    CellField<2> divergence(grid);
    out.max_divergence = compute_divergence(grid, state.u, divergence);
    for_each_index(grid.owned_cells(), [&](const Index<2>& c) {
        out.max_error = std::max(out.max_error, std::abs(state.p(c) - expected_fraction * mode(c)));
        out.max_pressure = std::max(out.max_pressure, std::abs(state.p(c)));
    });
    return out;
}

TEST(PressureUpdate, RotationalRecoversThePressureErrorOfAStokesModeInOneIteration)
{
    const ModeSetup s;
    const Outcome rotational = run_update(s, PressureUpdate::rotational, 1.0);
    EXPECT_LT(rotational.max_error, 1e-10);
    EXPECT_GT(rotational.max_pressure, 0.9);
    EXPECT_LT(rotational.max_divergence, 1e-9);
}

TEST(PressureUpdate, StandardRecoversOnlyTheTimeTermsShare)
{
    const ModeSetup s;
    const double fraction = s.standard_fraction();
    EXPECT_LT(fraction, 0.1); // μλ dominates ρf/Δt for this short wave
    const Outcome standard = run_update(s, PressureUpdate::standard, fraction);
    EXPECT_LT(standard.max_error, 1e-10);
    const Outcome rotational = run_update(s, PressureUpdate::rotational, 1.0);
    for (int a = 0; a < 2; ++a) { // the velocity correction is the same projection
        for (std::size_t i = 0; i < standard.velocity[a].size(); ++i) {
            ASSERT_NEAR(standard.velocity[a].values()[i], rotational.velocity[a].values()[i],
                        1e-12);
        }
    }
}

} // namespace
} // namespace fddem
