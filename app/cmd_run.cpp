// SPDX-License-Identifier: MIT
// `fddem run`: read and check the case (bad input writes nothing), then run it with the
// library's driver (fddem/run/run_case.hpp); with --restart, continue a run directory. This
// file supplies what belongs to the program: the default run directory, the progress line on
// the terminal, the signal handlers, and the exit status of each way a run ends.

#include "fddem/io/case_reader.hpp"
#include "fddem/run/rank_reasons.hpp"
#include "fddem/run/run_case.hpp"

#include <filesystem>
#include <limits>
#include <unistd.h>

#include "commands.hpp"
#include "interrupt.hpp"
#include "progress.hpp"

namespace fddem::app {
namespace {

namespace fs = std::filesystem;

fs::path default_run_directory(const RunOptions& options, const CaseConfig& config)
{
    if (!options.output_directory.empty()) {
        return options.output_directory;
    }
    if (!config.output.directory.empty()) {
        return config.output.directory;
    }
    const fs::path file(options.case_file);
    // cases/<…>/<name>/case.toml runs into runs/<name>.
    const std::string stem = file.stem() == "case" && file.has_parent_path()
                                 ? fs::absolute(file).parent_path().filename().string()
                                 : file.stem().string();
    return fs::path("runs") / stem;
}

/// The run as the user sees it on stderr: a status line redrawn on a terminal (plain lines
/// every output.log_interval steps otherwise, none with --quiet), messages on their own
/// lines; SIGINT, SIGTERM and SIGHUP stop the run after a step, with a checkpoint.
class TerminalMonitor final : public RunMonitor {
public:
    TerminalMonitor(const RunOptions& options, const CaseConfig& config)
        : progress_(stderr, !options.quiet && ::isatty(STDERR_FILENO) != 0,
                    options.quiet ? std::numeric_limits<long>::max() : config.output.log_interval,
                    config.time.end)
    {
    }

    void message(const std::string& text) override { progress_.message(text); }
    void loop_started(long step, double time) override { progress_.start(step, time); }
    void step_done(long step, double time, int outer_iterations) override
    {
        progress_.update(step, time, outer_iterations);
    }
    void loop_ended() override { progress_.finish(); }
    [[nodiscard]] int pending_interrupt() override { return app::pending_interrupt(); }

private:
    Progress progress_;
};

int exit_status(const RunResult& result)
{
    switch (result.outcome) {
    case RunResult::Outcome::completed:
        return exit_success;
    case RunResult::Outcome::numerical_failure:
        return exit_numerical_failure;
    case RunResult::Outcome::interrupted:
        return exit_interrupted_base + result.signal;
    }
    return exit_internal_error;
}

} // namespace

int run_command(const RunOptions& options)
{
    install_interrupt_handlers();
    const Communicator ranks =
        options.n_processes > 1 ? Communicator::world() : Communicator::self();
    RunMonitor quiet; // the other ranks: rank 0 speaks for the run
    if (!options.restart_directory.empty()) {
        const fs::path directory = options.restart_directory;
        // Rank 0 alone checks the lock; every rank reads the case (the same errors on each).
        CaseConfig config;
        agree_on_input_error(ranks, true, [&] {
            config = read_restart_case(directory, options.overrides, ranks.rank() == 0);
        });
        TerminalMonitor terminal(options, config);
        return exit_status(restart_run(
            config, directory, ranks.rank() == 0 ? static_cast<RunMonitor&>(terminal) : quiet,
            !options.overrides.empty(), ranks));
    }
    const CaseConfig config = read_case(options.case_file, options.overrides);
    TerminalMonitor terminal(options, config);
    return exit_status(run_case(config, default_run_directory(options, config),
                                ranks.rank() == 0 ? static_cast<RunMonitor&>(terminal) : quiet,
                                options.force, ranks));
}

} // namespace fddem::app
