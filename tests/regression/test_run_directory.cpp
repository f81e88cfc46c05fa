// SPDX-License-Identifier: MIT
// A run directory under hostile but realistic use (issue 17): two processes on one directory,
// `--force` over an old run with the user's own files in it, a read-only directory, a closed
// stderr, SIGHUP, SIGTERM before the time loop, a grid that does not fit in memory.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "support/case_builders.hpp"
#include "support/files_and_programs.hpp"

namespace {

namespace fs = std::filesystem;

using fddem::test::file_contents;
using fddem::test::lines_of;
using Result = fddem::test::ProgramResult;

const char* const cavity = fddem::test::small_cavity_case;

class RunDirectory : public ::testing::Test {
protected:
    void SetUp() override
    {
        root_ = fddem::test::fresh_test_directory("fddem_run_directory_test_");
        case_file_ = root_ / "cavity.toml";
        std::ofstream(case_file_) << cavity;
        log_ = root_ / "fddem.log";
    }
    void TearDown() override { fs::remove_all(root_); }

    [[nodiscard]] Result run(const std::string& arguments) const
    {
        return fddem::test::run_fddem(arguments, log_);
    }

    /// Starts a run of the cavity to t = 50 000 (800 000 steps: it runs until stopped) into
    /// `directory` and waits until it has taken a step; returns its pid. (To t = 1000, 16 000
    /// steps, the 16 × 16 cavity at steady state, one outer iteration a step, ran out in about
    /// 1.2 s on a free machine, and once ended before the test's SIGHUP reached it.)
    [[nodiscard]] pid_t start_long_run(const fs::path& directory, const fs::path& log) const
    {
        const pid_t pid =
            fddem::test::start_fddem({"run", case_file_.string(), "-o", directory.string(), "--set",
                                      "time.end=50000", "--set", "output.field_interval=0"},
                                     log);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (lines_of(file_contents(directory / "solver.csv")).size() < 2 &&
               std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return pid;
    }

    fs::path root_;
    fs::path case_file_;
    fs::path log_;
};

TEST_F(RunDirectory, ASecondProcessIsRefusedWhileTheFirstRunsAndLetInOnceItHasEnded)
{
    // Issue 17: a run and a --restart of it (or two --restarts) both ran, and solver.csv got
    // NUL bytes, missing and duplicated steps.
    const fs::path dir = root_ / "run";
    const pid_t first = start_long_run(dir, root_ / "first.log");
    for (const std::string& second :
         {"run --restart " + dir.string(),
          "run " + case_file_.string() + " --force -o " + dir.string()}) {
        const Result r = run(second);
        EXPECT_EQ(r.status, 2) << second << "\n" << r.output;
        EXPECT_NE(r.output.find(dir.string() +
                                ": the run directory is in use by another fddem "
                                "process (pid " +
                                std::to_string(first) + ")"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
    // A closed terminal (or a batch system) sends SIGHUP: a checkpoint, exit status 129.
    ::kill(first, SIGHUP);
    EXPECT_EQ(fddem::test::wait_for_exit(first), 128 + SIGHUP)
        << file_contents(root_ / "first.log");
    EXPECT_NE(file_contents(root_ / "first.log").find("interrupted by SIGHUP"), std::string::npos);
    EXPECT_NE(file_contents(dir / "summary.json").find("interrupted by SIGHUP"), std::string::npos);
    // Every step once, in order: the refused processes wrote nothing.
    const std::vector<std::string> rows = lines_of(file_contents(dir / "solver.csv"));
    for (std::size_t k = 1; k < rows.size(); ++k) {
        ASSERT_EQ(rows[k].substr(0, rows[k].find(',')), std::to_string(k)) << rows[k];
    }
    // The lock went with the process: the run continues, three steps further.
    const double end = 0.0625 * static_cast<double>(rows.size() + 2);
    const Result r =
        run("run --restart " + dir.string() + " --set time.end=" + std::to_string(end));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(lines_of(file_contents(dir / "solver.csv")).size(), rows.size() + 3);
}

TEST_F(RunDirectory, ForceRemovesTheOldRunsOutputsAndNothingElse)
{
    // Issue 17: a stale summary.json ("completed, 8 steps") stayed beside the new run's, and
    // old frames and samples stayed, listed or not.
    const fs::path dir = root_ / "run";
    ASSERT_EQ(run("run " + case_file_.string() + " -q -o " + dir.string()).status, 0);
    ASSERT_TRUE(fs::exists(dir / "fields/fields_000002.vtr"));
    const std::vector<std::string> mine{"notes.txt",        "fields/my_plot.png",
                                        "samples/mine.txt", "checkpoints/README",
                                        "analysis/a.csv",   "case.toml.orig"};
    for (const std::string& file : mine) {
        fs::create_directories((dir / file).parent_path());
        std::ofstream(dir / file) << "mine";
    }
    // The rerun: four steps, no line sample, no frames between the first and the last.
    const fs::path shorter = root_ / "shorter.toml";
    std::string text = cavity;
    text = text.substr(0, text.find("[[output.lines]]"));
    std::ofstream(shorter) << text;
    const Result r =
        run("run " + shorter.string() +
            " -q --force --set time.end=0.25 --set output.field_interval=0 -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
    for (const std::string& file : mine) {
        EXPECT_EQ(file_contents(dir / file), "mine") << file;
    }
    for (const char* gone : {"fields/fields_000002.vtr", "samples/vertical_centerline.csv",
                             "checkpoints/checkpoint_0000000008.ckpt"}) {
        EXPECT_FALSE(fs::exists(dir / gone)) << gone;
    }
    EXPECT_TRUE(fs::exists(dir / "fields/fields_000001.vtr"));
    EXPECT_TRUE(fs::exists(dir / "checkpoints/checkpoint_0000000004.ckpt"));
    EXPECT_NE(file_contents(dir / "summary.json").find("\"steps\" : 4,"), std::string::npos);
    EXPECT_EQ(lines_of(file_contents(dir / "solver.csv")).size(), 5U);
}

TEST_F(RunDirectory, WhatARunStoppedAtItsStartLeavesNeedsNoForce)
{
    // Issue 17: SIGTERM in the first milliseconds left case.toml.tmp.PID, and the rerun then
    // needed --force. Now the handlers are in place before anything is written: a SIGTERM at
    // any moment leaves no temporary.
    for (const int delay_ms : {0, 2, 5, 10, 20, 40}) {
        const fs::path dir = root_ / ("stopped_" + std::to_string(delay_ms));
        const pid_t pid =
            fddem::test::start_fddem({"run", case_file_.string(), "-q", "-o", dir.string()}, log_);
        std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
        ::kill(pid, SIGTERM);
        (void)fddem::test::wait_for_exit(pid);
        std::error_code error;
        for (const auto& entry : fs::recursive_directory_iterator(dir, error)) {
            EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << entry.path();
        }
    }
    // And what a kill -9 at that moment leaves (a temporary, the lock file, empty folders) is
    // no run to keep: the rerun goes ahead without --force.
    const fs::path dir = root_ / "killed";
    fs::create_directories(dir / "fields");
    fs::create_directories(dir / "samples");
    std::ofstream(dir / "case.toml.tmp.4242") << "[domain";
    std::ofstream(dir / ".fddem.lock") << "4242";
    const Result r = run("run " + case_file_.string() + " -q -o " + dir.string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(dir / "case.toml.tmp.4242"));
}

/// Runs `command` with `directory` read-only: as root (for whom permissions do not count) on a
/// read-only bind mount in a mount namespace of its own; otherwise with its write permission
/// taken away. False if neither can be arranged.
bool run_with_read_only(const fs::path& directory, const std::string& command)
{
    if (::geteuid() != 0) {
        fs::permissions(directory,
                        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                        fs::perm_options::remove);
        const int status = std::system(command.c_str());
        fs::permissions(directory, fs::perms::owner_write, fs::perm_options::add);
        return status != -1;
    }
    const std::string d = directory.string();
    const std::string wrapped = "unshare -m sh -c 'mount --bind " + d + " " + d +
                                " && mount -o remount,bind,ro " + d + " && " + command + "'";
    return std::system("unshare -m true 2>/dev/null") == 0 && std::system(wrapped.c_str()) != -1;
}

TEST_F(RunDirectory, ARestartInAReadOnlyDirectoryIsBadInputBeforeAnyWork)
{
    // Issue 17: "internal error: cannot write …" (exit 1) after the work had begun.
    const fs::path dir = root_ / "run";
    ASSERT_EQ(run("run " + case_file_.string() + " -q -o " + dir.string()).status, 0);
    const std::string before = file_contents(dir / "solver.csv");
    const fs::path out = root_ / "restart.log";
    const std::string command = std::string(FDDEM_EXECUTABLE) + " run --restart " + dir.string() +
                                " --set time.end=2 > " + out.string() + " 2>&1; echo $? >> " +
                                out.string();
    if (!run_with_read_only(dir, command)) {
        GTEST_SKIP() << "cannot make a directory read-only here";
    }
    const std::vector<std::string> lines = lines_of(file_contents(out));
    ASSERT_EQ(lines.size(), 2U) << file_contents(out);
    EXPECT_EQ(lines[0].find("fddem: " + dir.string() + ": the run directory is not writable"), 0U)
        << lines[0];
    EXPECT_EQ(lines[1], "2");
    EXPECT_EQ(file_contents(dir / "solver.csv"), before);
}

TEST_F(RunDirectory, AFrameThatCannotBeWrittenStopsTheRunWithOneMessageNamingIt)
{
    // A directory where the second field frame (t = 0.25) must go: its rename fails mid-run,
    // as on a full disk. One message naming the file and what failed, exit status 1, and the
    // first frame left whole.
    const fs::path dir = root_ / "run";
    fs::create_directories(dir / "fields" / "fields_000001.vtr" / "x");
    const Result result = run("run " + case_file_.string() + " -q --force -o " + dir.string());
    EXPECT_EQ(result.status, 1) << result.output;
    const std::vector<std::string> lines = lines_of(result.output);
    ASSERT_FALSE(lines.empty());
    // The memory estimate (said even with -q), then the failure, once, as the last line.
    EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                            [](const std::string& l) { return l.find("cannot write") != l.npos; }),
              1)
        << result.output;
    EXPECT_EQ(lines.back().find("fddem: cannot write the run's output: "), 0U) << lines.back();
    EXPECT_NE(lines.back().find("fields_000001.vtr"), std::string::npos) << lines.back();
    EXPECT_GT(fs::file_size(dir / "fields" / "fields_000000.vtr"), 0U);
}

TEST_F(RunDirectory, AClosedStderrStopsThePrintingNotTheRun)
{
    // Issue 17: `fddem run … 2>&1 | head -c 10` ended with exit status 141 (SIGPIPE), no
    // message and no final checkpoint.
    const fs::path dir = root_ / "run";
    const fs::path status = root_ / "status";
    const std::string command = "(" + std::string(FDDEM_EXECUTABLE) + " run " +
                                case_file_.string() + " -o " + dir.string() +
                                " --set output.log_interval=1 --set time.end=8 2>&1; echo $? > " +
                                status.string() + ") | head -c 10 > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(file_contents(status), "0\n");
    EXPECT_NE(file_contents(dir / "summary.json").find("\"status\" : \"completed\""),
              std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "checkpoints/checkpoint_0000000128.ckpt"));
}

TEST_F(RunDirectory, EveryRunSaysItsMemoryEstimateWhichCoversItsPeak)
{
    // One step on 512 × 512 cells: the estimate is above the program's peak resident memory
    // (the largest of this test's children: ctest runs each test in a process of its own), and
    // within twice it.
    const fs::path dir = root_ / "run";
    const Result r = run("run " + case_file_.string() +
                         " --set domain.cells=[512,512] --set time.dt=1e-4 --set time.end=1e-4 "
                         "-o " +
                         dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string said = "fddem: memory estimate ";
    const auto at = r.output.find(said);
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_EQ(r.output.find(" MiB for 512 × 512 cells (limit ", at), at + said.size() + 3)
        << r.output;
    const double estimate_mib = std::stod(r.output.substr(at + said.size()));
    rusage children{};
    ::getrusage(RUSAGE_CHILDREN, &children);
    const double peak_mib = static_cast<double>(children.ru_maxrss) / 1024.0;
    std::printf("512 x 512: estimate %.1f MiB, peak %.1f MiB\n", estimate_mib, peak_mib);
    EXPECT_GE(estimate_mib, peak_mib);
    EXPECT_LE(estimate_mib, 2.0 * peak_mib);
}

} // namespace
