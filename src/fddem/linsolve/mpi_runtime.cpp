// SPDX-License-Identifier: MIT
#include "fddem/linsolve/mpi_runtime.hpp"

#include "fddem/core/errors.hpp"

#include <mpi.h>

#include <cstdlib>

namespace fddem {

bool is_started_by_mpi_launcher()
{
    // Open MPI, MPICH/Hydra and PMIx-based launchers, Slurm.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_NTASKS"}) {
        if (std::getenv(name) != nullptr) {
            return true;
        }
    }
    return false;
}

void ensure_mpi_started()
{
    int is_started = 0;
    int is_finished = 0;
    MPI_Initialized(&is_started);
    MPI_Finalized(&is_finished);
    if (is_started != 0) {
        return;
    }
    if (is_finished != 0) {
        throw InternalError("MPI was needed after it had ended");
    }
    if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) {
        throw InternalError("MPI_Init failed");
    }
}

void finish_mpi()
{
    int is_started = 0;
    int is_finished = 0;
    MPI_Initialized(&is_started);
    MPI_Finalized(&is_finished);
    if (is_started != 0 && is_finished == 0) {
        MPI_Finalize();
    }
}

} // namespace fddem
