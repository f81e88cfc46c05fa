// SPDX-License-Identifier: MIT
// The fluid's SIMPLE iterations (eqs. (7)–(12)) on a grid split across MPI ranks (issue 15):
// the momentum assembly (a first Euler step, then BDF2) and red–black Gauss–Seidel sweeps with
// a halo fill between colours, the boundary conditions applied by the blocks that reach each
// side, hypre's pressure correction on the blocks. A lid-driven cavity (2D) and a channel with
// an inflow and an outflow, a wall sliding across the flow and periodic sides across it (3D),
// each for a few time steps, must give the one-process velocity and pressure on every owned
// entry to round-off of the pressure solve. Run under mpirun -n 1, 2, 4.

#include "fddem/core/time_scheme.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/momentum.hpp"
#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/split_compare.hpp"

namespace fddem {
namespace {

/// Runs `steps` time steps of `outer` SIMPLE iterations each from the fluid at rest, the
/// momentum solved by `cycles` multigrid V-cycles (0: by sweeps alone).
template <int Dim>
FluidState<Dim> run_fluid(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int steps,
                          int outer, int cycles)
{
    const FluidProperties fluid{1.0, 0.01};
    const MomentumSettings momentum{ConvectionScheme::upwind, 0.7, 4, cycles};
    PoissonSettings pressure;
    pressure.kind = PoissonSolverKind::hypre;
    pressure.tolerance = 1e-13;
    pressure.max_iterations = 500;
    const double dt = 0.5 * grid.spacing(0);
    auto poisson = make_poisson_solver<Dim>(grid, bc.is_periodic, pressure);
    std::vector<MomentumSystem<Dim>> systems;
    for (int a = 0; a < Dim; ++a) {
        systems.emplace_back(grid);
    }
    FluidState<Dim> state(grid);
    fill_velocity_ghosts(grid, bc, state.u);
    fill_cell_ghosts(grid, bc, state.p);
    for (int step = 0; step < steps; ++step) {
        for (int a = 0; a < Dim; ++a) {
            state.u_nm1[a] = state.u_n[a];
            state.u_n[a] = state.u[a];
        }
        // BDF2 after a first Euler step: both time schemes' assemblies run on the blocks.
        const TimeLevels time = time_levels(TimeScheme::bdf2, dt, step == 0 ? 0.0 : dt);
        for (int k = 0; k < outer; ++k) {
            for (int a = 0; a < Dim; ++a) {
                static_cast<void>(assemble_momentum(grid, bc, fluid, momentum, time, state, a,
                                                    systems[static_cast<std::size_t>(a)]));
            }
            for (int a = 0; a < Dim; ++a) {
                solve_momentum(grid, bc, momentum, systems[static_cast<std::size_t>(a)], a, state);
            }
            static_cast<void>(correct_pressure_and_velocity(grid, bc, fluid, time.dt_effective, 1.0,
                                                            PressureUpdate::standard, *poisson,
                                                            state));
        }
    }
    return state;
}

template <int Dim>
void expect_split_run_matches(const Index<Dim>& cells, const BoundaryConditions<Dim>& bc,
                              int cycles, const char* name)
{
    const Communicator world = Communicator::world();
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        length[d] = static_cast<double>(cells[static_cast<std::size_t>(d)]) / cells[0];
    }
    const MacGrid<Dim> whole(cells, Vec<Dim>::Zero(), length, bc.is_periodic);
    const MacGrid<Dim> split(cells, Vec<Dim>::Zero(), length, bc.is_periodic,
                             partition_grid<Dim>(world, cells, bc.is_periodic,
                                                 choose_rank_layout<Dim>(cells, world.size())));
    const int steps = 3;
    const int outer = 3;
    const FluidState<Dim> reference = run_fluid<Dim>(whole, bc, steps, outer, cycles);
    const FluidState<Dim> state = run_fluid<Dim>(split, bc, steps, outer, cycles);
    double worst_u = 0.0;
    double largest_u = 0.0;
    for (int a = 0; a < Dim; ++a) {
        const auto [worst, largest] =
            test::compare_owned<Dim>(world, split.owned_faces(a), state.u[a], reference.u[a]);
        worst_u = std::max(worst_u, worst);
        largest_u = std::max(largest_u, largest);
    }
    const auto [worst_p, largest_p] =
        test::compare_owned<Dim>(world, split.owned_cells(), state.p, reference.p);
    EXPECT_GT(largest_u, 0.1); // the flow has started
    EXPECT_GT(largest_p, 1e-3);
    EXPECT_LE(worst_u, 1e-10 * largest_u);
    EXPECT_LE(worst_p, 1e-10 * largest_p);
    if (world.rank() == 0) {
        std::printf("[ info ] %s on %d ranks: max |Δu|/max|u| = %.2e, max |Δp|/max|p| = %.2e\n",
                    name, world.size(), worst_u / largest_u, worst_p / largest_p);
    }
}

TEST(SplitFluid, CavityMatchesOneProcess)
{
    auto bc = BoundaryConditions<2>::closed_box();
    bc.wall_velocity[1][1] = Vec<2>(1.0, 0.0); // the lid
    expect_split_run_matches<2>({26, 24}, bc, 0, "2D cavity, sweeps");
}

// The multigrid's first coarse level merges blocks of the whole grid, some of which straddle
// two ranks (odd block starts: 26 cells over 2 or 4 ranks along x start a block at 13); the
// coarse levels are split over the ranks (linsolve/split_multigrid.hpp).
TEST(SplitFluid, CavityWithMultigridMatchesOneProcess)
{
    auto bc = BoundaryConditions<2>::closed_box();
    bc.wall_velocity[1][1] = Vec<2>(1.0, 0.0);
    expect_split_run_matches<2>({26, 24}, bc, 2, "2D cavity, multigrid");
}

TEST(SplitFluid, ChannelWithInflowOutflowAndSlidingWallMatchesOneProcess)
{
    auto bc = BoundaryConditions<3>::closed_box();
    bc.kind[0] = {BoundaryKind::inflow, BoundaryKind::outflow};
    bc.inflow = {InflowShape::parabolic, 1.0};
    bc.is_periodic[2] = true;
    bc.wall_velocity[1][1] = Vec<3>(0.0, 0.0, 0.5); // the top wall slides across the flow
    expect_split_run_matches<3>({16, 12, 12}, bc, 0, "3D channel, sweeps");
    expect_split_run_matches<3>({17, 12, 12}, bc, 1, "3D channel, multigrid");
}

} // namespace
} // namespace fddem
