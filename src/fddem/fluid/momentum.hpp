// SPDX-License-Identifier: MIT
#pragma once
/// The discrete momentum equations (7)–(8) on the staggered grid, one system per velocity
/// component: a_P u_P = Σ a_nb u_nb − (p_P − p_W) ΔV/h + b, and their approximate solution.

#include "fddem/core/time_scheme.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/linsolve/aggregation_multigrid.hpp"
#include "fddem/linsolve/split_multigrid.hpp"

#include <array>

namespace fddem {

/// Coefficients of one component's system. a_nb[2d] is the low neighbour along d, a_nb[2d+1]
/// the high one. b holds everything but the pressure gradient (time level n, body force,
/// deferred convection correction, wall terms).
template <int Dim>
struct MomentumSystem {
    explicit MomentumSystem(const MacGrid<Dim>& grid)
        : a_p(grid), b(grid), u_old(grid), scaled_source(grid)
    {
        for (auto& a : a_nb) {
            a = GridArray<Dim>(grid);
        }
        for (auto& c : scaled_nb) {
            c = GridArray<Dim>(grid);
        }
    }
    GridArray<Dim> a_p;
    std::array<GridArray<Dim>, 2 * Dim> a_nb;
    GridArray<Dim> b;
    GridArray<Dim> u_old; ///< the iterate at assembly, for under-relaxation

    // Scratch of solve_momentum (not state): the system divided by a_P/α, u_P = s + Σ c_nb u_nb,
    // so that a sweep reads 2·Dim + 1 arrays besides u instead of 2·Dim + 5.
    GridArray<Dim> scaled_source;
    std::array<GridArray<Dim>, 2 * Dim> scaled_nb;
    std::vector<CoarseLevel<Dim>> coarse_levels; ///< the multigrid's, rebuilt every solve
    /// The same on a grid split over ranks: the operator rebuilt every solve, the levels'
    /// boxes and routes kept from the first (one system per velocity component, one split).
    SplitHierarchy<Dim> split_levels;
};

struct MomentumSettings {
    ConvectionScheme convection; ///< see ConvectionScheme
    double relaxation;           ///< α_u in (0, 1]
    int sweeps;                  ///< red-black Gauss–Seidel sweeps per outer iteration, at most
    /// Multigrid V-cycles per outer iteration (fddem/linsolve/aggregation_multigrid.hpp), each
    /// with sweeps/2 sweeps before the coarse correction and the rest after; 0: Gauss–Seidel
    /// sweeps alone.
    int cycles = 1;
};

/// The share of the time term in a_P for a fluid at rest: ρΔV/Δt over ρΔV/Δt + Σ_d 2μA_d/h_d.
/// Gauss–Seidel reduces a smooth error by about 1 minus this per sweep.
template <int Dim>
[[nodiscard]] double time_term_share(const MacGrid<Dim>& grid, const FluidProperties& fluid,
                                     double dt);

/// Below this share of the time term the multigrid pays for its coarse levels (measured:
/// Fig. 5 case, share 0.11, 1.7× fewer outer iterations and 1.2× faster; the cavity at
/// Δt = h, 0.16, 2× faster; the cavity at Δt = h/2, 0.28, and the DKT case, 0.73, slower).
inline constexpr double multigrid_time_share = 0.2;

/// How the momentum equations are solved: V-cycles smoothed by Gauss–Seidel (multigrid),
/// sweeps alone (gauss_seidel), or the multigrid below multigrid_time_share (automatic).
enum class MomentumSolver { automatic, multigrid, gauss_seidel };

/// The V-cycles per outer iteration for `solver`: `cycles`, or 0 (sweeps alone).
[[nodiscard]] int momentum_cycles_for(MomentumSolver solver, int cycles, double time_share);

/// Assembles eqs. (7)–(8) for component `axis` about the current iterate `state.u` (Picard:
/// fluxes from the latest iterate). The time term is ρf ΔV (u − ũ^n)/Δt_e of `time`
/// (core/time_scheme.hpp): implicit Euler, or BDF2 from state.u_n and state.u_nm1. Requires
/// the ghosts of state.u filled. Returns the normalised residual of the current iterate,
/// max |r / a_P| [m/s].
template <int Dim>
[[nodiscard]] double assemble_momentum(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                       const FluidProperties& fluid,
                                       const MomentumSettings& settings, const TimeLevels& time,
                                       const FluidState<Dim>& state, int axis,
                                       MomentumSystem<Dim>& system);

/// Relaxes component `axis` of state.u towards the solution of its system, with velocity
/// under-relaxation (Patankar's a_P/α form): settings.cycles multigrid V-cycles smoothed by
/// red-black Gauss–Seidel, or settings.sweeps sweeps alone if cycles is 0. Ghosts are
/// refilled between sweeps (periodic images lag by one colour).
template <int Dim>
void solve_momentum(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                    const MomentumSettings& settings, MomentumSystem<Dim>& system, int axis,
                    FluidState<Dim>& state);

/// When solve_momentum_to stops repeating its round (the settings' sweeps, or V-cycles).
struct MomentumStop {
    /// Stop once max |r/a_P| over the faces is at most this [m/s] (r the residual of the system
    /// as relaxed; with α = 1 assemble_momentum's); 0: after one round, as solve_momentum.
    double residual = 0.0;
    int max_rounds = 1; ///< and after this many rounds in any case
};
struct MomentumSolveResult {
    double residual = 0.0; ///< max |r/a_P| after the last round [m/s] (0 if not asked for)
    int rounds = 0;        ///< rounds taken
};

/// solve_momentum, its round repeated until `stop` (simple.algorithm = "projection": the
/// predictor of a step solved to the step's tolerance). The residual is checked after each
/// round, one pass over the system, and its max is taken over all ranks.
template <int Dim>
MomentumSolveResult solve_momentum_to(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                      const MomentumSettings& settings, MomentumSystem<Dim>& system,
                                      int axis, FluidState<Dim>& state, const MomentumStop& stop);

} // namespace fddem
