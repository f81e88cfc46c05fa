// SPDX-License-Identifier: MIT
#pragma once
/// What the one-process and the MPI FFT Poisson solvers share of FFTW: its process-wide
/// start-up and its aligned work arrays.

#include <cstddef>

namespace fddem {

/// Before FFTW plans a transform: starts FFTW's thread support once per process (FFTW manual
/// §5.2) and sets the thread count of the next plans to OpenMP's. Without OpenMP, nothing.
void prepare_fftw_threads();

/// Before FFTW-MPI plans a transform: prepare_fftw_threads(), then fftw_mpi_init() once per
/// process (FFTW manual §6.12.2: after MPI_Init and after the threads). MPI must be running.
void prepare_fftw_mpi();

/// A zeroed array of `n` doubles from fftw_alloc_real (SIMD-aligned in every process, so that
/// wisdom recorded in one process fits the array of another); free it with fftw_free. Throws
/// InternalError if FFTW cannot allocate it.
[[nodiscard]] double* allocate_fftw_work(std::size_t n);

} // namespace fddem
