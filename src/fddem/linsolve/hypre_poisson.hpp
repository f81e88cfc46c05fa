// SPDX-License-Identifier: MIT
#pragma once
/// The pressure-correction Poisson problem by hypre's structured interface: conjugate
/// gradients preconditioned by one PFMG multigrid V-cycle, warm-started from the previous
/// solution (DESIGN.md §3). For boundaries the FFT solver cannot take, and as its check.

#include "fddem/linsolve/poisson_solver.hpp"

#include <array>
#include <memory>
#include <vector>

namespace fddem {

template <int Dim>
class HyprePoissonSolver final : public PoissonSolver<Dim> {
public:
    /// `tolerance`: relative residual ‖b − Ax‖/‖b‖ to stop at; `max_iterations`: CG limit.
    HyprePoissonSolver(const MacGrid<Dim>& grid, const std::array<bool, Dim>& is_periodic,
                       double tolerance, int max_iterations);
    ~HyprePoissonSolver() override;
    HyprePoissonSolver(const HyprePoissonSolver&) = delete;
    HyprePoissonSolver& operator=(const HyprePoissonSolver&) = delete;
    HyprePoissonSolver(HyprePoissonSolver&&) = delete;
    HyprePoissonSolver& operator=(HyprePoissonSolver&&) = delete;

    /// Uses phi's current values as the initial guess.
    void solve(const CellField<Dim>& rhs, CellField<Dim>& phi) override;
    [[nodiscard]] std::string name() const override { return "hypre PFMG-PCG"; }
    [[nodiscard]] int last_iterations() const override { return last_iterations_; }
    [[nodiscard]] double last_relative_residual() const noexcept { return last_residual_; }

private:
    struct Handles; // hypre objects, kept out of the header

    MacGrid<Dim> grid_;
    std::unique_ptr<Handles> handles_;
    std::vector<double> values_; ///< owned cells, x fastest
    int last_iterations_ = 0;
    double last_residual_ = 0.0;
};

template <int Dim>
[[nodiscard]] std::unique_ptr<PoissonSolver<Dim>>
make_hypre_poisson_solver(const MacGrid<Dim>& grid, const std::array<bool, Dim>& is_periodic,
                          double tolerance, int max_iterations);

} // namespace fddem
