// SPDX-License-Identifier: MIT
// Micro-benchmarks of the hot kernels of one SIMPLE outer iteration, per grid size:
// momentum assembly (7)–(8), one red-black sweep, the pressure Poisson solve (9) by FFTW and
// by hypre. Counters report nanoseconds per cell. Also the broad phase of contact detection
// (cell list vs brute force) for N disks, per step.

#include "fddem/contact/cell_list.hpp"
#include "fddem/fluid/momentum.hpp"
#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

#include <benchmark/benchmark.h>
#include <mpi.h>

#include <cmath>
#include <random>
#include <vector>

namespace fddem {
namespace {

struct CavityFixture {
    explicit CavityFixture(int n)
        : grid({n, n}, Vec<2>::Zero(), Vec<2>::Ones()), bc(BoundaryConditions<2>::closed_box()),
          state(grid), system(grid)
    {
        bc.wall_velocity[1][1] = Vec<2>(1.0, 0.0);
        // A smooth divergence-free field as the iterate: ψ = sin²(πx) sin²(πy).
        for (int a = 0; a < 2; ++a) {
            for_each_index(grid.face_box(a), [&](const Index<2>& c) {
                const Vec<2> x = grid.face_centre(a, c);
                const double s = std::sin(M_PI * x[0]);
                const double t = std::sin(M_PI * x[1]);
                state.u[a](c) = a == 0 ? M_PI * s * s * std::sin(2 * M_PI * x[1])
                                       : -M_PI * std::sin(2 * M_PI * x[0]) * t * t;
            });
            state.u_n[a] = state.u[a];
        }
        fill_velocity_ghosts(grid, bc, state.u);
    }
    MacGrid<2> grid;
    BoundaryConditions<2> bc;
    FluidState<2> state;
    MomentumSystem<2> system;
    FluidProperties fluid{1.0, 0.01};
    MomentumSettings settings{ConvectionScheme::central, 1.0, 1, 0}; // one sweep
    double dt = 0.5 / 256;
};

void per_cell(benchmark::State& state, int n)
{
    state.counters["ns_per_cell"] = benchmark::Counter(
        static_cast<double>(n) * n * 1e-9,
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void momentum_assembly(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    CavityFixture f(n);
    for (auto _ : state) {
        for (int a = 0; a < 2; ++a) {
            benchmark::DoNotOptimize(assemble_momentum(f.grid, f.bc, f.fluid, f.settings,
                                                       TimeLevels{f.dt}, f.state, a, f.system));
        }
    }
    per_cell(state, n);
}

void momentum_sweep(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    CavityFixture f(n);
    (void)assemble_momentum(f.grid, f.bc, f.fluid, f.settings, TimeLevels{f.dt}, f.state, 0,
                            f.system);
    for (auto _ : state) {
        solve_momentum(f.grid, f.bc, f.settings, f.system, 0, f.state);
        solve_momentum(f.grid, f.bc, f.settings, f.system, 0, f.state);
    }
    per_cell(state, n);
}

/// One multigrid V-cycle (2 + 2 sweeps and the coarse levels, rebuilt as in every solve).
void momentum_vcycle(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    CavityFixture f(n);
    MomentumSettings cycle = f.settings;
    cycle.sweeps = 4;
    cycle.cycles = 1;
    (void)assemble_momentum(f.grid, f.bc, f.fluid, cycle, TimeLevels{f.dt}, f.state, 0, f.system);
    for (auto _ : state) {
        solve_momentum(f.grid, f.bc, cycle, f.system, 0, f.state);
    }
    per_cell(state, n);
}

void poisson(benchmark::State& state, PoissonSolverKind kind)
{
    const int n = static_cast<int>(state.range(0));
    const MacGrid<2> grid({n, n}, Vec<2>::Zero(), Vec<2>::Ones());
    PoissonSettings settings;
    settings.kind = kind;
    settings.tolerance = 1e-8;
    auto solver = make_poisson_solver<2>(grid, {false, false}, settings);
    CellField<2> rhs(grid);
    CellField<2> phi(grid);
    for_each_index(grid.cell_box(), [&](const Index<2>& c) {
        const Vec<2> x = grid.cell_centre(c);
        rhs(c) = std::cos(M_PI * x[0]) * std::cos(2 * M_PI * x[1]);
    });
    for (auto _ : state) {
        phi.fill(0.0); // cold start: the worst case for the iterative solver
        solver->solve(rhs, phi);
    }
    per_cell(state, n);
    state.counters["iterations"] = solver->last_iterations();
}

/// N disks of diameter d scattered without overlap at area fraction 0.3 in a square box:
/// pairs are searched within 1.5 d (contact at d, plus a margin as in a neighbour list).
std::vector<Vec<2>> scattered_disks(int n, double d, double& box)
{
    box = std::sqrt(n * M_PI * d * d / 4.0 / 0.3);
    std::mt19937 random(12345);
    std::vector<Vec<2>> centres;
    centres.reserve(static_cast<std::size_t>(n));
    // A jittered square lattice: random, and no overlaps at this area fraction.
    const int per_row = static_cast<int>(std::ceil(std::sqrt(n)));
    const double pitch = box / per_row;
    std::uniform_real_distribution<double> jitter(-0.5 * (pitch - d), 0.5 * (pitch - d));
    for (int k = 0; k < n; ++k) {
        const double x = (k % per_row + 0.5) * pitch + jitter(random);
        const double y = (k / per_row + 0.5) * pitch + jitter(random);
        centres.emplace_back(x, y);
    }
    return centres;
}

void contact_pairs(benchmark::State& state, bool is_brute_force)
{
    const int n = static_cast<int>(state.range(0));
    const double d = 0.01;
    double box = 0.0;
    const std::vector<Vec<2>> centres = scattered_disks(n, d, box);
    CellList<2> cells(Vec<2>::Zero(), Vec<2>(box, box), 1.5 * d);
    std::vector<std::pair<int, int>> pairs;
    for (auto _ : state) {
        if (is_brute_force) {
            pairs = brute_force_pairs<2>(centres, 1.5 * d);
        } else {
            cells.find_pairs(centres, pairs);
        }
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.counters["ns_per_disk"] = benchmark::Counter(
        static_cast<double>(n) * 1e-9,
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(contact_pairs, cell_list, false)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(contact_pairs, brute_force, true)
    ->RangeMultiplier(10)
    ->Range(1000, 10000)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(momentum_assembly)->RangeMultiplier(2)->Range(64, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(momentum_sweep)->RangeMultiplier(2)->Range(64, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(momentum_vcycle)->RangeMultiplier(2)->Range(64, 512)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(poisson, fft, PoissonSolverKind::fft)
    ->RangeMultiplier(2)
    ->Range(64, 512)
    ->Unit(benchmark::kMillisecond);

} // namespace
} // namespace fddem

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    MPI_Finalize();
    return 0;
}
