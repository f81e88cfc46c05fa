// SPDX-License-Identifier: MIT
#pragma once
/// Whether the OpenMP threads of this process have a CPU each (issue 15: one rank through
/// mpirun must be no slower than one process). Open MPI binds each rank to one core by default
/// (to a socket above two ranks), so `OMP_NUM_THREADS=2 mpirun -n 1 fddem run …` puts both
/// threads on one core and runs at about half speed, without any message from MPI or OpenMP.

#include <string>

namespace fddem {

/// The CPUs this process may run on (its affinity mask, sched_getaffinity); 0 if unknown.
[[nodiscard]] int usable_cpus();

/// A warning when `threads` OpenMP threads must share fewer `cpus` (empty otherwise, and when
/// `cpus` is unknown, 0): it names both counts and the mpirun options that give each rank as
/// many cores as threads.
[[nodiscard]] std::string thread_placement_warning(int threads, int cpus);

} // namespace fddem
