// SPDX-License-Identifier: MIT
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
    // operator constant-coefficient on a uniform box, so "auto" is always the direct solver.
    if (settings.kind == PoissonSolverKind::hypre) {
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
