// SPDX-License-Identifier: MIT
#include "fddem/linsolve/fft_poisson.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/linsolve/fftw_support.hpp"
#include "fddem/linsolve/laplacian_eigenvalue.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstdlib>

namespace fddem {

template <int Dim>
struct FftPoissonSolver<Dim>::Plans {
    // FFTW's own allocation: SIMD-aligned in every process, so that a plan recorded as wisdom
    // in one process fits the array of another (wisdom depends on the alignment).
    double* work = nullptr; ///< the owned cells, x fastest, contiguous
    std::size_t size = 0;
    fftw_plan forward = nullptr;
    fftw_plan backward = nullptr;
    std::array<int, Dim> dims{};
    std::array<fftw_r2r_kind, Dim> forward_kind{};
    std::array<fftw_r2r_kind, Dim> backward_kind{};
    unsigned flags = FFTW_ESTIMATE;

    explicit Plans(std::size_t n) : work(allocate_fftw_work(n)), size(n) {}
    Plans(const Plans&) = delete;
    Plans& operator=(const Plans&) = delete;
    Plans(Plans&&) = delete;
    Plans& operator=(Plans&&) = delete;
    ~Plans()
    {
        destroy();
        fftw_free(work);
    }

    void destroy() noexcept
    {
        if (forward != nullptr) {
            fftw_destroy_plan(forward);
            forward = nullptr;
        }
        if (backward != nullptr) {
            fftw_destroy_plan(backward);
            backward = nullptr;
        }
    }

    /// (Re)plans both transforms; planning overwrites `work`, which holds nothing between
    /// solves. With OpenMP, on all of its threads (FFTW's threads split the independent 1-D
    /// transforms, so a thread count gives the same result every run).
    void make()
    {
        destroy();
        prepare_fftw_threads();
        forward = fftw_plan_r2r(Dim, dims.data(), work, work, forward_kind.data(), flags);
        backward = fftw_plan_r2r(Dim, dims.data(), work, work, backward_kind.data(), flags);
        if (forward == nullptr || backward == nullptr) {
            throw InternalError("FFTW could not plan the Poisson transforms");
        }
    }
};

template <int Dim>
FftPoissonSolver<Dim>::FftPoissonSolver(const MacGrid<Dim>& grid,
                                        const std::array<bool, Dim>& is_periodic, bool is_measured)
    : grid_(grid), plans_(std::make_unique<Plans>(grid.n_cells()))
{
    const std::size_t n_total = grid.n_cells();
    inverse_eigen_.assign(n_total, 0.0);

    // FFTW is row-major (first dimension slowest); our x is fastest, so dims are reversed.
    double normalisation = 1.0; // FFTW transforms are unnormalised
    for (int d = 0; d < Dim; ++d) {
        const auto slot = static_cast<std::size_t>(Dim - 1 - d);
        const bool periodic = is_periodic[static_cast<std::size_t>(d)];
        plans_->dims[slot] = grid.cells(d);
        plans_->forward_kind[slot] = periodic ? FFTW_R2HC : FFTW_REDFT10;
        plans_->backward_kind[slot] = periodic ? FFTW_HC2R : FFTW_REDFT01;
        normalisation *= periodic ? grid.cells(d) : 2.0 * grid.cells(d);
    }
    // Measured plans are faster but may differ between processes (see PoissonSettings and
    // plan_record()).
    plans_->flags = is_measured ? FFTW_MEASURE : FFTW_ESTIMATE;
    plans_->make();

    // Serial walk in the contiguous (x fastest) order of the work array.
    std::array<int, Dim> m{};
    for (std::size_t flat = 0; flat < n_total; ++flat) {
        double lambda = 0.0;
        for (int d = 0; d < Dim; ++d) {
            lambda +=
                laplacian_eigenvalue(m[static_cast<std::size_t>(d)], grid.cells(d), grid.spacing(d),
                                     is_periodic[static_cast<std::size_t>(d)]);
        }
        // The constant mode (λ = 0) is the null space: its coefficient is set to zero,
        // which removes the mean of rhs and returns the zero-mean solution.
        inverse_eigen_[flat] = flat == 0 ? 0.0 : 1.0 / (lambda * normalisation);
        for (int d = 0; d < Dim; ++d) {
            auto& md = m[static_cast<std::size_t>(d)];
            if (++md < grid.cells(d)) {
                break;
            }
            md = 0;
        }
    }
}

template <int Dim>
FftPoissonSolver<Dim>::~FftPoissonSolver() = default;

template <int Dim>
std::string FftPoissonSolver<Dim>::plan_record() const
{
    if (plans_->flags == FFTW_ESTIMATE) {
        return {};
    }
    char* text = fftw_export_wisdom_to_string();
    std::string record = text == nullptr ? std::string() : std::string(text);
    std::free(text); // NOLINT(*-no-malloc,*-owning-memory): FFTW documents free() for it
    return record;
}

template <int Dim>
void FftPoissonSolver<Dim>::restore_plans(const std::string& record)
{
    if (record.empty()) {
        return;
    }
    // The wisdom of this process (its own measurements) would compete with the recorded one.
    fftw_forget_wisdom();
    if (fftw_import_wisdom_from_string(record.c_str()) == 0) {
        throw InternalError("FFTW could not read the recorded Poisson plans");
    }
    plans_->make();
}

template <int Dim>
void FftPoissonSolver<Dim>::solve(const CellField<Dim>& rhs, CellField<Dim>& phi)
{
    const Box<Dim> box = grid_.owned_cells();
    const int nx = box.extent(0);
    // Gather the owned cells into the contiguous work array, row by row.
    for_each_row(box, [&](const Index<Dim>& row) {
        std::size_t flat = 0;
        std::size_t stride = 1;
        for (int d = 0; d < Dim; ++d) {
            flat += static_cast<std::size_t>(row[static_cast<std::size_t>(d)]) * stride;
            stride *= static_cast<std::size_t>(grid_.cells(d));
        }
        const double* source = rhs.data() + grid_.offset(row);
        std::copy(source, source + nx, plans_->work + flat);
    });
    fftw_execute(plans_->forward);
    double* work = plans_->work;
    const double* inverse = inverse_eigen_.data();
    const auto n = static_cast<std::ptrdiff_t>(plans_->size);
    [[maybe_unused]] const bool is_threaded = plans_->size >= min_points_for_threads;
#pragma omp parallel for schedule(static) if (is_threaded)
    for (std::ptrdiff_t k = 0; k < n; ++k) {
        work[k] *= inverse[k];
    }
    fftw_execute(plans_->backward);
    for_each_row(box, [&](const Index<Dim>& row) {
        std::size_t flat = 0;
        std::size_t stride = 1;
        for (int d = 0; d < Dim; ++d) {
            flat += static_cast<std::size_t>(row[static_cast<std::size_t>(d)]) * stride;
            stride *= static_cast<std::size_t>(grid_.cells(d));
        }
        const double* begin = work + flat;
        std::copy(begin, begin + nx, phi.data() + grid_.offset(row));
    });
}

template class FftPoissonSolver<2>;
template class FftPoissonSolver<3>;

} // namespace fddem
