// SPDX-License-Identifier: MIT
#pragma once
/// The direct FFT Poisson solver on a grid split across MPI ranks (issue 15; DESIGN.md §3 and
/// §6): FFTW-MPI's multi-dimensional r2r transforms on slabs, the same diagonalisation as the
/// one-process solver (linsolve/fft_poisson.hpp: DCT-II along walled axes, real Fourier along
/// periodic ones, a division by the eigenvalues of the 5/7-point Laplacian).
///
/// FFTW-MPI distributes its array in slabs along the slowest axis of its row-major order,
/// which is fddem's last axis (y in 2D, z in 3D). The grid's blocks are whatever the rank
/// layout made them (parallel.ranks, or choose_rank_layout), so one personalised all-to-all
/// moves the right-hand side from the blocks onto the slabs and one moves the solution back
/// (Communicator::all_to_all); where a block already is a slab these are local copies. The
/// forward transform leaves its output transposed (FFTW_MPI_TRANSPOSED_OUT: slabs along the
/// second-slowest axis) and the inverse reads it so (FFTW_MPI_TRANSPOSED_IN), which saves FFTW
/// one global transpose each way; the division by the eigenvalues is local either way.
///
/// The answer equals the one-process solver's to round-off: the same transforms, done in
/// another order.

#include "fddem/linsolve/poisson_solver.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace fddem {

template <int Dim>
class FftMpiPoissonSolver final : public PoissonSolver<Dim> {
public:
    /// Collective over the grid's communicator, which must use MPI.
    FftMpiPoissonSolver(const MacGrid<Dim>& grid, const std::array<bool, Dim>& is_periodic,
                        bool is_measured = false);
    ~FftMpiPoissonSolver() override;
    FftMpiPoissonSolver(const FftMpiPoissonSolver&) = delete;
    FftMpiPoissonSolver& operator=(const FftMpiPoissonSolver&) = delete;
    FftMpiPoissonSolver(FftMpiPoissonSolver&&) = delete;
    FftMpiPoissonSolver& operator=(FftMpiPoissonSolver&&) = delete;

    /// Collective.
    void solve(const CellField<Dim>& rhs, CellField<Dim>& phi) override;
    [[nodiscard]] std::string name() const override { return "FFTW-MPI direct (slabs)"; }
    [[nodiscard]] int last_iterations() const override { return 1; }
    // plan_record() stays empty: FFTW-MPI's measured plans are agreed between the ranks of one
    // run, but are not recorded for a restart (docs/parallel.md).

    /// The cells of this rank's slab along the last axis, [first, last) (for tests).
    [[nodiscard]] std::array<int, 2> slab() const noexcept { return slab_; }

private:
    struct Plans; // FFTW plan handles and their work array, kept out of the header

    /// Which part of a block goes to which slab: the boxes this rank sends to each rank (its
    /// block cut to their slab) and receives from each (their block cut to its slab).
    struct Routes {
        std::vector<Box<Dim>> send;
        std::vector<Box<Dim>> receive;
        std::vector<int> send_counts;
        std::vector<int> receive_counts;
    };

    /// Moves `from` (owned cells) onto the slabs, into the transform's work array.
    void blocks_to_slabs(const CellField<Dim>& from);
    /// Moves the work array back onto the blocks, into the owned cells of `to`.
    void slabs_to_blocks(CellField<Dim>& to);

    MacGrid<Dim> grid_;
    std::array<int, 2> slab_{};
    Routes routes_;
    std::vector<double> outgoing_;
    std::vector<double> incoming_;
    std::vector<double> inverse_eigen_; ///< 1/λ per local transposed mode × normalisation
    std::unique_ptr<Plans> plans_;
};

} // namespace fddem
