// SPDX-License-Identifier: MIT
// Test entry point: traps invalid operations, division by zero and overflow, so a NaN fails
// the test where it is born (STYLE.md §10), and initialises MPI once for hypre.

#include <gtest/gtest.h>
#include <mpi.h>

#include <cfenv>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace {

// Open MPI keeps what MPI_Init allocates alive past MPI_Finalize on purpose (caches and the
// plugins it loads and unloads); LeakSanitizer would report those blocks, with no names
// because the plugins are gone by then. Allocations made inside these two calls are excluded
// from leak checking; everything fddem and the tests allocate is still checked.
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

class FloatingPointTraps : public ::testing::Environment {
public:
    void SetUp() override { feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
    void TearDown() override { fedisableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
};

} // namespace

int main(int argc, char** argv)
{
    without_leak_checks([&] { return MPI_Init(&argc, &argv); });
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new FloatingPointTraps); // gtest takes ownership
    const int status = RUN_ALL_TESTS();
    without_leak_checks([] { return MPI_Finalize(); });
    return status;
}
