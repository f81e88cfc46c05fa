// SPDX-License-Identifier: MIT
// The momentum solve: multigrid V-cycles reach the same solution of the discrete momentum
// system as Gauss–Seidel sweeps alone (walls, a moving lid, periodic axes; 2D and 3D), and get
// there in a fraction of the fine-grid sweeps.

#include "fddem/fluid/momentum.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class MomentumSolve : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(MomentumSolve, Dimensions);

/// A smooth flow and pressure, so that the systems have all scales in their right-hand sides.
template <int Dim>
void fill_state(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, FluidState<Dim>& state)
{
    for (int a = 0; a < Dim; ++a) {
        for_each_index(grid.face_box(a), [&](const Index<Dim>& c) {
            const Vec<Dim> x = grid.face_centre(a, c);
            state.u[a](c) = std::sin(3.0 * x[0] + a) * std::cos(2.0 * x[1]);
            state.u_n[a](c) = 0.5 * state.u[a](c);
        });
    }
    for_each_index(grid.cell_box(), [&](const Index<Dim>& c) {
        const Vec<Dim> x = grid.cell_centre(c);
        state.p(c) = std::cos(x[0]) * x[1];
    });
    fill_velocity_ghosts(grid, bc, state.u);
    fill_cell_ghosts(grid, bc, state.p);
}

/// Max |a − b| over the unknown faces of component `axis`.
template <int Dim>
double max_difference(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                      const FluidState<Dim>& a, const FluidState<Dim>& b)
{
    return max_over(grid.communicator(), unknown_faces(grid, bc, axis),
                    [&](const Index<Dim>& c) { return std::abs(a.u[axis](c) - b.u[axis](c)); });
}

template <int Dim>
void expect_multigrid_matches_sweeps(const BoundaryConditions<Dim>& bc)
{
    Index<Dim> cells{};
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = Dim == 2 ? 40 + 8 * d : 24 + 4 * d;
    }
    const MacGrid<Dim> grid(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), bc.is_periodic);
    const FluidProperties fluid{1.0, 1.0}; // cell Péclet number 0.025: viscous links dominate
    // Δt such that the time term is 2 % of the viscous links: the regime where Gauss–Seidel
    // stalls (the paper's Fig. 5 case at h = 1/160).
    const double h = grid.spacing(0);
    const double dt = 0.5 * fluid.density * h * h / (0.02 * 2 * Dim * fluid.viscosity);
    FluidState<Dim> start(grid);
    fill_state(grid, bc, start);

    for (int axis = 0; axis < Dim; ++axis) {
        SCOPED_TRACE(axis);
        MomentumSettings sweeps_alone{ConvectionScheme::central, 1.0, 4000, 0};
        MomentumSettings multigrid{ConvectionScheme::central, 1.0, 4, 1};
        MomentumSystem<Dim> system(grid);
        static_cast<void>(
            assemble_momentum(grid, bc, fluid, sweeps_alone, TimeLevels{dt}, start, axis, system));

        FluidState<Dim> reference = start;
        solve_momentum(grid, bc, sweeps_alone, system, axis, reference);
        const double scale =
            max_over(grid.communicator(), unknown_faces(grid, bc, axis),
                     [&](const Index<Dim>& c) { return std::abs(reference.u[axis](c)); });

        // Both start from rest: an error of every scale.
        FluidState<Dim> at_rest = start;
        for_each_index(unknown_faces(grid, bc, axis),
                       [&](const Index<Dim>& c) { at_rest.u[axis](c) = 0.0; });
        fill_velocity_ghosts(grid, bc, at_rest.u);
        FluidState<Dim> cycled = at_rest;
        for (int k = 0; k < 3; ++k) {
            solve_momentum(grid, bc, multigrid, system, axis, cycled);
        }
        // Twelve fine sweeps in all, against twelve sweeps alone.
        FluidState<Dim> swept = at_rest;
        MomentumSettings twelve = sweeps_alone;
        twelve.sweeps = 12;
        solve_momentum(grid, bc, twelve, system, axis, swept);
        const double cycled_error = max_difference(grid, bc, axis, cycled, reference) / scale;
        const double swept_error = max_difference(grid, bc, axis, swept, reference) / scale;
        EXPECT_LT(cycled_error, 0.1 * swept_error);

        for (int k = 0; k < 40; ++k) {
            solve_momentum(grid, bc, multigrid, system, axis, cycled);
        }
        EXPECT_LT(max_difference(grid, bc, axis, cycled, reference) / scale, 1e-9);
    }
}

TYPED_TEST(MomentumSolve, MultigridReachesTheSweepsSolutionInAFractionOfTheSweeps)
{
    constexpr int Dim = TypeParam::value;
    auto walls = BoundaryConditions<Dim>::closed_box();
    walls.wall_velocity[1][1][0] = 1.0; // a lid
    expect_multigrid_matches_sweeps<Dim>(walls);

    auto periodic = BoundaryConditions<Dim>::closed_box();
    periodic.is_periodic[0] = true;
    expect_multigrid_matches_sweeps<Dim>(periodic);
}

/// max |r/a_P| over the unknown faces of `axis`, from the unscaled system: r = b − (p_P − p_W)
/// ΔV/h + Σ a_nb u_nb − a_P u_P (momentum.hpp), written out here apart from the solver's own.
template <int Dim>
double residual_over_a_p(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int axis,
                         const MomentumSystem<Dim>& system, const FluidState<Dim>& state)
{
    const GridArray<Dim>& u = state.u[axis];
    return max_over(grid.communicator(), unknown_faces(grid, bc, axis), [&](const Index<Dim>& c) {
        const std::ptrdiff_t o = grid.offset(c);
        double r = system.b[o] - (state.p[o] - state.p[o - grid.stride(axis)]) *
                                     grid.cell_volume() / grid.spacing(axis);
        for (int d = 0; d < Dim; ++d) {
            const auto k = static_cast<std::size_t>(2 * d);
            r += system.a_nb[k][o] * u[o - grid.stride(d)] +
                 system.a_nb[k + 1][o] * u[o + grid.stride(d)];
        }
        return std::abs(r - system.a_p[o] * u[o]) / system.a_p[o];
    });
}

TYPED_TEST(MomentumSolve, SolvedToAToleranceItsResidualIsBelowIt)
{
    constexpr int Dim = TypeParam::value;
    auto bc = BoundaryConditions<Dim>::closed_box();
    bc.wall_velocity[1][1][0] = 1.0;
    bc.is_periodic[0] = true;
    Index<Dim> cells{};
    cells.fill(Dim == 2 ? 32 : 16);
    const MacGrid<Dim> grid(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), bc.is_periodic);
    const FluidProperties fluid{1.0, 0.01};
    const double dt = 0.5 * grid.spacing(0); // Courant number about 0.5: the cube's regime
    FluidState<Dim> start(grid);
    fill_state(grid, bc, start);
    for (const int cycles : {0, 1}) {
        for (int axis = 0; axis < Dim; ++axis) {
            SCOPED_TRACE(testing::Message() << "cycles " << cycles << ", axis " << axis);
            const MomentumSettings settings{ConvectionScheme::central, 1.0, 4, cycles};
            MomentumSystem<Dim> system(grid);
            static_cast<void>(
                assemble_momentum(grid, bc, fluid, settings, TimeLevels{dt}, start, axis, system));
            const double before = residual_over_a_p(grid, bc, axis, system, start);

            // No stop: one round, whose residual is still far above the tolerances below.
            FluidState<Dim> once = start;
            const MomentumSolveResult one =
                solve_momentum_to(grid, bc, settings, system, axis, once, MomentumStop{});
            EXPECT_EQ(one.rounds, 1);
            EXPECT_GT(residual_over_a_p(grid, bc, axis, system, once), 1e-5 * before);

            // A tolerance: as many rounds as it takes, and the residual it reports is the
            // system's, below the tolerance.
            for (const double tolerance : {1e-6 * before, 1e-10 * before}) {
                FluidState<Dim> solved = start;
                const MomentumSolveResult r = solve_momentum_to(
                    grid, bc, settings, system, axis, solved, MomentumStop{tolerance, 1000});
                const double actual = residual_over_a_p(grid, bc, axis, system, solved);
                EXPECT_GT(r.rounds, 1);
                EXPECT_LT(r.rounds, 1000);
                EXPECT_LE(r.residual, tolerance);
                EXPECT_NEAR(actual, r.residual, 1e-12 * before);
            }
            // The rounds run out first: it stops there, the residual still above.
            FluidState<Dim> short_of = start;
            const MomentumSolveResult cut = solve_momentum_to(
                grid, bc, settings, system, axis, short_of, MomentumStop{1e-14 * before, 2});
            EXPECT_EQ(cut.rounds, 2);
            EXPECT_GT(cut.residual, 1e-14 * before);
        }
    }
}

TEST(MomentumSolve, AutoChoosesTheMultigridWhereViscosityDominatesTheTimeTerm)
{
    // The paper's Fig. 5 case: h = 1/64, ρ = 1, μ = 0.1, Δt = 0.005: ρh²/Δt = 0.048828 against
    // 4μ = 0.4.
    const MacGrid<2> grid({128, 384}, Vec<2>::Zero(), Vec<2>(2.0, 6.0));
    const double share = time_term_share(grid, FluidProperties{1.0, 0.1}, 0.005);
    EXPECT_NEAR(share, 0.048828125 / (0.048828125 + 0.4), 1e-15);
    EXPECT_EQ(momentum_cycles_for(MomentumSolver::automatic, 1, share), 1);
    // The drafting–kissing–tumbling case: h = 1/96, μ = 0.01, Δt = 0.001: the time term
    // dominates and Gauss–Seidel converges quickly by itself.
    const MacGrid<2> dkt({192, 768}, Vec<2>::Zero(), Vec<2>(2.0, 8.0));
    const double dkt_share = time_term_share(dkt, FluidProperties{1.0, 0.01}, 0.001);
    EXPECT_GT(dkt_share, 0.7);
    EXPECT_EQ(momentum_cycles_for(MomentumSolver::automatic, 1, dkt_share), 0);
    EXPECT_EQ(momentum_cycles_for(MomentumSolver::multigrid, 2, dkt_share), 2);
    EXPECT_EQ(momentum_cycles_for(MomentumSolver::gauss_seidel, 1, share), 0);
}

} // namespace
} // namespace fddem
