// SPDX-License-Identifier: MIT
// Test entry point: traps invalid operations, division by zero and overflow, so a NaN fails
// the test where it is born (STYLE.md §10), and initialises MPI once for hypre.

#include "fddem/linsolve/mpi_runtime.hpp"

#include <gtest/gtest.h>

#include <cfenv>

namespace {

class FloatingPointTraps : public ::testing::Environment {
public:
    void SetUp() override { feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
    void TearDown() override { fedisableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
};

} // namespace

int main(int argc, char** argv)
{
    fddem::start_mpi(&argc, &argv); // outside leak checking (linsolve/mpi_runtime.cpp)
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new FloatingPointTraps); // gtest takes ownership
    const int status = RUN_ALL_TESTS();
    fddem::finish_mpi();
    return status;
}
