// SPDX-License-Identifier: MIT
#pragma once
/// One run of a case in its run directory: the time loop, the outputs on their schedule,
/// checkpoints, and the end of the run. A new run (start) and a restarted one (resume,
/// driver_restart.cpp) prepare the directory differently, then share the time loop. Callers use
/// run_case.hpp; this class is the machinery behind it.

#include "fddem/io/run_record.hpp"
#include "fddem/run/run_monitor.hpp"
#include "fddem/run/run_outputs.hpp"
#include "fddem/simulation/simulation.hpp"

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace fddem {

/// How a run ended. A restarted run that finds its case already complete is `completed`.
struct RunResult {
    enum class Outcome {
        completed,         ///< reached the end of its case
        numerical_failure, ///< stopped at a blow-up, with a checkpoint of the last good step
        interrupted,       ///< stopped at the monitor's request, with a checkpoint
    };
    Outcome outcome = Outcome::completed;
    int signal = 0; ///< with `interrupted`: the signal number the monitor gave
};

template <int Dim>
class Driver {
public:
    /// Builds the simulation from `config` (InputError for bad input, before anything is
    /// written), on `ranks`. `monitor` must outlive the driver.
    ///
    /// On several ranks (issue 15; every rank holds all bodies) every rank steps its block and
    /// writes its pieces of the field and particle frames (run/field_frames.hpp) and of the
    /// checkpoints (io/checkpoint.hpp), and samples the line points in its cells; rank 0 alone
    /// writes the rest: the run directory, solver.csv, particles.csv, the frames' master files
    /// and .pvd collections, the checkpoints' files, the line samples (gathered point by
    /// point), summary.json, the progress and messages (the other ranks' monitors should be
    /// quiet). No rank holds the whole grid. The files are those of a one-process run of the
    /// same case, but for the frames and checkpoints in pieces; a checkpoint continues on any
    /// number of ranks.
    Driver(const CaseConfig& config, std::filesystem::path directory, RunMonitor& monitor,
           const Communicator& ranks = Communicator::self());

    /// A new run: prepares the run directory (InputError if it holds files, unless
    /// `overwrite`), writes the initial outputs, steps to the end.
    RunResult start(bool overwrite);

    /// Continues the run in the directory from its newest usable checkpoint (a damaged one is
    /// set aside and the previous one used), cutting the outputs back to that step first.
    /// Throws InputError, before writing anything, when no checkpoint is usable, a checkpoint
    /// belongs to another grid or bodies, or the outputs do not match the checkpoint. With
    /// `rewrite_case`, case.toml is rewritten as the case now run (it was changed by --set).
    RunResult resume(bool rewrite_case);

private:
    RunResult step_to_end();
    /// Closes the outputs and says how the run ended: by a numerical `failure` (its text), by
    /// the interrupt `signal`, or (neither) at the end of the case.
    RunResult end_run(const std::string& failure, int signal);
    /// particles.csv rows and field frames due at the end of the step just taken.
    void write_scheduled_outputs();
    /// The outputs at the end of a run (completed or failed): the closing field frame, the line
    /// samples, summary.json with `status`, and a checkpoint.
    void close_outputs(const std::string& status);
    /// Checkpoint at the end of the current step; the first `n_frames` frames of each .pvd
    /// are recorded as the run's (the end-of-run frame outside output.field_interval is not).
    void write_checkpoint_now(std::size_t n_frames);
    void write_summary(const std::string& status) const;
    /// Once per process: a warning when a body with a shallow retracted marker ring comes within
    /// half a cell of a wall without coupling.markers_off_at_walls (wall_proximity.hpp).
    void warn_of_wall_ring();
    /// The last message of a completed run.
    [[nodiscard]] std::string completion_message() const;
    /// time.steady: whether the march reached the steady state and solved its last step.
    [[nodiscard]] std::string steady_march_verdict() const;
    [[nodiscard]] double wall_seconds() const;
    /// Whether this process writes the run's files.
    [[nodiscard]] bool is_writer() const noexcept { return ranks_.rank() == 0; }

    CaseConfig config_;
    Communicator ranks_;
    int ranks_on_node_; ///< how many of the ranks run on this machine (for the memory estimate)
    Simulation<Dim> sim_;
    std::filesystem::path directory_;
    RunMonitor& monitor_;
    RunOutputs<Dim> outputs_;
    RunRecord record_;
    std::filesystem::path last_checkpoint_;
    /// Wall time of the time loop before this process (a restarted run) [s].
    double wall_seconds_before_ = 0.0;
    std::chrono::steady_clock::time_point loop_start_;
    /// Retried steps this process has taken (time.max_retries); the first few are reported.
    long retried_steps_ = 0;
    /// On several ranks: the largest peak resident memory of the ranks other than 0 [MiB], taken
    /// at the end of the run (end_run), for summary.json.
    double other_ranks_peak_mib_ = 0.0;
    /// Whether this process warned of a shallow marker ring beside a wall (warn_of_wall_ring).
    bool has_warned_wall_ring_ = false;
    static constexpr long max_reported_retries = 10;
};

} // namespace fddem
