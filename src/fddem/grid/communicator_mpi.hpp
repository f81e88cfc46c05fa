// SPDX-License-Identifier: MIT
#pragma once
/// The MPI communicator behind a Communicator, for the libraries that take one (hypre,
/// FFTW-MPI). Only their adapters include this header, so mpi.h stays out of the rest.

#include "fddem/grid/communicator.hpp"

#include <mpi.h>

namespace fddem {

/// The MPI_Comm of `comm`: MPI_COMM_SELF for Communicator::self() (MPI must be running).
[[nodiscard]] MPI_Comm mpi_handle(const Communicator& comm) noexcept;

} // namespace fddem
