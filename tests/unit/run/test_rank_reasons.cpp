// SPDX-License-Identifier: MIT
// first_reason on one process (run/rank_reasons.hpp): what this rank says, unchanged, and
// nothing when it says nothing, an empty reason included (its presence, not its text, counts).
// On several ranks: tests/mpi/split_run.py (a damaged piece that only rank 1 reads).

#include "fddem/run/rank_reasons.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fddem {
namespace {

TEST(RankReasons, OneProcessGivesItsOwnReasonOrNone)
{
    const Communicator self = Communicator::self();
    EXPECT_FALSE(first_reason(self, std::nullopt, "on rank").has_value());
    EXPECT_EQ(first_reason(self, std::string("is damaged"), "on rank"), "is damaged");
    EXPECT_EQ(first_reason(self, std::string(), "on rank"), ""); // a reason, though empty
    const std::string long_reason(1000, 'x');
    EXPECT_EQ(first_reason(self, long_reason, "on rank")->size(), 400U); // cut to 400 bytes
}

} // namespace
} // namespace fddem
