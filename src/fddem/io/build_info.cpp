// SPDX-License-Identifier: MIT
#include "fddem/io/build_info.hpp"

#include <Eigen/Core>
#include <HYPRE_config.h>
#include <fftw3.h>
#include <fmt/format.h>
#include <mpi.h>
#include <toml++/toml.h>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

#ifndef FDDEM_GIT_COMMIT
#define FDDEM_GIT_COMMIT "unknown"
#endif
#ifndef FDDEM_BUILD_TYPE
#define FDDEM_BUILD_TYPE "unknown"
#endif
#ifndef FDDEM_COMPILER
#define FDDEM_COMPILER "unknown"
#endif

namespace fddem {

std::vector<std::pair<std::string, std::string>> build_info()
{
    std::vector<std::pair<std::string, std::string>> info;
    info.reserve(16); // also keeps GCC 12 from a false -Wnull-dereference in vector growth
    info.emplace_back("version", FDDEM_VERSION);
    info.emplace_back("commit", FDDEM_GIT_COMMIT);
    info.emplace_back("build_type", FDDEM_BUILD_TYPE);
    info.emplace_back("compiler", FDDEM_COMPILER);
    info.emplace_back("fftw", fftw_version);
    info.emplace_back("hypre", HYPRE_RELEASE_VERSION);
    std::string mpi(MPI_MAX_LIBRARY_VERSION_STRING, '\0');
    int length = 0;
    MPI_Get_library_version(mpi.data(), &length);
    mpi.resize(static_cast<std::size_t>(length));
    if (const auto newline = mpi.find_first_of("\r\n,"); newline != std::string::npos) {
        mpi.resize(newline);
    }
    info.emplace_back("mpi", mpi);
    int is_initialised = 0;
    MPI_Initialized(&is_initialised);
    int n_processes = 1;
    if (is_initialised != 0) {
        MPI_Comm_size(MPI_COMM_WORLD, &n_processes);
    }
    info.emplace_back("mpi_processes", std::to_string(n_processes));
    info.emplace_back("eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
                                           EIGEN_MINOR_VERSION));
    info.emplace_back("tomlplusplus",
                      fmt::format("{}.{}.{}", TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH));
    info.emplace_back("fmt", fmt::format("{}", FMT_VERSION));
#ifdef FDDEM_HAVE_OPENMP
    info.emplace_back("openmp", fmt::format("{} (threads {})", _OPENMP, omp_get_max_threads()));
#else
    info.emplace_back("openmp", "off (threads 1)");
#endif
    return info;
}

} // namespace fddem
