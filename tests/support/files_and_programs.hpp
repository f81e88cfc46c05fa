// SPDX-License-Identifier: MIT
#pragma once
/// Helpers for tests that look at files and run the fddem program: a file read whole, solver.csv
/// without its wall time, a fresh scratch directory per test, and `fddem …` run through the shell
/// with its output captured.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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

/// An empty directory under the system's temporary directory, named after `prefix`, the
/// process and the running test, so that parallel tests never share one.
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

} // namespace fddem::test
