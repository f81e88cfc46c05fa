// SPDX-License-Identifier: MIT
// The warning for OpenMP threads that share fewer CPUs (run/thread_placement.hpp).

#include "fddem/run/thread_placement.hpp"

#include <gtest/gtest.h>

namespace fddem {
namespace {

TEST(ThreadPlacement, TwoThreadsOnOneCpuAreWarnedWithTheMpirunOptions)
{
    const std::string warning = thread_placement_warning(2, 1);
    EXPECT_NE(warning.find("2 OpenMP threads share 1 CPU "), std::string::npos) << warning;
    EXPECT_NE(warning.find("--map-by slot:PE=2"), std::string::npos) << warning;
    EXPECT_NE(warning.find("OMP_NUM_THREADS=1"), std::string::npos) << warning;
    EXPECT_NE(thread_placement_warning(8, 4).find("8 OpenMP threads share 4 CPUs"),
              std::string::npos);
}

TEST(ThreadPlacement, NoWarningWhenEveryThreadHasACpuOrTheMaskIsUnknown)
{
    EXPECT_EQ(thread_placement_warning(1, 1), "");
    EXPECT_EQ(thread_placement_warning(2, 2), "");
    EXPECT_EQ(thread_placement_warning(2, 8), "");
    EXPECT_EQ(thread_placement_warning(4, 0), "");
}

TEST(ThreadPlacement, ThisProcessMayRunOnAtLeastOneCpu)
{
    EXPECT_GE(usable_cpus(), 1);
}

} // namespace
} // namespace fddem
