// SPDX-License-Identifier: MIT
#include "fddem/linsolve/mpi_runtime.hpp"

#include "fddem/core/errors.hpp"

#include <mpi.h>

#include <cstdlib>
#include <string_view>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
// The leak check at exit does not scan thread-local storage (use_tls=0). With Open MPI's plugins
// loaded and unloaded by MPI_Init and MPI_Finalize, GCC 12's LeakSanitizer read a dynamic TLS
// block of the main thread with a bogus range (0xd9b–0x400002a9d) and crashed ("Tracer caught
// signal 11") at the exit of the sanitizer build's test_verification, even when it only listed
// its tests. No fddem object lives only in thread-local storage, so no leak is hidden by this.
// A library default: LSAN_OPTIONS in the environment (the tests' suppressions) still applies.
extern "C" const char* __lsan_default_options()
{
    return "use_tls=0";
}
// Without the TLS scan, the OpenMP runtime's thread-pool state, reachable only from the
// threads' TLS, would be reported as leaked: libgomp's own blocks are not checked.
extern "C" const char* __lsan_default_suppressions()
{
    return "leak:libgomp.so\n";
}
#endif

namespace fddem {

namespace {

// Open MPI keeps what MPI_Init allocates alive past MPI_Finalize on purpose (caches and the
// plugins it loads and unloads), and MPI_Finalize leaves some of its own; LeakSanitizer would
// report those blocks in a sanitizer build, with no names because the plugins are gone by then.
// Allocations made inside these two calls are excluded from leak checking (as the tests' entry
// point does, tests/support/test_main.cpp); everything fddem allocates is still checked.
template <class Call>
int without_leak_checks(Call call)
{
#if defined(__SANITIZE_ADDRESS__)
    __lsan_disable();
    const int status = call();
    __lsan_enable();
    return status;
#else
    return call();
#endif
}

} // namespace

bool is_started_among_several(const std::function<const char*(const char*)>& variable)
{
    // Open MPI, MPICH/Hydra and Slurm give the world's size: start MPI unless it is one.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_NTASKS"}) {
        if (const char* size = variable(name); size != nullptr) {
            return std::string_view(size) != "1";
        }
    }
    // A PMIx launcher that gives only the rank: the size is known after MPI_Init.
    return variable("PMIX_RANK") != nullptr;
}

bool is_started_by_mpi_launcher()
{
    return is_started_among_several([](const char* name) -> const char* {
        return std::getenv(name); // NOLINT(concurrency-mt-unsafe): before any thread starts
    });
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
    start_mpi(nullptr, nullptr);
}

void start_mpi(int* argc, char*** argv)
{
    // FUNNELED: the OpenMP threads may run while the main thread calls MPI (the momentum sweeps'
    // wavefront exchanges its end slices from the main thread inside a parallel region;
    // grid/loops.hpp). Every MPI library provides it; what is provided is checked.
    int provided = MPI_THREAD_SINGLE;
    if (without_leak_checks([&] {
            return MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
        }) != MPI_SUCCESS) {
        throw InternalError("MPI_Init_thread failed");
    }
    if (provided < MPI_THREAD_FUNNELED) {
        throw InternalError("MPI does not provide MPI_THREAD_FUNNELED");
    }
}

void finish_mpi()
{
    int is_started = 0;
    int is_finished = 0;
    MPI_Initialized(&is_started);
    MPI_Finalized(&is_finished);
    if (is_started != 0 && is_finished == 0) {
        without_leak_checks([] { return MPI_Finalize(); });
    }
}

} // namespace fddem
