// SPDX-License-Identifier: MIT
#include "python_program.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

#include "commands.hpp"

namespace fddem::app {

namespace fs = std::filesystem;

namespace {

bool holds_package(const fs::path& directory)
{
    std::error_code error;
    return fs::is_regular_file(directory / "fddem" / "__init__.py", error);
}

} // namespace

std::string python_interpreter()
{
    const char* chosen = std::getenv("FDDEM_PYTHON");
    return chosen != nullptr && *chosen != '\0' ? std::string(chosen) : "/usr/bin/python3";
}

std::string self_path()
{
    std::error_code error;
    const fs::path path = fs::read_symlink("/proc/self/exe", error);
    return error ? std::string("fddem") : path.string();
}

std::optional<fs::path> find_python_package()
{
    std::vector<fs::path> candidates;
    if (const char* chosen = std::getenv("FDDEM_PYTHONPATH"); chosen != nullptr && *chosen) {
        candidates.emplace_back(chosen);
    }
    candidates.push_back(fs::path(self_path()).parent_path().parent_path() / "share" / "fddem" /
                         "python");
    candidates.emplace_back(FDDEM_PYTHON_DIR);
    for (const fs::path& candidate : candidates) {
        if (holds_package(candidate)) {
            return candidate;
        }
    }
    return std::nullopt;
}

int run_child(std::vector<std::string> arguments, const std::string& pythonpath)
{
    std::vector<char*> argv;
    for (std::string& a : arguments) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    const pid_t child = ::fork();
    if (child == 0) {
        if (!pythonpath.empty()) {
            const char* old = std::getenv("PYTHONPATH");
            const std::string value =
                old != nullptr && *old != '\0' ? pythonpath + ":" + old : pythonpath;
            ::setenv("PYTHONPATH", value.c_str(), 1);
        }
        ::execv(argv[0], argv.data());
        std::fprintf(stderr, "fddem: cannot run %s (install it: tools/install-deps.sh)\n", argv[0]);
        std::_Exit(exit_bad_input);
    }
    int status = 0;
    if (child < 0 || ::waitpid(child, &status, 0) < 0) {
        std::perror("fddem: running python");
        return exit_internal_error;
    }
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) {
        return exit_interrupted_base + SIGINT;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : exit_internal_error;
}

} // namespace fddem::app
