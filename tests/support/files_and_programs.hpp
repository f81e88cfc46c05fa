// SPDX-License-Identifier: MIT
#pragma once
/// Helpers for tests that look at files and run the fddem program: a file read whole, solver.csv
/// without its wall time, a fresh scratch directory per test, and `fddem …` run through the shell
/// with its output captured, or started in the background.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ; // NOLINT: POSIX, for posix_spawn

namespace fddem::test {

/// The whole file, bytes as they are ("" if it cannot be read).
inline std::string file_contents(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The lines of `text`, without their line ends.
inline std::vector<std::string> lines_of(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

/// The rows of RUN/solver.csv without their wall_seconds column (the last one, which no two
/// runs share): what must be equal for two runs to be the same.
inline std::vector<std::string> solver_rows_without_wall_time(const std::filesystem::path& run)
{
    std::vector<std::string> rows = lines_of(file_contents(run / "solver.csv"));
    for (std::string& row : rows) {
        row = row.substr(0, row.rfind(','));
    }
    return rows;
}

/// An empty directory under the system's temporary directory, named after `prefix` (which
/// starts with "fddem_"), the process and the running test, so that parallel tests never share
/// one. test_main.cpp removes it when the test passes.
inline std::filesystem::path fresh_test_directory(const std::string& prefix)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        (prefix + std::to_string(::getpid()) + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

struct ProgramResult {
    int status = -1;    ///< exit status, −1 if the program did not exit normally
    std::string output; ///< stdout and stderr
};

/// Runs `fddem ARGUMENTS` (the build's program) to its end, stdout and stderr into `log`.
inline ProgramResult run_fddem(const std::string& arguments, const std::filesystem::path& log)
{
    const std::string command =
        std::string(FDDEM_EXECUTABLE) + " " + arguments + " > " + log.string() + " 2>&1";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, file_contents(log)};
}

/// Starts `fddem WORDS…` (the build's program) without waiting, stdout and stderr into `log`;
/// returns its pid (for kill and waitpid).
inline pid_t start_fddem(std::vector<std::string> words, const std::filesystem::path& log)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    words.insert(words.begin(), FDDEM_EXECUTABLE);
    std::vector<char*> argv;
    for (std::string& w : words) {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, FDDEM_EXECUTABLE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    EXPECT_EQ(error, 0);
    return pid;
}

/// The exit status of the process `pid` once it ends; −1 if a signal ended it.
inline int wait_for_exit(pid_t pid)
{
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

} // namespace fddem::test
