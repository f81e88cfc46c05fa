// SPDX-License-Identifier: MIT
#include "fddem/core/errors.hpp"
#include "fddem/linsolve/fft_poisson.hpp"
#include "fddem/linsolve/hypre_poisson.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

namespace fddem {

template <int Dim>
std::unique_ptr<PoissonSolver<Dim>> make_poisson_solver(const MacGrid<Dim>& grid,
                                                        const std::array<bool, Dim>& is_periodic,
                                                        const PoissonSettings& settings)
{
    // Every boundary fddem has today (walls, periodic pairs) keeps the pressure-correction
    // operator constant-coefficient on a uniform box, so "auto" is the direct solver on one
    // process. On a grid split across ranks it is hypre, on the same blocks: the FFT solver
    // transforms whole lines and has no FFTW-MPI slab version yet (issue 15).
    bool is_split = false;
    for (int d = 0; d < Dim; ++d) {
        is_split = is_split || grid.is_split(d);
    }
    if (is_split && settings.kind == PoissonSolverKind::fft) {
        throw InputError("", 0, "simple.pressure_solver",
                         "\"fft\" runs on one process only (no FFTW-MPI transforms yet); use "
                         "\"hypre\" or \"auto\" on several ranks");
    }
    if (settings.kind == PoissonSolverKind::hypre || is_split) {
        return make_hypre_poisson_solver<Dim>(grid, is_periodic, settings.tolerance,
                                              settings.max_iterations);
    }
    return std::make_unique<FftPoissonSolver<Dim>>(grid, is_periodic,
                                                   settings.fft_planning == FftPlanning::measure);
}

template std::unique_ptr<PoissonSolver<2>>
make_poisson_solver<2>(const MacGrid<2>&, const std::array<bool, 2>&, const PoissonSettings&);
template std::unique_ptr<PoissonSolver<3>>
make_poisson_solver<3>(const MacGrid<3>&, const std::array<bool, 3>&, const PoissonSettings&);

} // namespace fddem
