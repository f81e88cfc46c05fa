// SPDX-License-Identifier: MIT
#pragma once
/// When MPI runs. hypre needs MPI; nothing else in fddem does yet. Open MPI's start-up as a
/// singleton (a program not started by mpirun) costs about 0.45 s, a tenth of the paper's
/// Fig. 5 case, so a process starts MPI only when a hypre solver is built, or at once when
/// mpirun started it. MPI itself is process-wide state; these functions only ask it.

#include <functional>

namespace fddem {

/// True if a launcher (mpirun, mpiexec, srun) started this process among several: its world's
/// size is in the environment before MPI_Init (Open MPI's OMPI_COMM_WORLD_SIZE, Hydra's
/// PMI_SIZE, Slurm's SLURM_NTASKS), and is not 1; also when only a PMIx rank says that a
/// launcher is there. One process through `mpirun -n 1` then runs as a plain process does
/// (MPI only if a hypre solver starts it), so it is no slower than one (issue 15).
[[nodiscard]] bool is_started_by_mpi_launcher();

/// The answer of is_started_by_mpi_launcher() for an environment read by `variable` (a
/// getenv: the value, or null when unset).
[[nodiscard]] bool
is_started_among_several(const std::function<const char*(const char*)>& variable);

/// Starts MPI (MPI_Init_thread with the program's arguments, which may be null, asking for
/// MPI_THREAD_FUNNELED: MPI calls from the main thread while OpenMP threads run). Call once,
/// from the main thread, before any other MPI call.
void start_mpi(int* argc, char*** argv);
/// Starts MPI if it is not running and has not ended. Call from the main thread.
void ensure_mpi_started();

/// Ends MPI if it is running. Call once, from the main thread, after every hypre object is gone.
void finish_mpi();

} // namespace fddem
