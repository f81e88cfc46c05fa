// SPDX-License-Identifier: MIT
// When a process starts MPI at once (linsolve/mpi_runtime.hpp): under a launcher that started
// several processes, not under `mpirun -n 1` (which then runs as one plain process does).

#include "fddem/linsolve/mpi_runtime.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace fddem {
namespace {

/// is_started_among_several() in an environment of `variables` alone.
bool starts_with(const std::map<std::string, std::string>& variables)
{
    return is_started_among_several([&](const char* name) -> const char* {
        const auto found = variables.find(name);
        return found == variables.end() ? nullptr : found->second.c_str();
    });
}

TEST(MpiRuntime, SeveralProcessesFromAnyLauncherStartMpiAtOnce)
{
    EXPECT_TRUE(starts_with({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "2"}}));
    EXPECT_TRUE(starts_with({{"PMI_SIZE", "2"}}));
    EXPECT_TRUE(starts_with({{"SLURM_NTASKS", "64"}}));
    EXPECT_TRUE(starts_with({{"PMIX_RANK", "0"}})); // size unknown before MPI_Init
}

TEST(MpiRuntime, OneProcessOrNoLauncherRunsWithoutMpi)
{
    EXPECT_FALSE(starts_with({}));
    EXPECT_FALSE(starts_with({{"OMPI_COMM_WORLD_SIZE", "1"}, {"PMIX_RANK", "0"}}));
    EXPECT_FALSE(starts_with({{"PMI_SIZE", "1"}}));
    EXPECT_FALSE(starts_with({{"SLURM_NTASKS", "1"}}));
}

} // namespace
} // namespace fddem
