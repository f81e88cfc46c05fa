// SPDX-License-Identifier: MIT
#pragma once
// The subcommands of the fddem program. Each returns the process exit status.

#include <string>
#include <vector>

namespace fddem::app {

/// Exit statuses: 0 success, 1 internal error or an unwritable output, 2 bad input, 3 numerical
/// failure, 128 + the signal number (130 SIGINT, 143 SIGTERM, the shells' convention) when a signal
/// stopped the run after a checkpoint.
inline constexpr int exit_success = 0;
inline constexpr int exit_internal_error = 1;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_numerical_failure = 3;
inline constexpr int exit_interrupted_base = 128;

struct RunOptions {
    std::string case_file;         ///< empty with restart_directory
    std::string restart_directory; ///< --restart: continue this run directory
    std::string output_directory;  ///< empty: from the case, or runs/<case stem>
    std::vector<std::string> overrides;
    bool force = false;
    bool quiet = false;
    /// The MPI processes running this command (mpirun -n): more than one splits the grid.
    int n_processes = 1;
};

struct ValidateOptions {
    std::string output_directory = "validation"; ///< report.md, PNGs and the run directories
    bool quick = false;                          ///< the CI-sized set (a few minutes)
    std::string only;                            ///< run only the checks whose name contains it
};

struct PlotOptions {
    std::string run_directory;
    std::string output_directory;  ///< empty: RUN_DIR/plots
    std::vector<double> times;     ///< of the flow snapshots; empty: spread over the run
    std::vector<std::string> only; ///< these figures only; empty: all that fit
    int dpi = 0;                   ///< PNG resolution; 0: the package's default
    bool movie = false;            ///< also OUT/movie.mp4
    bool svg = false;              ///< each figure also as SVG
    bool quiet = false;
};

int run_command(const RunOptions& options);
/// Runs the fddem Python package's `plot` on a run directory; 2 if it is not one.
int plot_command(const PlotOptions& options);
/// Runs tools/validate.py on this program; its exit status: 0 every check passes, 1 not.
int validate_command(const ValidateOptions& options);
int info_command(bool keys, bool markdown);

} // namespace fddem::app
