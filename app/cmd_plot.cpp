// SPDX-License-Identifier: MIT
// fddem plot: the figures that fit a run, and with --movie an MP4. The plotting is the fddem
// Python package (python/fddem: numpy, matplotlib, ffmpeg for movies); this command finds the
// package (python_program.hpp) and runs `python3 -m fddem plot …` with the same arguments. The
// package checks the run directory itself (one line and exit status 2 when it is not a run).

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "python_program.hpp"

namespace fddem::app {

int plot_command(const PlotOptions& options)
{
    const std::optional<std::filesystem::path> package = find_python_package();
    if (!package) {
        std::fprintf(stderr, "fddem: plot needs the fddem Python package (python/fddem in the "
                             "source tree, share/fddem/python when installed, or "
                             "$FDDEM_PYTHONPATH); none found\n");
        return exit_bad_input;
    }
    std::vector<std::string> arguments = {python_interpreter(), "-m", "fddem", "plot",
                                          options.run_directory};
    if (!options.output_directory.empty()) {
        arguments.insert(arguments.end(), {"-o", options.output_directory});
    }
    if (options.movie) {
        arguments.emplace_back("--movie");
    }
    if (options.svg) {
        arguments.emplace_back("--svg");
    }
    if (options.quiet) {
        arguments.emplace_back("--quiet");
    }
    if (!options.times.empty()) {
        arguments.emplace_back("--times");
        for (const double t : options.times) {
            arguments.push_back(std::to_string(t));
        }
    }
    if (!options.only.empty()) {
        arguments.emplace_back("--only");
        arguments.insert(arguments.end(), options.only.begin(), options.only.end());
    }
    if (options.dpi > 0) {
        arguments.insert(arguments.end(), {"--dpi", std::to_string(options.dpi)});
    }
    return run_child(arguments, package->string());
}

} // namespace fddem::app
