// SPDX-License-Identifier: MIT
#include "fddem/grid/communicator.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/core/phase_timer.hpp"
#include "fddem/grid/communicator_mpi.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace fddem {

namespace detail {

/// An MPI communicator; one this code created is freed with it (while MPI still runs).
struct MpiCommunicator {
    MPI_Comm comm = MPI_COMM_NULL;
    bool is_owned = false;
    int rank = 0;
    int size = 1;
    bool is_cartesian = false;
    /// Counted as the calls go (MPI is called from the main thread only).
    mutable Traffic sent;

    MpiCommunicator(MPI_Comm c, bool owned) : comm(c), is_owned(owned)
    {
        MPI_Comm_rank(comm, &rank);
        MPI_Comm_size(comm, &size);
        int topology = MPI_UNDEFINED;
        MPI_Topo_test(comm, &topology);
        is_cartesian = topology == MPI_CART;
    }
    MpiCommunicator(const MpiCommunicator&) = delete;
    MpiCommunicator& operator=(const MpiCommunicator&) = delete;
    ~MpiCommunicator()
    {
        int is_finished = 0;
        MPI_Finalized(&is_finished);
        if (is_owned && is_finished == 0) {
            MPI_Comm_free(&comm);
        }
    }
};

} // namespace detail

struct CommunicatorAccess {
    static const detail::MpiCommunicator* of(const Communicator& comm) noexcept
    {
        return comm.mpi_.get();
    }
};

MPI_Comm mpi_handle(const Communicator& comm) noexcept
{
    const detail::MpiCommunicator* mpi = CommunicatorAccess::of(comm);
    return mpi != nullptr ? mpi->comm : MPI_COMM_SELF;
}

namespace {

void check(int status, const char* what)
{
    if (status != MPI_SUCCESS) {
        throw InternalError(std::string(what) + " failed");
    }
}

} // namespace

Communicator Communicator::world()
{
    int is_started = 0;
    MPI_Initialized(&is_started);
    if (is_started == 0) {
        throw InternalError("Communicator::world() needs MPI to be running");
    }
    return Communicator(std::make_shared<const detail::MpiCommunicator>(MPI_COMM_WORLD, false));
}

int Communicator::rank() const noexcept
{
    return mpi_ ? mpi_->rank : 0;
}

int Communicator::size() const noexcept
{
    return mpi_ ? mpi_->size : 1;
}

int Communicator::ranks_on_this_node() const
{
    if (!mpi_) {
        return 1;
    }
    // The ranks that can share memory with this one: those of this machine (MPI-3).
    MPI_Comm node = MPI_COMM_NULL;
    check(MPI_Comm_split_type(mpi_->comm, MPI_COMM_TYPE_SHARED, mpi_->rank, MPI_INFO_NULL, &node),
          "MPI_Comm_split_type");
    int size = 1;
    check(MPI_Comm_size(node, &size), "MPI_Comm_size");
    MPI_Comm_free(&node);
    return size;
}

Traffic Communicator::traffic() const noexcept
{
    return mpi_ ? mpi_->sent : Traffic{};
}

const double* Communicator::seconds_counter() const noexcept
{
    return mpi_ ? &mpi_->sent.seconds : nullptr;
}

void Communicator::count_collective(std::size_t bytes, std::size_t received) const noexcept
{
    ++mpi_->sent.collectives;
    mpi_->sent.collective_bytes += static_cast<long>(bytes);
    mpi_->sent.collective_received_bytes += static_cast<long>(received);
}

double Communicator::max(double local) const
{
    if (!mpi_) {
        return local;
    }
    // Gathered rather than MPI_MAX: a NaN must win (MPI_MAX's comparison would drop it).
    const ScopedSeconds timer(mpi_->sent.seconds);
    count_collective(sizeof(double), sizeof(double) * static_cast<std::size_t>(mpi_->size));
    std::vector<double> all(static_cast<std::size_t>(mpi_->size));
    check(MPI_Allgather(&local, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, mpi_->comm),
          "MPI_Allgather");
    double result = all.front();
    for (const double v : all) {
        if (std::isnan(v)) {
            return v;
        }
        result = std::max(result, v);
    }
    return result;
}

double Communicator::sum(double local) const
{
    double value = local;
    sum(std::span<double>(&value, 1));
    return value;
}

void Communicator::sum(std::span<double> values) const
{
    if (!mpi_ || values.empty()) {
        return;
    }
    // Every rank's partial values, then added in rank order on every rank: the same bits on
    // each, and in each rerun (MPI_Allreduce leaves the order of additions open).
    const auto n = values.size();
    const ScopedSeconds timer(mpi_->sent.seconds);
    count_collective(n * sizeof(double), n * sizeof(double) * static_cast<std::size_t>(mpi_->size));
    std::vector<double> all(n * static_cast<std::size_t>(mpi_->size));
    check(MPI_Allgather(values.data(), static_cast<int>(n), MPI_DOUBLE, all.data(),
                        static_cast<int>(n), MPI_DOUBLE, mpi_->comm),
          "MPI_Allgather");
    for (std::size_t k = 0; k < n; ++k) {
        double total = 0.0;
        for (std::size_t r = 0; r < static_cast<std::size_t>(mpi_->size); ++r) {
            total += all[r * n + k];
        }
        values[k] = total;
    }
}

void Communicator::broadcast(std::string& bytes) const
{
    if (!mpi_) {
        return;
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    auto size = static_cast<unsigned long long>(bytes.size());
    check(MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, mpi_->comm), "MPI_Bcast");
    count_collective(mpi_->rank == 0 ? static_cast<std::size_t>(size) : 0,
                     mpi_->rank == 0 ? 0 : static_cast<std::size_t>(size));
    bytes.resize(static_cast<std::size_t>(size));
    // In pieces below MPI's int count limit.
    constexpr std::size_t piece = std::size_t{1} << 30;
    for (std::size_t start = 0; start < bytes.size(); start += piece) {
        const std::size_t count = std::min(piece, bytes.size() - start);
        check(MPI_Bcast(bytes.data() + start, static_cast<int>(count), MPI_CHAR, 0, mpi_->comm),
              "MPI_Bcast");
    }
}

void Communicator::exchange(std::span<const double> send, int destination,
                            std::span<double> receive, int source, int tag) const
{
    if (!mpi_) {
        if ((destination != 0 && destination != no_rank) || (source != 0 && source != no_rank)) {
            throw InternalError("Communicator::exchange: no such rank on this process alone");
        }
        if (destination == 0 && source == 0) {
            if (send.size() != receive.size()) {
                throw InternalError("Communicator::exchange: sizes differ");
            }
            std::copy(send.begin(), send.end(), receive.begin());
        }
        return;
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    const int to = destination == no_rank ? MPI_PROC_NULL : destination;
    const int from = source == no_rank ? MPI_PROC_NULL : source;
    if (to != MPI_PROC_NULL) {
        ++mpi_->sent.messages;
        mpi_->sent.bytes += static_cast<long>(send.size() * sizeof(double));
    }
    check(MPI_Sendrecv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, to, tag,
                       receive.data(), static_cast<int>(receive.size()), MPI_DOUBLE, from, tag,
                       mpi_->comm, MPI_STATUS_IGNORE),
          "MPI_Sendrecv");
}

void Communicator::send_and_receive(std::span<const Outgoing> sends,
                                    std::span<const Incoming> receives, int tag) const
{
    if (!mpi_) {
        if (!sends.empty() || !receives.empty()) {
            throw InternalError("Communicator::send_and_receive: no other rank on this process");
        }
        return;
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    std::vector<MPI_Request> requests;
    requests.reserve(sends.size() + receives.size());
    for (const Incoming& in : receives) {
        if (in.rank == mpi_->rank) {
            throw InternalError("Communicator::send_and_receive: a message from this rank");
        }
        check(MPI_Irecv(in.values.data(), static_cast<int>(in.values.size()), MPI_DOUBLE, in.rank,
                        tag, mpi_->comm, &requests.emplace_back()),
              "MPI_Irecv");
    }
    for (const Outgoing& out : sends) {
        if (out.rank == mpi_->rank) {
            throw InternalError("Communicator::send_and_receive: a message to this rank");
        }
        ++mpi_->sent.messages;
        mpi_->sent.bytes += static_cast<long>(out.values.size() * sizeof(double));
        check(MPI_Isend(out.values.data(), static_cast<int>(out.values.size()), MPI_DOUBLE,
                        out.rank, tag, mpi_->comm, &requests.emplace_back()),
              "MPI_Isend");
    }
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall");
}

std::vector<int> Communicator::all_gather(std::span<const int> local) const
{
    if (!mpi_) {
        return {local.begin(), local.end()};
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    count_collective(local.size() * sizeof(int),
                     local.size() * sizeof(int) * static_cast<std::size_t>(mpi_->size));
    std::vector<int> all(local.size() * static_cast<std::size_t>(mpi_->size));
    check(MPI_Allgather(local.data(), static_cast<int>(local.size()), MPI_INT, all.data(),
                        static_cast<int>(local.size()), MPI_INT, mpi_->comm),
          "MPI_Allgather");
    return all;
}

void Communicator::all_gather(std::span<const double> local, std::span<const int> counts,
                              std::span<double> all) const
{
    const auto n_ranks = static_cast<std::size_t>(size());
    if (counts.size() != n_ranks) {
        throw InternalError("Communicator::all_gather: one count per rank is needed");
    }
    std::vector<int> offsets(n_ranks, 0);
    long long total = counts.empty() ? 0 : counts[0];
    for (std::size_t q = 1; q < n_ranks; ++q) {
        total += counts[q];
        if (total > std::numeric_limits<int>::max()) {
            throw InternalError("Communicator::all_gather: more than 2^31 values (MPI's int "
                                "counts); gather them in pieces");
        }
        offsets[q] = offsets[q - 1] + counts[q - 1];
    }
    const auto own = static_cast<std::size_t>(rank());
    if (static_cast<std::size_t>(counts[own]) != local.size() ||
        static_cast<std::size_t>(offsets.back() + counts.back()) != all.size()) {
        throw InternalError("Communicator::all_gather: the counts do not match the values");
    }
    if (!mpi_) {
        std::copy(local.begin(), local.end(), all.begin());
        return;
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    count_collective(local.size() * sizeof(double), all.size() * sizeof(double));
    check(MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_DOUBLE, all.data(),
                         counts.data(), offsets.data(), MPI_DOUBLE, mpi_->comm),
          "MPI_Allgatherv");
}

void Communicator::all_to_all(std::span<const double> send, std::span<const int> send_counts,
                              std::span<double> receive, std::span<const int> receive_counts) const
{
    const auto n_ranks = static_cast<std::size_t>(size());
    if (send_counts.size() != n_ranks || receive_counts.size() != n_ranks) {
        throw InternalError("Communicator::all_to_all: one count per rank is needed");
    }
    if (!mpi_) {
        if (send.size() != receive.size()) {
            throw InternalError("Communicator::all_to_all: sizes differ");
        }
        std::copy(send.begin(), send.end(), receive.begin());
        return;
    }
    std::vector<int> send_offsets(n_ranks, 0);
    std::vector<int> receive_offsets(n_ranks, 0);
    for (std::size_t q = 1; q < n_ranks; ++q) {
        send_offsets[q] = send_offsets[q - 1] + send_counts[q - 1];
        receive_offsets[q] = receive_offsets[q - 1] + receive_counts[q - 1];
    }
    const ScopedSeconds timer(mpi_->sent.seconds);
    const auto own = static_cast<std::size_t>(mpi_->rank);
    ++mpi_->sent.all_to_alls;
    mpi_->sent.all_to_all_bytes += static_cast<long>(
        (send.size() - static_cast<std::size_t>(send_counts[own])) * sizeof(double));
    check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_DOUBLE,
                        receive.data(), receive_counts.data(), receive_offsets.data(), MPI_DOUBLE,
                        mpi_->comm),
          "MPI_Alltoallv");
}

Communicator Communicator::cartesian(std::span<const int> dims,
                                     std::span<const bool> is_periodic) const
{
    int product = 1;
    for (const int d : dims) {
        product *= d;
    }
    if (product != size() || dims.size() != is_periodic.size()) {
        throw InternalError("Communicator::cartesian: " + std::to_string(product) + " blocks for " +
                            std::to_string(size()) + " ranks");
    }
    if (!mpi_) {
        return {};
    }
    std::vector<int> periods(is_periodic.begin(), is_periodic.end());
    MPI_Comm cart = MPI_COMM_NULL;
    // reorder = 0: rank r of this communicator stays rank r, so the layout is the same on
    // every machine and outputs gathered in rank order do not depend on MPI's choice.
    check(MPI_Cart_create(mpi_->comm, static_cast<int>(dims.size()), dims.data(), periods.data(), 0,
                          &cart),
          "MPI_Cart_create");
    return Communicator(std::make_shared<const detail::MpiCommunicator>(cart, true));
}

void Communicator::cartesian_coords(std::span<int> coords) const
{
    if (!mpi_ || !mpi_->is_cartesian) {
        if (mpi_ && mpi_->size > 1) {
            throw InternalError("Communicator::cartesian_coords: not a Cartesian communicator");
        }
        std::fill(coords.begin(), coords.end(), 0);
        return;
    }
    check(MPI_Cart_coords(mpi_->comm, mpi_->rank, static_cast<int>(coords.size()), coords.data()),
          "MPI_Cart_coords");
}

int Communicator::cartesian_rank(std::span<const int> coords) const
{
    if (!mpi_ || !mpi_->is_cartesian) {
        if (mpi_ && mpi_->size > 1) {
            throw InternalError("Communicator::cartesian_rank: not a Cartesian communicator");
        }
        return 0;
    }
    int rank = 0;
    check(MPI_Cart_rank(mpi_->comm, coords.data(), &rank), "MPI_Cart_rank");
    return rank;
}

std::pair<int, int> Communicator::cartesian_neighbours(int axis, bool axis_is_periodic) const
{
    if (!mpi_ || !mpi_->is_cartesian) {
        if (mpi_ && mpi_->size > 1) {
            throw InternalError("Communicator::cartesian_neighbours: not a Cartesian communicator");
        }
        const int self = axis_is_periodic ? 0 : no_rank;
        return {self, self};
    }
    int below = MPI_PROC_NULL;
    int above = MPI_PROC_NULL;
    check(MPI_Cart_shift(mpi_->comm, axis, 1, &below, &above), "MPI_Cart_shift");
    return {below == MPI_PROC_NULL ? no_rank : below, above == MPI_PROC_NULL ? no_rank : above};
}

} // namespace fddem
