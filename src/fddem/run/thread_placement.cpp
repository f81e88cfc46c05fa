// SPDX-License-Identifier: MIT
#include "fddem/run/thread_placement.hpp"

#include <fmt/format.h>

#include <sched.h>

namespace fddem {

int usable_cpus()
{
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (sched_getaffinity(0, sizeof(mask), &mask) != 0) {
        return 0;
    }
    return CPU_COUNT(&mask);
}

std::string thread_placement_warning(int threads, int cpus)
{
    if (cpus <= 0 || threads <= cpus) {
        return {};
    }
    return fmt::format("fddem: warning: {} OpenMP threads share {} CPU{} (mpirun binds each rank "
                       "to a core by default); give each rank as many cores as threads with "
                       "mpirun --map-by slot:PE={} (or --bind-to none), or set OMP_NUM_THREADS={}",
                       threads, cpus, cpus == 1 ? "" : "s", threads, cpus);
}

} // namespace fddem
