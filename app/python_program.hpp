// SPDX-License-Identifier: MIT
#pragma once
// Running fddem's Python side (`fddem plot`, `fddem validate`): which interpreter, where the
// fddem package is, and a child process whose exit status becomes the command's.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fddem::app {

/// $FDDEM_PYTHON, else Debian's /usr/bin/python3 (the one with python3-numpy and
/// python3-matplotlib; a pyenv python3 earlier on PATH may lack them).
std::string python_interpreter();

/// The directory that holds the fddem Python package (fddem/__init__.py), searched in order:
/// $FDDEM_PYTHONPATH; <prefix>/share/fddem/python beside an installed <prefix>/bin/fddem; the
/// source tree this program was built from (FDDEM_PYTHON_DIR, set by CMake). None if none has it.
std::optional<std::filesystem::path> find_python_package();

/// The path of the running program (Linux: /proc/self/exe).
std::string self_path();

/// Runs `arguments` (arguments[0] is the program's path) as a child process, with `pythonpath`
/// put first on its PYTHONPATH when not empty, and waits for it. Returns its exit status (1 if it
/// could not be started or ended by a signal other than SIGINT).
int run_child(std::vector<std::string> arguments, const std::string& pythonpath = "");

} // namespace fddem::app
