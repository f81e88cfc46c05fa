// SPDX-License-Identifier: MIT
#pragma once
/// When MPI runs. hypre needs MPI; nothing else in fddem does yet. Open MPI's start-up as a
/// singleton (a program not started by mpirun) costs about 0.45 s, a tenth of the paper's
/// Fig. 5 case, so a process starts MPI only when a hypre solver is built, or at once when
/// mpirun started it. MPI itself is process-wide state; these functions only ask it.

namespace fddem {

/// True if a launcher (mpirun, mpiexec, srun) started this process: its rank is in the
/// environment before MPI_Init.
[[nodiscard]] bool is_started_by_mpi_launcher();

/// Starts MPI (MPI_Init with the program's arguments, which may be null). Call once, from the
/// main thread, before any other MPI call.
void start_mpi(int* argc, char*** argv);
/// Starts MPI if it is not running and has not ended. Call from the main thread.
void ensure_mpi_started();

/// Ends MPI if it is running. Call once, from the main thread, after every hypre object is gone.
void finish_mpi();

} // namespace fddem
