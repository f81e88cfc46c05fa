// SPDX-License-Identifier: MIT
// CSV histories: the byte length a checkpoint records, cutting a history back to it (a restart)
// and refusing histories that do not hold what the checkpoint records.

#include "fddem/core/errors.hpp"
#include "fddem/io/case_changes.hpp"
#include "fddem/io/csv_history.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <unistd.h>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;

class History : public ::testing::Test {
protected:
    void SetUp() override
    {
        path_ = fs::temp_directory_path() /
                ("fddem_history_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv");
    }
    void TearDown() override { fs::remove(path_); }

    fs::path path_;
    const std::vector<std::string> columns_{"step", "time"};
};

TEST_F(History, CutBackAndContinuedItReadsAsOneHistory)
{
    std::uint64_t after_two = 0;
    {
        CsvHistory history(path_, columns_);
        history.append({1.0, 0.5});
        history.append({2.0, 1.0});
        after_two = history.size();
        history.append({3.0, 1.5});
        EXPECT_EQ(history.size(), fs::file_size(path_));
    }
    check_history(path_, columns_, after_two);
    truncate_history(path_, after_two);
    {
        CsvHistory history(path_, columns_, CsvHistory::Continue{});
        EXPECT_EQ(history.size(), after_two);
        history.append({3.0, 1.25});
    }
    EXPECT_EQ(test::file_contents(path_), "step,time\n1,0.5\n2,1\n3,1.25\n");
}

TEST_F(History, HistoryThatDoesNotHoldTheCheckpointsRowsIsRefused)
{
    {
        CsvHistory history(path_, columns_);
        history.append({1.0, 0.5});
    }
    const std::uint64_t size = fs::file_size(path_);
    EXPECT_NO_THROW(check_history(path_, columns_, size));
    EXPECT_THROW(check_history(path_, columns_, size + 10), InputError); // cut short
    EXPECT_THROW(check_history(path_, columns_, size - 2), InputError);  // mid-row
    EXPECT_THROW(check_history(path_, {"step", "time", "dt"}, size), InputError);
    EXPECT_THROW(check_history(path_.string() + ".missing", columns_, size), InputError);
    EXPECT_EQ(fs::file_size(path_), size) << "a check changes nothing";
}

TEST(CaseChanges, NamesTheKeysAnOverrideChanged)
{
    const std::string before = "[time]\ndt = 0.01\nend = 1.0\n[[bodies]]\ndensity = 2.0\n"
                               "[[bodies]]\ndensity = 3.0\n";
    const std::string after = "# a comment\n[time]\nend = 2.0\ndt = 0.01\n[[bodies]]\n"
                              "density = 2.0\n[[bodies]]\ndensity = 3.5\n";
    const std::vector<std::string> changes = case_changes(before, after);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_EQ(changes[0], "bodies.2.density: 3.0 → 3.5");
    EXPECT_EQ(changes[1], "time.end: 1.0 → 2.0");
    EXPECT_TRUE(case_changes(before, before).empty());
}

} // namespace
} // namespace fddem
