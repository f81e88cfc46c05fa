// SPDX-License-Identifier: MIT
#include "fddem/linsolve/fftw_support.hpp"

#include "fddem/core/errors.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <mutex>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

namespace fddem {

void prepare_fftw_threads()
{
#ifdef FDDEM_HAVE_OPENMP
    static std::once_flag started;
    std::call_once(started, [] {
        if (fftw_init_threads() == 0) {
            throw InternalError("FFTW could not start its threads");
        }
    });
    // FFTW's threads split the independent 1-D transforms, so a thread count gives the same
    // result every run.
    fftw_plan_with_nthreads(omp_get_max_threads());
#endif
}

void prepare_fftw_mpi()
{
    prepare_fftw_threads();
    static std::once_flag started;
    std::call_once(started, [] { fftw_mpi_init(); });
}

double* allocate_fftw_work(std::size_t n)
{
    double* work = fftw_alloc_real(n);
    if (work == nullptr) {
        throw InternalError("FFTW could not allocate the Poisson work array");
    }
    std::fill(work, work + n, 0.0);
    return work;
}

} // namespace fddem
