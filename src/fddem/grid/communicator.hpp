// SPDX-License-Identifier: MIT
#pragma once
/// The processes that share one grid, and the one place where values owned by each are
/// combined (STYLE.md §13, DESIGN.md §6). Every reduction over the grid (max_over, sum_over in
/// loops.hpp: residuals, norms, Courant numbers, fluxes) ends here.
///
/// This is the single-process communicator: one rank, and every reduction is the identity on
/// the local value, so a run computes bit for bit what it computed before reductions went
/// through it. When the grid is split across MPI ranks this class holds the Cartesian
/// communicator, and max() and sum() become MPI_Allreduce with MPI_MAX and MPI_SUM (the sum of
/// the ranks' partial sums, taken in rank order so that reruns are bit-identical); nothing that
/// calls them changes.

#include <span>

namespace fddem {

class Communicator {
public:
    /// This process alone (MPI_COMM_SELF's role): also what rank-local work, such as the
    /// coarse levels of the momentum multigrid, reduces over.
    [[nodiscard]] static Communicator self() noexcept { return {}; }

    [[nodiscard]] int rank() const noexcept { return 0; }
    [[nodiscard]] int size() const noexcept { return 1; }

    /// The largest of the ranks' `local` values. A NaN anywhere must come out as NaN or +∞
    /// (loops.hpp's max_keeping_nan), so that a blown-up residual never looks converged.
    [[nodiscard]] double max(double local) const noexcept { return local; }
    /// The sum of the ranks' `local` values.
    [[nodiscard]] double sum(double local) const noexcept { return local; }
    /// Element-wise sums over the ranks, in place (one message for several totals).
    void sum(std::span<double> values) const noexcept { static_cast<void>(values); }
};

} // namespace fddem
