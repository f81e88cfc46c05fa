// SPDX-License-Identifier: MIT
#pragma once
/// One interface for the pressure-correction Poisson solvers (DESIGN.md §3): the direct FFTW
/// solver where the boundaries allow it, hypre structured multigrid otherwise.

#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <array>
#include <memory>
#include <string>

namespace fddem {

/// Solves the cell-centred 5-point (7-point in 3D) Poisson problem
///     Σ_d (φ_{i+e_d} − 2 φ_i + φ_{i−e_d}) / h_d² = rhs_i      on the owned cells,
/// with a zero normal gradient at walls and periodic images across periodic axes.
/// The operator is singular (constants); the solvers remove the mean of `rhs` and return the
/// zero-mean solution. Ghosts of `phi` are not filled.
template <int Dim>
class PoissonSolver {
public:
    PoissonSolver() = default;
    PoissonSolver(const PoissonSolver&) = delete;
    PoissonSolver& operator=(const PoissonSolver&) = delete;
    PoissonSolver(PoissonSolver&&) = delete;
    PoissonSolver& operator=(PoissonSolver&&) = delete;
    virtual ~PoissonSolver() = default;

    virtual void solve(const CellField<Dim>& rhs, CellField<Dim>& phi) = 0;
    [[nodiscard]] virtual std::string name() const = 0;
    /// Iterations of the last solve (1 for a direct solver).
    [[nodiscard]] virtual int last_iterations() const = 0;

    /// What another process needs to make the same plans, so that a run continued from a
    /// checkpoint gives the same bits (measured FFT plans differ between processes); empty
    /// when the solver has nothing of the kind.
    [[nodiscard]] virtual std::string plan_record() const { return {}; }
    /// Replans from another process's plan_record(); an empty record changes nothing.
    virtual void restore_plans(const std::string& record) { static_cast<void>(record); }
};

/// The pressure-correction solver: the direct FFT solver (FFTW-MPI's slabs on a grid split
/// across ranks), hypre's PFMG-preconditioned CG, or automatic (the FFT solver wherever the
/// boundaries allow it, which every boundary here does, unless a split grid has more ranks
/// than FFTW-MPI has planes to give them: then hypre).
enum class PoissonSolverKind { automatic, fft, hypre };

/// FFT plans by measurement (FFTW_MEASURE: ≈ 1.7× faster transforms at 256², but the plan
/// FFTW picks may differ between processes, and with it the last bits of the answer) or by
/// estimate (FFTW_ESTIMATE: the same plan, so bit-identical reruns).
enum class FftPlanning { estimate, measure };

struct PoissonSettings {
    PoissonSolverKind kind = PoissonSolverKind::automatic;
    double tolerance = 1e-10; ///< relative residual, iterative solvers
    int max_iterations = 200;
    FftPlanning fft_planning = FftPlanning::estimate;
};

/// Builds the solver chosen in `settings` for a grid whose axes are periodic where
/// `is_periodic` says and walled elsewhere.
template <int Dim>
[[nodiscard]] std::unique_ptr<PoissonSolver<Dim>>
make_poisson_solver(const MacGrid<Dim>& grid, const std::array<bool, Dim>& is_periodic,
                    const PoissonSettings& settings);

} // namespace fddem
