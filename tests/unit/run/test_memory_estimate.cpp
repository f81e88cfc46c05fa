// SPDX-License-Identifier: MIT
// The memory estimate on several ranks (run/memory_estimate.hpp, issue 15): the largest rank's
// share, covering what was measured, and the check against a machine's memory counting only the
// ranks that run on it.

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/run/memory_estimate.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fddem {
namespace {

/// The lid-driven cube of docs/examples at n³ cells.
CaseConfig cube(int n)
{
    const std::string cells = std::to_string(n);
    return read_case(std::string(FDDEM_SOURCE_DIR) + "/docs/examples/cavity3d.toml",
                     {"domain.cells=[" + cells + "," + cells + "," + cells + "]"});
}

TEST(MemoryEstimate, OneRankIsTheWholeRun)
{
    const CaseConfig config = cube(96);
    EXPECT_EQ(estimate_rank_memory(config, 1), estimate_run_memory(config));
}

TEST(MemoryEstimate, EachOfTwoRanksNeedsAboutHalfAndCoversItsMeasuredPeak)
{
    // Measured (bench/RESULTS.md, "Peak memory per MPI rank"): the 96³ cube on 2 ranks peaked at
    // 529 MiB on the larger rank, 960 MiB on one process.
    constexpr double mib = 1024.0 * 1024.0;
    const CaseConfig config = cube(96);
    const double whole = estimate_run_memory(config);
    const double each = estimate_rank_memory(config, 2);
    EXPECT_GT(whole, 960 * mib);
    EXPECT_GT(each, 529 * mib);
    EXPECT_LT(each, 0.6 * whole); // a block of 96 × 96 × 48 and its ghosts, and the fixed part
    EXPECT_GT(each, 0.5 * whole);
    // Many ranks: the fixed part remains.
    EXPECT_LT(estimate_rank_memory(config, 64), 0.1 * whole);
    EXPECT_GT(estimate_rank_memory(config, 64), 48 * mib);
}

TEST(MemoryEstimate, TheCheckCountsOnlyTheRanksOnThisMachine)
{
    // A cluster run: 64 ranks of which 16 share this machine need 16 ranks' memory here, not the
    // whole run's; all 64 here would not fit.
    const CaseConfig config = cube(256);
    const double each = estimate_rank_memory(config, 64);
    const double limit = 20 * each;
    EXPECT_GT(estimate_run_memory(config), limit);
    EXPECT_NO_THROW(check_run_memory(config, limit, 64, 16));
    try {
        check_run_memory(config, limit, 64, 64);
        FAIL() << "64 ranks on one machine passed";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "domain.cells");
        EXPECT_NE(std::string(e.what()).find("for the 64 of its 64 ranks on this machine"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(check_run_memory(config, limit), InputError); // one process: the whole run
}

TEST(MemoryEstimate, TheMessageGivesTheLargestRanksShareOnSeveralRanks)
{
    const CaseConfig config = cube(96);
    const std::string one = memory_message(config, std::nullopt);
    EXPECT_EQ(one.find("ranks"), std::string::npos) << one;
    const std::string two = memory_message(config, std::nullopt, 2, 2);
    EXPECT_NE(two.find("; on 2 ranks about "), std::string::npos) << two;
    EXPECT_NE(two.find("for the 2 on this machine"), std::string::npos) << two;
}

} // namespace
} // namespace fddem
