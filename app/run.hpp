// SPDX-License-Identifier: MIT
#pragma once
// One `fddem run`: a simulation, its run directory and its outputs. A new run (start) and a
// restarted one (resume, app/run_restart.cpp) prepare the directory differently, then share
// the time loop and the end of the run.

#include "fddem/io/checkpoint_files.hpp"
#include "fddem/io/csv_history.hpp"
#include "fddem/io/run_record.hpp"
#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress.hpp"

namespace fddem::app {

template <int Dim>
class Run {
public:
    Run(const CaseConfig& config, std::filesystem::path directory, const RunOptions& options);

    /// A new run: prepares the run directory (bad input throws before anything is written),
    /// writes the initial outputs, steps to the end. Returns the exit status.
    int start(bool force);

    /// Continues the run in the directory from its newest usable checkpoint (a damaged one is
    /// set aside and the previous one used), cutting the outputs back to that step first.
    /// Throws InputError, before writing anything, when no checkpoint is usable, a checkpoint
    /// belongs to another grid or bodies, or the outputs do not match the checkpoint. With
    /// `has_overrides` (--set), case.toml is rewritten as the case now run.
    int resume(bool has_overrides);

private:
    static std::vector<std::string> solver_columns();
    static std::vector<std::string> particle_columns();

    int step_to_end();
    /// The outputs at the end of a run (completed or failed): the closing field frame, the line
    /// samples, summary.json with `status`, and a checkpoint.
    void close_outputs(const std::string& status);
    /// Checkpoint at the end of the current step; the first `n_frames` frames of each .pvd
    /// are recorded as the run's (the end-of-run frame outside output.field_interval is not).
    void write_checkpoint_now(std::size_t n_frames);
    [[nodiscard]] bool is_checkpoint_due();
    [[nodiscard]] double wall_seconds() const;

    void write_particles();
    void write_fields();
    void write_samples();
    void write_summary(const std::string& status);
    void report_derived();
    void watch(const StepReport& report);

    CaseConfig config_;
    Simulation<Dim> sim_;
    std::filesystem::path directory_;
    Progress progress_;
    PvdCollection pvd_;
    PvdCollection particles_pvd_;
    std::unique_ptr<CsvHistory> solver_;
    std::unique_ptr<CsvHistory> particles_;
    RunRecord record_;
    std::filesystem::path last_checkpoint_;
    /// Wall time of the time loop before this process (a restarted run) [s].
    double wall_seconds_before_ = 0.0;
    std::chrono::steady_clock::time_point loop_start_;
};

} // namespace fddem::app
