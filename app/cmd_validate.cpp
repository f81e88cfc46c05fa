// SPDX-License-Identifier: MIT
// fddem validate: runs the verification and validation cases against their references and
// writes a Markdown report with plots. The comparisons and the plots are in
// tools/validate.py (numpy, matplotlib: Debian's python3 packages); this command finds that
// script in the source tree fddem was built from and runs it on this very program.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "commands.hpp"

namespace fddem::app {

namespace {

/// The path of the running program (Linux: /proc/self/exe).
std::string self_path()
{
    std::error_code error;
    const std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::string("fddem") : path.string();
}

} // namespace

int validate_command(const ValidateOptions& options)
{
    const std::filesystem::path script =
        std::filesystem::path(FDDEM_SOURCE_DIR) / "tools" / "validate.py";
    if (!std::filesystem::exists(script)) {
        std::fprintf(stderr,
                     "fddem: validate needs the source tree fddem was built from (%s not "
                     "found)\n",
                     script.c_str());
        return exit_bad_input;
    }
    std::vector<std::string> arguments = {
        "/usr/bin/python3",      script.string(), "--fddem", self_path(), "-o",
        options.output_directory};
    if (options.quick) {
        arguments.emplace_back("--quick");
    }
    std::vector<char*> argv;
    for (std::string& a : arguments) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    const pid_t child = ::fork();
    if (child == 0) {
        ::execv(argv[0], argv.data());
        std::perror("fddem: validate: cannot run /usr/bin/python3");
        std::_Exit(exit_bad_input);
    }
    int status = 0;
    if (child < 0 || ::waitpid(child, &status, 0) < 0) {
        std::perror("fddem: validate");
        return exit_internal_error;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : exit_internal_error;
}

} // namespace fddem::app
