// SPDX-License-Identifier: MIT
// Test entry point: traps invalid operations, division by zero and overflow, so a NaN fails
// the test where it is born (STYLE.md §10), initialises MPI once for hypre, and removes the
// scratch directories of a test that passed (a failed test's stay, to be looked at).

#include "fddem/linsolve/mpi_runtime.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace {

class FloatingPointTraps : public ::testing::Environment {
public:
    void SetUp() override { feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
    void TearDown() override { fedisableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW); }
};

/// Removes, after each passed test, the directories test::fresh_test_directory made for it
/// (files_and_programs.hpp: named …<pid>_<test name> in the temporary directory).
class ScratchCleaner : public ::testing::EmptyTestEventListener {
public:
    void OnTestEnd(const ::testing::TestInfo& test) override
    {
        if (!test.result()->Passed()) {
            return;
        }
        // A parameterised test's name is "Name/N": its directory is …_Name/N, under …_Name.
        const std::string name = test.name();
        const std::string tail = std::to_string(::getpid()) + "_" + name.substr(0, name.find('/'));
        std::error_code error;
        const std::filesystem::path temp = std::filesystem::temp_directory_path(error);
        if (error) {
            return;
        }
        for (const auto& entry : std::filesystem::directory_iterator(temp, error)) {
            const std::string entry_name = entry.path().filename().string();
            if (entry_name.starts_with("fddem_") && entry_name.ends_with(tail)) {
                std::filesystem::remove_all(entry.path(), error);
            }
        }
    }
};

} // namespace

int main(int argc, char** argv)
{
    fddem::start_mpi(&argc, &argv); // outside leak checking (linsolve/mpi_runtime.cpp)
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new FloatingPointTraps); // gtest takes ownership
    ::testing::UnitTest::GetInstance()->listeners().Append(new ScratchCleaner); // ditto
    const int status = RUN_ALL_TESTS();
    fddem::finish_mpi();
    return status;
}
