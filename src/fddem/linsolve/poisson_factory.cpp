// SPDX-License-Identifier: MIT
#include "fddem/linsolve/fft_mpi_poisson.hpp"
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
    // operator constant-coefficient on a uniform box, so "auto" is the direct solver: on one
    // process the serial FFTW transforms, on a grid split across ranks FFTW-MPI's slabs
    // (linsolve/fft_mpi_poisson.hpp). FFTW-MPI gives each rank planes along the last axis
    // and, after its transposed output, along the one before; "auto" hands the solve to hypre,
    // on the grid's own blocks, when there are more ranks than either has planes (some ranks
    // would idle through the transforms). "fft" asked for runs FFTW-MPI anyway.
    bool is_split = false;
    for (int d = 0; d < Dim; ++d) {
        is_split = is_split || grid.is_split(d);
    }
    const int n_ranks = grid.communicator().size();
    const bool has_planes_for_all =
        grid.cells(Dim - 1) >= n_ranks && grid.cells(Dim - 2) >= n_ranks;
    const bool is_hypre =
        settings.kind == PoissonSolverKind::hypre ||
        (is_split && settings.kind == PoissonSolverKind::automatic && !has_planes_for_all);
    if (is_hypre) {
        return make_hypre_poisson_solver<Dim>(grid, is_periodic, settings.tolerance,
                                              settings.max_iterations);
    }
    const bool is_measured = settings.fft_planning == FftPlanning::measure;
    if (is_split) {
        return std::make_unique<FftMpiPoissonSolver<Dim>>(grid, is_periodic, is_measured);
    }
    return std::make_unique<FftPoissonSolver<Dim>>(grid, is_periodic, is_measured);
}

template std::unique_ptr<PoissonSolver<2>>
make_poisson_solver<2>(const MacGrid<2>&, const std::array<bool, 2>&, const PoissonSettings&);
template std::unique_ptr<PoissonSolver<3>>
make_poisson_solver<3>(const MacGrid<3>&, const std::array<bool, 3>&, const PoissonSettings&);

} // namespace fddem
