// SPDX-License-Identifier: MIT
#include "fddem/linsolve/fft_mpi_poisson.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/communicator_mpi.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/fftw_support.hpp"
#include "fddem/linsolve/laplacian_eigenvalue.hpp"

#include <climits>
#include <fftw3-mpi.h>

#include <algorithm>
#include <cstddef>

namespace fddem {

template <int Dim>
struct FftMpiPoissonSolver<Dim>::Plans {
    double* work = nullptr; ///< this rank's slab (input) or transposed slab (output)
    fftw_plan forward = nullptr;
    fftw_plan backward = nullptr;

    explicit Plans(std::ptrdiff_t n) : work(allocate_fftw_work(static_cast<std::size_t>(n))) {}
    Plans(const Plans&) = delete;
    Plans& operator=(const Plans&) = delete;
    Plans(Plans&&) = delete;
    Plans& operator=(Plans&&) = delete;
    ~Plans()
    {
        if (forward != nullptr) {
            fftw_destroy_plan(forward);
        }
        if (backward != nullptr) {
            fftw_destroy_plan(backward);
        }
        fftw_free(work);
    }
};

namespace {

/// Where the row starting at `row` begins in `box` stored x fastest.
template <int Dim>
std::size_t position_in_box(const Box<Dim>& box, const Index<Dim>& row)
{
    std::size_t flat = 0;
    std::size_t stride = 1;
    for (int d = 0; d < Dim; ++d) {
        const auto a = static_cast<std::size_t>(d);
        flat += static_cast<std::size_t>(row[a] - box.lo[a]) * stride;
        stride *= static_cast<std::size_t>(box.extent(d));
    }
    return flat;
}

/// `box` with its last axis cut to [first, last); empty (hi = lo) where they do not meet.
template <int Dim>
Box<Dim> cut_to_slab(Box<Dim> box, int first, int last)
{
    constexpr auto z = static_cast<std::size_t>(Dim - 1);
    box.lo[z] = std::max(box.lo[z], first);
    box.hi[z] = std::max(box.lo[z], std::min(box.hi[z], last));
    return box;
}

int checked_count(std::size_t n)
{
    if (n > static_cast<std::size_t>(INT_MAX)) {
        throw InternalError("FFTW-MPI Poisson solver: a rank's share exceeds MPI's int count");
    }
    return static_cast<int>(n);
}

} // namespace

template <int Dim>
FftMpiPoissonSolver<Dim>::FftMpiPoissonSolver(const MacGrid<Dim>& grid,
                                              const std::array<bool, Dim>& is_periodic,
                                              bool is_measured)
    : grid_(grid)
{
    const Communicator& comm = grid.communicator();
    if (!comm.uses_mpi()) {
        throw InternalError("FftMpiPoissonSolver needs a grid on an MPI communicator");
    }
    prepare_fftw_mpi();

    // FFTW is row-major (first dimension slowest); our x is fastest, so dims are reversed and
    // FFTW's slabs cut fddem's last axis.
    std::array<std::ptrdiff_t, Dim> n{};
    std::array<fftw_r2r_kind, Dim> forward_kind{};
    std::array<fftw_r2r_kind, Dim> backward_kind{};
    double normalisation = 1.0; // FFTW transforms are unnormalised
    for (int d = 0; d < Dim; ++d) {
        const auto slot = static_cast<std::size_t>(Dim - 1 - d);
        const bool periodic = is_periodic[static_cast<std::size_t>(d)];
        n[slot] = grid.cells(d);
        forward_kind[slot] = periodic ? FFTW_R2HC : FFTW_REDFT10;
        backward_kind[slot] = periodic ? FFTW_HC2R : FFTW_REDFT01;
        normalisation *= periodic ? grid.cells(d) : 2.0 * grid.cells(d);
    }
    const MPI_Comm handle = mpi_handle(comm);
    std::ptrdiff_t local_n0 = 0;
    std::ptrdiff_t start0 = 0;
    std::ptrdiff_t local_n1 = 0;
    std::ptrdiff_t start1 = 0;
    // For r2r transforms the sizes are in real numbers (FFTW manual §6.6).
    const std::ptrdiff_t alloc = fftw_mpi_local_size_transposed(Dim, n.data(), handle, &local_n0,
                                                                &start0, &local_n1, &start1);
    plans_ = std::make_unique<Plans>(std::max<std::ptrdiff_t>(alloc, 1));
    slab_ = {static_cast<int>(start0), static_cast<int>(start0 + local_n0)};
    const unsigned flags = is_measured ? FFTW_MEASURE : FFTW_ESTIMATE;
    plans_->forward = fftw_mpi_plan_r2r(Dim, n.data(), plans_->work, plans_->work, handle,
                                        forward_kind.data(), flags | FFTW_MPI_TRANSPOSED_OUT);
    plans_->backward = fftw_mpi_plan_r2r(Dim, n.data(), plans_->work, plans_->work, handle,
                                         backward_kind.data(), flags | FFTW_MPI_TRANSPOSED_IN);
    if (plans_->forward == nullptr || plans_->backward == nullptr) {
        throw InternalError("FFTW-MPI could not plan the Poisson transforms");
    }

    // Every rank's block and slab, once: the routes between them do not change.
    std::array<int, 2 * Dim + 2> mine{};
    const Box<Dim>& block = grid.owned_cells();
    for (int d = 0; d < Dim; ++d) {
        mine[static_cast<std::size_t>(d)] = block.lo[static_cast<std::size_t>(d)];
        mine[static_cast<std::size_t>(Dim + d)] = block.hi[static_cast<std::size_t>(d)];
    }
    mine[2 * Dim] = slab_[0];
    mine[2 * Dim + 1] = slab_[1];
    const std::vector<int> all = comm.all_gather(mine);
    const auto n_ranks = static_cast<std::size_t>(comm.size());
    std::size_t n_out = 0;
    std::size_t n_in = 0;
    for (std::size_t q = 0; q < n_ranks; ++q) {
        const int* theirs = all.data() + q * mine.size();
        Box<Dim> their_block;
        for (int d = 0; d < Dim; ++d) {
            their_block.lo[static_cast<std::size_t>(d)] = theirs[d];
            their_block.hi[static_cast<std::size_t>(d)] = theirs[Dim + d];
        }
        routes_.send.push_back(cut_to_slab<Dim>(block, theirs[2 * Dim], theirs[2 * Dim + 1]));
        routes_.receive.push_back(cut_to_slab<Dim>(their_block, slab_[0], slab_[1]));
        routes_.send_counts.push_back(checked_count(routes_.send.back().size()));
        routes_.receive_counts.push_back(checked_count(routes_.receive.back().size()));
        n_out += routes_.send.back().size();
        n_in += routes_.receive.back().size();
    }
    outgoing_.resize(n_out);
    incoming_.resize(n_in);

    // 1/λ in the transposed output's order: FFTW's dimension 1 (local_n1 of it, from start1)
    // slowest, then dimension 0, then dimensions 2 … in order (FFTW manual §6.4.3).
    std::array<std::ptrdiff_t, Dim> shape = n;
    shape[0] = local_n1;
    shape[1] = n[0];
    std::size_t n_modes = 1;
    for (const std::ptrdiff_t s : shape) {
        n_modes *= static_cast<std::size_t>(s);
    }
    inverse_eigen_.assign(n_modes, 0.0);
    std::array<std::ptrdiff_t, Dim> t{}; // index in `shape`, last fastest
    for (std::size_t flat = 0; flat < n_modes; ++flat) {
        std::array<std::ptrdiff_t, Dim> mode = t; // the mode along each FFTW dimension
        mode[0] = t[1];
        mode[1] = t[0] + start1;
        double lambda = 0.0;
        bool is_constant = true;
        for (int d = 0; d < Dim; ++d) {
            const auto slot = static_cast<std::size_t>(Dim - 1 - d);
            lambda +=
                laplacian_eigenvalue(static_cast<int>(mode[slot]), grid.cells(d), grid.spacing(d),
                                     is_periodic[static_cast<std::size_t>(d)]);
            is_constant = is_constant && mode[slot] == 0;
        }
        // The constant mode is the null space: zero, as in the one-process solver.
        inverse_eigen_[flat] = is_constant ? 0.0 : 1.0 / (lambda * normalisation);
        for (int s = Dim - 1; s >= 0; --s) {
            auto& ts = t[static_cast<std::size_t>(s)];
            if (++ts < shape[static_cast<std::size_t>(s)]) {
                break;
            }
            ts = 0;
        }
    }
}

template <int Dim>
FftMpiPoissonSolver<Dim>::~FftMpiPoissonSolver() = default;

template <int Dim>
void FftMpiPoissonSolver<Dim>::blocks_to_slabs(const CellField<Dim>& from)
{
    std::size_t offset = 0;
    for (const Box<Dim>& box : routes_.send) {
        const auto nx = static_cast<std::size_t>(box.extent(0));
        for_each_row(box, [&](const Index<Dim>& row) {
            const double* source = from.data() + grid_.offset(row);
            std::copy(source, source + nx,
                      outgoing_.data() + offset + position_in_box<Dim>(box, row));
        });
        offset += box.size();
    }
    grid_.communicator().all_to_all(outgoing_, routes_.send_counts, incoming_,
                                    routes_.receive_counts);
    const Box<Dim> slab = cut_to_slab<Dim>(grid_.cell_box(), slab_[0], slab_[1]);
    offset = 0;
    for (const Box<Dim>& box : routes_.receive) {
        const auto nx = static_cast<std::size_t>(box.extent(0));
        for_each_row(box, [&](const Index<Dim>& row) {
            const double* source = incoming_.data() + offset + position_in_box<Dim>(box, row);
            std::copy(source, source + nx, plans_->work + position_in_box<Dim>(slab, row));
        });
        offset += box.size();
    }
}

template <int Dim>
void FftMpiPoissonSolver<Dim>::slabs_to_blocks(CellField<Dim>& to)
{
    // The reverse of blocks_to_slabs: what came in from rank q goes back to it.
    const Box<Dim> slab = cut_to_slab<Dim>(grid_.cell_box(), slab_[0], slab_[1]);
    std::size_t offset = 0;
    for (const Box<Dim>& box : routes_.receive) {
        const auto nx = static_cast<std::size_t>(box.extent(0));
        for_each_row(box, [&](const Index<Dim>& row) {
            const double* source = plans_->work + position_in_box<Dim>(slab, row);
            std::copy(source, source + nx,
                      incoming_.data() + offset + position_in_box<Dim>(box, row));
        });
        offset += box.size();
    }
    grid_.communicator().all_to_all(incoming_, routes_.receive_counts, outgoing_,
                                    routes_.send_counts);
    offset = 0;
    for (const Box<Dim>& box : routes_.send) {
        const auto nx = static_cast<std::size_t>(box.extent(0));
        for_each_row(box, [&](const Index<Dim>& row) {
            const double* source = outgoing_.data() + offset + position_in_box<Dim>(box, row);
            std::copy(source, source + nx, to.data() + grid_.offset(row));
        });
        offset += box.size();
    }
}

template <int Dim>
void FftMpiPoissonSolver<Dim>::solve(const CellField<Dim>& rhs, CellField<Dim>& phi)
{
    blocks_to_slabs(rhs);
    fftw_execute(plans_->forward);
    double* work = plans_->work;
    const double* inverse = inverse_eigen_.data();
    const auto n = static_cast<std::ptrdiff_t>(inverse_eigen_.size());
    [[maybe_unused]] const bool is_threaded = inverse_eigen_.size() >= min_points_for_threads;
#pragma omp parallel for schedule(static) if (is_threaded)
    for (std::ptrdiff_t k = 0; k < n; ++k) {
        work[k] *= inverse[k];
    }
    fftw_execute(plans_->backward);
    slabs_to_blocks(phi);
}

template class FftMpiPoissonSolver<2>;
template class FftMpiPoissonSolver<3>;

} // namespace fddem
