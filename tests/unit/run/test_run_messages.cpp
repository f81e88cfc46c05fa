// SPDX-License-Identifier: MIT
// watch_step (run/run_messages.hpp) on the joint film solve's iteration limits: the first step
// with a solve stopped at its limit is said once, with the step and the count; every one is
// counted in the run's record (summary.json's unfinished_film_solves); a step without one says
// nothing.

#include "fddem/run/run_messages.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fddem {
namespace {

struct Collect final : RunMonitor {
    std::vector<std::string> lines;
    void message(const std::string& text) override { lines.push_back(text); }
};

TEST(RunMessages, AFilmSolveStoppedAtItsLimitIsSaidOnceAndEveryOneCounted)
{
    const CaseConfig config;
    RunRecord record;
    Collect monitor;
    StepReport report;
    report.is_converged = true;
    Clock clock;
    clock.step = 1;
    watch_step(report, clock, config, record, monitor);
    EXPECT_TRUE(monitor.lines.empty());
    EXPECT_EQ(record.unfinished_film_solves, 0);

    report.unfinished_film_solves = 3;
    clock.step = 2;
    clock.time = 0.25;
    watch_step(report, clock, config, record, monitor);
    ASSERT_EQ(monitor.lines.size(), 1U);
    const std::string& said = monitor.lines.front();
    EXPECT_NE(said.find("warning: step 2 (t = 0.25 s): 3 of the lubrication films' joint solves"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("unfinished_film_solves"), std::string::npos) << said;

    report.unfinished_film_solves = 2;
    clock.step = 3;
    watch_step(report, clock, config, record, monitor);
    EXPECT_EQ(monitor.lines.size(), 1U); // said once
    EXPECT_EQ(record.unfinished_film_solves, 5);
}

} // namespace
} // namespace fddem
