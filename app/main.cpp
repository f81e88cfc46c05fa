// SPDX-License-Identifier: MIT
// The fddem program: parses the command line, runs one subcommand, maps failures to exit
// statuses (the library throws; only app/ decides how a failure ends the process).

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/linsolve/mpi_runtime.hpp"

#include <CLI/CLI.hpp>
#include <mpi.h>

#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"
#include "error_agreement.hpp"
#include "interrupt.hpp"

namespace {

/// MPI for hypre: one process by default; `mpirun -n 1 fddem …` is the same run. Started here
/// only under a launcher (to refuse more than one process before any work); otherwise the first
/// hypre solver starts it (fddem/linsolve/mpi_runtime.hpp). Ended here in either case.
class MpiSession {
public:
    MpiSession(int* argc, char*** argv)
    {
        if (fddem::is_started_by_mpi_launcher()) {
            fddem::start_mpi(argc, argv);
        }
    }
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    MpiSession(MpiSession&&) = delete;
    MpiSession& operator=(MpiSession&&) = delete;
    ~MpiSession() { fddem::finish_mpi(); }
};

/// "unknown subcommand 'bogus' …" when the first argument is a word that names no subcommand
/// (`fddem bogus`, which CLI11 reports only as "A subcommand is required"); "" otherwise.
std::string unknown_subcommand(const CLI::App& app, int argc, char** argv)
{
    if (argc < 2 || argv[1][0] == '-' || !app.get_subcommands().empty()) {
        return "";
    }
    std::string names;
    for (const CLI::App* command : app.get_subcommands({})) {
        names += (names.empty() ? "" : ", ") + command->get_name();
    }
    return "unknown subcommand '" + std::string(argv[1]) + "' (the subcommands are " + names + ")";
}

} // namespace

int main(int argc, char** argv)
{
    using namespace fddem::app;
    ignore_broken_pipes();
    MpiSession mpi(&argc, &argv);

    CLI::App app{"fddem: rigid particles in viscous incompressible fluid (FD-DEM, Wu & Yuan 2015)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", FDDEM_VERSION);

    RunOptions run;
    CLI::App* run_cmd = app.add_subcommand("run", "Run a case file");
    CLI::Option* case_option = run_cmd->add_option("case", run.case_file, "Case file (TOML)");
    CLI::Option* output_option = run_cmd->add_option(
        "-o,--output", run.output_directory,
        "Run directory (default: the case's output.directory, or runs/<case name>)");
    run_cmd->add_option(
        "--set", run.overrides,
        "Override a case key, section.key=value; bodies.N.key=value for body N (from 1), "
        "bodies.key=value for every body (repeatable)");
    CLI::Option* force_option =
        run_cmd->add_flag("--force", run.force, "Overwrite an existing run directory");
    run_cmd
        ->add_option("--restart", run.restart_directory,
                     "Continue the run in RUN_DIR from its newest usable checkpoint, with its "
                     "case.toml (and any --set overrides)")
        ->option_text("RUN_DIR")
        ->excludes(case_option)
        ->excludes(output_option)
        ->excludes(force_option);
    run_cmd->add_flag("-q,--quiet", run.quiet, "No progress output");

    bool keys = false;
    bool markdown = false;
    CLI::App* info_cmd =
        app.add_subcommand("info", "Version, build and libraries; --keys: case keys");
    info_cmd->add_flag("--keys", keys, "Print every case key with type, unit, default, range, doc");
    info_cmd->add_flag("--markdown", markdown, "With --keys: Markdown (docs/case-file.md)");

    ValidateOptions validate;
    CLI::App* validate_cmd = app.add_subcommand(
        "validate", "Run the verification and validation cases against their references; "
                    "writes DIR/report.md with plots");
    validate_cmd->add_flag("--quick", validate.quick, "The few-minute set (run in CI)");
    validate_cmd->add_option("-o,--output", validate.output_directory,
                             "Report directory (default: validation)");
    validate_cmd->add_option("--only", validate.only,
                             "Run only the checks whose name contains this text");

    PlotOptions plot;
    CLI::App* plot_cmd = app.add_subcommand(
        "plot", "Write the figures that fit a run (PNG, SVG) and with --movie an MP4 "
                "(the fddem Python package; docs/plotting.md)");
    plot_cmd->add_option("run", plot.run_directory, "Run directory")->required();
    plot_cmd->add_option("-o,--output", plot.output_directory,
                         "Figure directory (default: RUN_DIR/plots)");
    plot_cmd->add_flag("--movie", plot.movie, "Also OUT/movie.mp4 of the flow and bodies (ffmpeg)");
    plot_cmd->add_flag("--svg", plot.svg, "Each figure also as SVG");
    plot_cmd->add_option("--times", plot.times, "Times of the flow snapshots (default: spread)");
    plot_cmd->add_option("--only", plot.only,
                         "Only these figures (overview, solver, snapshots, …)");
    plot_cmd->add_option("--dpi", plot.dpi, "PNG resolution (default 130)")
        ->check(CLI::Range(20, 1200));
    plot_cmd->add_flag("-q,--quiet", plot.quiet, "No list of files, no progress bar");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string unknown = unknown_subcommand(app, argc, argv);
        std::fprintf(stderr, "fddem: command line: %s (see fddem --help)\n",
                     unknown.empty() ? e.what() : unknown.c_str());
        return exit_bad_input;
    }
    if (*run_cmd && run.case_file.empty() && run.restart_directory.empty()) {
        std::fprintf(stderr, "fddem: command line: run needs a case file or --restart RUN_DIR "
                             "(see fddem run --help)\n");
        return exit_bad_input;
    }

    int n_processes = 1;
    int is_mpi_started = 0;
    MPI_Initialized(&is_mpi_started);
    if (is_mpi_started != 0) {
        MPI_Comm_size(MPI_COMM_WORLD, &n_processes);
    }
    int rank = 0;
    if (n_processes > 1) {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (!*run_cmd) {
            if (rank == 0) {
                std::fprintf(stderr,
                             "fddem: only `fddem run` runs on more than one MPI process (got "
                             "%d); run this command with one process\n",
                             n_processes);
            }
            return exit_bad_input;
        }
    }
    run.n_processes = n_processes;
    ErrorAgreement agreement(n_processes);
    // On several processes an error that one rank meets would leave the others waiting in a
    // collective. An input error is met by every rank alike: rank 0 says it, and when every
    // rank has met it (app/error_agreement.hpp) they all end with its status. Any other error,
    // or one that not every rank meets within the wait, ends them all by MPI_Abort, said by
    // the rank that met it.
    const auto fail = [&](int status, const std::string& text, bool is_said_by_every_rank) {
        if (rank == 0 || !is_said_by_every_rank) {
            std::fprintf(stderr, "%s\n", text.c_str());
        }
        std::fflush(stderr);
        if (n_processes > 1) {
            // The ranks meet a common input error within moments of each other (they read the
            // same files); the wait bounds the delay of an input error met by fewer of them.
            constexpr double wait_seconds = 10.0;
            if (is_said_by_every_rank && agreement.every_rank_failed(wait_seconds)) {
                return status;
            }
            if (rank != 0 && is_said_by_every_rank) {
                std::fprintf(stderr, "%s (rank %d; not every rank met it)\n", text.c_str(), rank);
                std::fflush(stderr);
            }
            MPI_Abort(MPI_COMM_WORLD, status);
        }
        return status;
    };

    try {
        if (*run_cmd) {
            return run_command(run);
        }
        if (*validate_cmd) {
            return validate_command(validate);
        }
        if (*plot_cmd) {
            return plot_command(plot);
        }
        return info_command(keys, markdown);
    } catch (const fddem::InputError& e) {
        return fail(exit_bad_input, "fddem: " + e.formatted(), true);
    } catch (const fddem::OutputError& e) {
        // Neither fddem's fault nor the case's: the disk or the directory (full, removed, a
        // directory where a file must go). On several ranks the rank that met it says it.
        const std::string where = n_processes > 1 ? " (rank " + std::to_string(rank) + ")" : "";
        return fail(exit_internal_error,
                    "fddem: cannot write the run's output" + where + ": " + e.what(), false);
    } catch (const std::exception& e) {
        const std::string where = n_processes > 1 ? " (rank " + std::to_string(rank) + ")" : "";
        return fail(exit_internal_error, "fddem: internal error" + where + ": " + e.what(), false);
    }
}
