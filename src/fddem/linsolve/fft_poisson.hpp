// SPDX-License-Identifier: MIT
#pragma once
/// Direct Poisson solver by FFTW real transforms (DESIGN.md §3, the CaNS approach): on a
/// uniform box the cell-centred Laplacian is diagonalised by a cosine transform (DCT-II) along
/// walled axes (zero normal gradient at the faces) and by a real Fourier transform along
/// periodic axes, so one forward transform, a division by the eigenvalues and one inverse
/// transform solve it exactly, at O(N log N).

#include "fddem/linsolve/poisson_solver.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace fddem {

template <int Dim>
class FftPoissonSolver final : public PoissonSolver<Dim> {
public:
    FftPoissonSolver(const MacGrid<Dim>& grid, const std::array<bool, Dim>& is_periodic,
                     bool is_measured = false);
    ~FftPoissonSolver() override;
    FftPoissonSolver(const FftPoissonSolver&) = delete;
    FftPoissonSolver& operator=(const FftPoissonSolver&) = delete;
    FftPoissonSolver(FftPoissonSolver&&) = delete;
    FftPoissonSolver& operator=(FftPoissonSolver&&) = delete;

    void solve(const CellField<Dim>& rhs, CellField<Dim>& phi) override;
    [[nodiscard]] std::string name() const override { return "FFTW direct"; }
    [[nodiscard]] int last_iterations() const override { return 1; }
    /// FFTW's wisdom: the plans this process measured (empty for estimated plans, which are the
    /// same in every process).
    [[nodiscard]] std::string plan_record() const override;
    /// Imports the wisdom and replans: the measured plans of the recording process come back.
    void restore_plans(const std::string& record) override;

private:
    struct Plans; // FFTW plan handles and their SIMD-aligned work array, kept out of the header

    MacGrid<Dim> grid_;
    std::vector<double> inverse_eigen_; ///< 1/λ per mode (0 for the constant mode) × normalisation
    std::unique_ptr<Plans> plans_;
};

} // namespace fddem
