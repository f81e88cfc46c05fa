// SPDX-License-Identifier: MIT
#pragma once
/// The processes that share one grid, and the one place where values owned by each are
/// combined or exchanged (STYLE.md §13, DESIGN.md §6). Every reduction over the grid (max_over,
/// sum_over in loops.hpp: residuals, norms, Courant numbers, fluxes) ends here, and so does the
/// halo exchange's point-to-point traffic (grid/halo_exchange.hpp). MPI appears nowhere else
/// in the grid and the solvers.
///
/// Communicator::self() is this process alone, without MPI: every reduction is the identity on
/// the local value, so a one-process run computes bit for bit what it computed before
/// reductions went through here, and does not start MPI. A communicator over several processes
/// wraps an MPI communicator (MPI must be running). Its sums are taken in rank order from the
/// gathered partial values, not by MPI_Allreduce, whose order of additions the MPI standard
/// leaves open: the same ranks then give bit-identical reruns.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

namespace detail {
struct MpiCommunicator; // communicator.cpp: holds the MPI_Comm, so mpi.h stays out of headers
}

/// What this rank has sent through one communicator since it was made (issue 15's message
/// counts): the halo exchange's point-to-point messages, the collectives (sums, maxima,
/// broadcasts, gathers) it took part in, and the all-to-alls that move a field between the
/// grid's blocks and FFTW-MPI's slabs. hypre's and FFTW-MPI's own messages, on their own
/// handles, are not here.
struct Traffic {
    long messages = 0;         ///< point-to-point sends to another rank
    long bytes = 0;            ///< their payload [B]
    long collectives = 0;      ///< reductions, broadcasts and gathers
    long collective_bytes = 0; ///< this rank's contribution to them [B]
    /// What they brought this rank [B]: a sum or a gather of n values from every rank brings
    /// it n times the number of ranks, a gather of parts the parts' total.
    long collective_received_bytes = 0;
    long all_to_alls = 0;      ///< personalised all-to-alls (all_to_all)
    long all_to_all_bytes = 0; ///< what left this rank in them [B]
    double seconds = 0.0;      ///< wall time inside all of these calls, waiting included [s]
};

class Communicator {
public:
    /// The rank of a side with no neighbour (MPI_PROC_NULL's role): exchanges with it are
    /// skipped.
    static constexpr int no_rank = -1;

    /// This process alone: the same as self().
    Communicator() noexcept = default;
    /// This process alone (MPI_COMM_SELF's role, without starting MPI): also what rank-local
    /// work, such as the coarse levels of the momentum multigrid, reduces over.
    [[nodiscard]] static Communicator self() noexcept { return {}; }
    /// Every process mpirun started (MPI_COMM_WORLD). MPI must be running.
    [[nodiscard]] static Communicator world();

    [[nodiscard]] int rank() const noexcept;
    [[nodiscard]] int size() const noexcept;
    /// How many of the ranks run on this machine (share its memory), this one included; 1 on
    /// this process alone. Collective.
    [[nodiscard]] int ranks_on_this_node() const;
    /// True if this is more than one process (or one process through MPI).
    [[nodiscard]] bool uses_mpi() const noexcept { return mpi_ != nullptr; }

    /// The largest of the ranks' `local` values. A NaN anywhere must come out as NaN or +∞
    /// (loops.hpp's max_keeping_nan), so that a blown-up residual never looks converged.
    [[nodiscard]] double max(double local) const;
    /// The sum of the ranks' `local` values, added in rank order.
    [[nodiscard]] double sum(double local) const;
    /// Element-wise sums over the ranks, in place (one message for several totals).
    void sum(std::span<double> values) const;

    /// Rank 0's `bytes` on every rank (MPI_Bcast): a restarted run's state, read by rank 0.
    void broadcast(std::string& bytes) const;

    /// Sends `send` to rank `destination` and receives `receive` from rank `source` in one
    /// step (MPI_Sendrecv), so that a ring of such calls cannot deadlock. Either rank may be
    /// no_rank: that half is skipped. On this process alone both must be 0 or no_rank, and the
    /// values are copied. `tag` tells apart several exchanges between the same two ranks.
    void exchange(std::span<const double> send, int destination, std::span<double> receive,
                  int source, int tag) const;

    /// One message to each rank of `sends` and one from each rank of `receives`, all at once
    /// (MPI_Irecv, MPI_Isend, MPI_Waitall): the few ranks that share a body's markers (issue
    /// 15, coupling/marker_routes.hpp). Both sides know the sizes; no rank may be this one. On
    /// this process alone both lists must be empty.
    struct Outgoing {
        int rank;
        std::span<const double> values;
    };
    struct Incoming {
        int rank;
        std::span<double> values;
    };
    void send_and_receive(std::span<const Outgoing> sends, std::span<const Incoming> receives,
                          int tag) const;

    /// Every rank's `local` values, rank after rank (MPI_Allgather; each rank gives as many).
    /// On this process alone, `local` itself.
    [[nodiscard]] std::vector<int> all_gather(std::span<const int> local) const;

    /// Every rank's `local` values, rank after rank, into `all` (MPI_Allgatherv): rank q gives
    /// counts[q] values, the same counts on every rank, and `all` holds their sum. Nothing is
    /// added, so each value arrives bit for bit (a sum with zeros from the other ranks, as
    /// sum() would do for values only one rank holds, costs every rank size() times the
    /// values and turns −0 into +0). On this process alone, `local` is copied.
    void all_gather(std::span<const double> local, std::span<const int> counts,
                    std::span<double> all) const;

    /// Personalised all-to-all (MPI_Alltoallv): `send` holds, one after the other in rank
    /// order, send_counts[q] values for each rank q; `receive` gets receive_counts[q] values from
    /// each rank q, in rank order. The counts must agree pairwise across the ranks (what q sends
    /// to r is what r expects from q). On this process alone, `send` is copied to `receive`.
    /// Used to move a field between the grid's blocks and FFTW-MPI's slabs.
    void all_to_all(std::span<const double> send, std::span<const int> send_counts,
                    std::span<double> receive, std::span<const int> receive_counts) const;

    /// This rank's traffic through this communicator so far (zero on self()).
    [[nodiscard]] Traffic traffic() const noexcept;
    /// Traffic::seconds as it grows, for PhaseTimes::communication_clock; nullptr on self().
    [[nodiscard]] const double* seconds_counter() const noexcept;

    /// The ranks laid out as a Cartesian grid of dims[0] × … processes (MPI_Cart_create, ranks
    /// in the same order), periodic where `is_periodic` says. The product of `dims` must be
    /// size(). On this process alone (all dims 1) the result is self().
    [[nodiscard]] Communicator cartesian(std::span<const int> dims,
                                         std::span<const bool> is_periodic) const;
    /// This rank's coordinates in the Cartesian layout (all 0 on self()).
    void cartesian_coords(std::span<int> coords) const;
    /// The rank at `coords` of the Cartesian layout (MPI_Cart_rank); 0 on self().
    [[nodiscard]] int cartesian_rank(std::span<const int> coords) const;
    /// The ranks one step below and above this one along `axis` (MPI_Cart_shift): no_rank
    /// beyond a side that is not periodic. This process alone: itself if `axis_is_periodic`.
    [[nodiscard]] std::pair<int, int> cartesian_neighbours(int axis, bool axis_is_periodic) const;

private:
    /// Adds one collective of `bytes` from this rank, bringing it `received`, to traffic();
    /// needs MPI.
    void count_collective(std::size_t bytes, std::size_t received) const noexcept;

    friend struct CommunicatorAccess; // communicator.cpp: the MPI_Comm for hypre and FFTW-MPI

    explicit Communicator(std::shared_ptr<const detail::MpiCommunicator> mpi) noexcept
        : mpi_(std::move(mpi))
    {
    }

    std::shared_ptr<const detail::MpiCommunicator> mpi_;
};

} // namespace fddem
