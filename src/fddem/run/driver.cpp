// SPDX-License-Identifier: MIT
// A run from its start: the run directory, the initial outputs, the time loop with its outputs
// and checkpoints, and the end of the run (also the end of a restarted run).

#include "fddem/run/driver.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/checkpoint.hpp"
#include "fddem/io/checkpoint_files.hpp"
#include "fddem/io/run_directory.hpp"
#include "fddem/io/summary.hpp"
#include "fddem/run/body_snapshot.hpp"
#include "fddem/run/line_samples.hpp"
#include "fddem/run/memory_estimate.hpp"
#include "fddem/run/output_schedule.hpp"
#include "fddem/run/run_messages.hpp"
#include "fddem/run/run_summary.hpp"
#include "fddem/run/wall_proximity.hpp"
#include "fddem/simulation/simulation_setup.hpp"

#include <fmt/format.h>

#include <utility>

namespace fddem {

namespace fs = std::filesystem;
using Seconds = std::chrono::duration<double>;

template <int Dim>
Driver<Dim>::Driver(const CaseConfig& config, fs::path directory, RunMonitor& monitor,
                    const Communicator& ranks)
    : config_(config), ranks_(ranks), ranks_on_node_(ranks.ranks_on_this_node()),
      sim_(config, ranks), directory_(std::move(directory)), monitor_(monitor),
      outputs_(directory_, body_count(sim_) > 0)
{
}

template <int Dim>
RunResult Driver<Dim>::start(bool overwrite)
{
    // A forced rerun removes the old run's outputs: its checkpoints for a later --restart to
    // find, its summary.json and frames that the new run would not replace.
    if (is_writer()) {
        prepare_run_directory(directory_, overwrite);
        write_file_atomically(directory_ / "case.toml", config_.as_run);
        outputs_.create();
        if (outputs_.has_bodies()) {
            outputs_.append_particles(sim_);
        }
    }
    report_start(config_, monitor_, ranks_.size(), ranks_on_node_);
    report_derived_values(config_, monitor_);
    outputs_.write_frame(sim_);
    record_.next_particle_time = config_.output.particle_interval;
    record_.next_field_time = config_.output.field_interval;
    record_.next_checkpoint_time = config_.checkpoint.time_interval;
    return step_to_end();
}

template <int Dim>
double Driver<Dim>::wall_seconds() const
{
    return wall_seconds_before_ + Seconds(std::chrono::steady_clock::now() - loop_start_).count();
}

template <int Dim>
RunResult Driver<Dim>::step_to_end()
{
    monitor_.loop_started(sim_.clock().step, sim_.clock().time);
    wall_seconds_before_ = record_.wall_seconds;
    loop_start_ = std::chrono::steady_clock::now();
    std::string failure;
    bool is_finished = false;
    int signal = 0;
    try {
        do {
            const StepReport report = sim_.advance();
            record_.last = report;
            record_.total_outer_iterations += report.outer_iterations;
            const Clock& clock = sim_.clock();
            if (is_writer()) {
                outputs_.append_step(clock, report, record_.total_outer_iterations, wall_seconds());
            }
            watch_step(report, clock, config_, record_, monitor_);
            warn_of_wall_ring();
            if (report.retries > 0 && ++retried_steps_ <= max_reported_retries) {
                monitor_.message(fmt::format(
                    "warning: step {} (t = {:g} s) taken again {} time(s), kept at Δt = {:.3g} s; "
                    "the last failure: {}{}",
                    clock.step, clock.time, report.retries, clock.dt, sim_.last_retry_note(),
                    retried_steps_ == max_reported_retries ? "; further ones only in solver.csv"
                                                           : ""));
            }
            monitor_.step_done(clock.step, clock.time, report.outer_iterations);
            write_scheduled_outputs();
            is_finished = sim_.is_finished(report);
            // Every rank stops at the step where any was asked to (the writer's terminal).
            signal = is_finished ? 0
                                 : static_cast<int>(ranks_.max(
                                       static_cast<double>(monitor_.pending_interrupt())));
            // The last step's checkpoint follows the end-of-run outputs (below).
            if (!is_finished && (take_due_checkpoint(clock, config_.checkpoint.step_interval,
                                                     config_.checkpoint.time_interval,
                                                     record_.next_checkpoint_time) ||
                                 signal != 0)) {
                write_checkpoint_now(outputs_.n_frames());
            }
        } while (!is_finished && signal == 0);
    } catch (const NumericalError& e) {
        failure =
            fmt::format("step {}, t = {:g} s, in {}: {}", e.step(), e.time(), e.where(), e.what());
    }
    monitor_.loop_ended();
    record_.wall_seconds = wall_seconds();
    return end_run(failure, signal);
}

template <int Dim>
RunResult Driver<Dim>::end_run(const std::string& failure, int signal)
{
    const Clock& clock = sim_.clock();
    // Every rank ends here: the others' memory for rank 0's summary.json (collective).
    other_ranks_peak_mib_ = ranks_.max(is_writer() ? 0.0 : peak_memory_mib());
    if (!failure.empty()) {
        // The simulation is back at the end of the last good step (Simulation::advance): its
        // fields and samples close the outputs, and its checkpoint lets the run go on from
        // there, with a smaller Δt say.
        close_outputs("failed: " + failure);
        monitor_.message(fmt::format(
            "fddem: numerical failure at {}\n  the outputs up to the last good step (step {}, "
            "t = {:.6g} s) are in {},\n  with a checkpoint of that state, {}; continue from it "
            "with: fddem run --restart {} --set time.dt=...",
            failure, clock.step, clock.time, directory_.string(), last_checkpoint_.string(),
            directory_.string()));
        return {RunResult::Outcome::numerical_failure, 0};
    }
    if (signal != 0) {
        if (is_writer()) {
            write_summary(
                fmt::format("interrupted by {} at step {}", signal_name(signal), clock.step));
        }
        monitor_.message(fmt::format(
            "fddem: interrupted by {}: stopped after step {} (t = {:.6g} s) with a checkpoint, "
            "{}\n  continue with: fddem run --restart {}",
            signal_name(signal), clock.step, clock.time, last_checkpoint_.string(),
            directory_.string()));
        return {RunResult::Outcome::interrupted, signal};
    }
    // Its checkpoint lets `fddem run --restart DIR --set time.end=…` extend a finished run.
    close_outputs("completed");
    monitor_.message(completion_message());
    return {RunResult::Outcome::completed, 0};
}

template <int Dim>
void Driver<Dim>::write_scheduled_outputs()
{
    const Clock& clock = sim_.clock();
    if (outputs_.has_bodies() &&
        take_due_output(clock, config_.output.particle_interval, record_.next_particle_time) &&
        is_writer()) {
        outputs_.append_particles(sim_);
    }
    // output.field_interval = 0: no frames between the first and the last.
    if (config_.output.field_interval > 0.0 &&
        take_due_output(clock, config_.output.field_interval, record_.next_field_time)) {
        outputs_.write_frame(sim_);
    }
}

template <int Dim>
std::string Driver<Dim>::completion_message() const
{
    const auto rest = sim_.at_rest_since();
    const std::string settled =
        rest && config_.time.rest_speed
            ? fmt::format(" (every free body slower than time.rest_speed = {:g} since t = {:g} s)",
                          *config_.time.rest_speed, *rest)
            : std::string();
    if (config_.time.is_steady) {
        return fmt::format("fddem: {}: {} pseudo-time steps to t = {:.6g} s, {} outer iterations; "
                           "{}; {:.2f} s; results in {}",
                           config_.source_file, sim_.clock().step, sim_.clock().time,
                           record_.total_outer_iterations, steady_march_verdict(),
                           record_.wall_seconds, directory_.string());
    }
    // The run's warnings name at most the first unconverged steps; the last line says how many
    // there were, so that a run whose steps broke down does not read as a clean one.
    const std::string unconverged =
        record_.unconverged_steps > 0
            ? fmt::format(" ({} of the {} steps unconverged, largest Courant number {:.3g}; "
                          "solver.csv has every step)",
                          record_.unconverged_steps, sim_.clock().step, record_.max_courant)
            : std::string();
    return fmt::format("fddem: {}: {} steps to t = {:.6g} s{}, {} outer iterations{}, {:.2f} s; "
                       "results in {}",
                       config_.source_file, sim_.clock().step, sim_.clock().time, settled,
                       record_.total_outer_iterations, unconverged, record_.wall_seconds,
                       directory_.string());
}

template <int Dim>
std::string Driver<Dim>::steady_march_verdict() const
{
    // What a pseudo-time march (time.steady) reached: the steady test of its last step, and
    // whether that step's outer iterations solved the equations to simple.tolerance (the steps
    // on the way need not: their count is only mentioned).
    const StepReport& last = record_.last;
    const double tolerance = config_.time.steady_tolerance.value_or(0.0);
    const bool is_steady = sim_.clock().step > 1 && last.rate_of_change < tolerance;
    std::string verdict =
        is_steady ? fmt::format("steady: max|∂u/∂t| L/U² = {:.2e}, below time.steady_tolerance = "
                                "{:g}",
                                last.rate_of_change, tolerance)
                  : fmt::format("warning: NOT steady: max|∂u/∂t| L/U² = {:.2e} at the end, "
                                "time.steady_tolerance = {:g} (raise time.end or time.max_steps)",
                                last.rate_of_change, tolerance);
    if (!last.is_converged) {
        const bool is_projection = last.momentum_rounds > 0; // not a step near a contact
        verdict +=
            fmt::format("; warning: the last step's {} did not converge "
                        "(mass residual {:.2e}, momentum residual {:.2e}, simple.tolerance "
                        "{:g}): raise simple.max_outer_iterations",
                        is_projection ? "momentum predictor" : "outer iterations",
                        last.mass_residual, last.momentum_residual, config_.simple.tolerance);
    } else {
        verdict += fmt::format(" (last step: mass residual {:.2e}, momentum residual {:.2e})",
                               last.mass_residual, last.momentum_residual);
    }
    const long earlier = record_.unconverged_steps - (last.is_converged ? 0 : 1);
    if (earlier > 0) {
        verdict += fmt::format("; {} of the earlier steps ended at simple.max_outer_iterations, "
                               "as steps far from steady may",
                               earlier);
    }
    return verdict;
}

template <int Dim>
void Driver<Dim>::close_outputs(const std::string& status)
{
    // A closing field frame off the output schedule is left out of the checkpoint's frames:
    // a continued run drops it and writes its frames on the schedule.
    const std::size_t n_frames = outputs_.n_frames();
    // Rank 0 alone holds the frames' list; a split frame is written by every rank.
    const bool has_frame =
        ranks_.max(is_writer() && outputs_.has_frame_at(sim_.clock().time) ? 1.0 : 0.0) > 0.0;
    if (!has_frame) {
        outputs_.write_frame(sim_);
    }
    write_line_samples(sim_, config_.output.lines, directory_); // collective; rank 0 writes
    if (is_writer()) {
        write_summary(status);
    }
    write_checkpoint_now(n_frames);
}

template <int Dim>
void Driver<Dim>::write_checkpoint_now(std::size_t n_frames)
{
    // Every rank writes its piece (io/checkpoint.hpp), rank 0 the checkpoint's file with the
    // record and then prunes; rank 0's copy of every body's markers is what gets written.
    sim_.share_marker_state();
    last_checkpoint_ = checkpoint_path(directory_, sim_.clock().step);
    if (is_writer()) {
        outputs_.record_lengths(record_, n_frames);
        record_.wall_seconds = wall_seconds();
    }
    std::error_code exists; // another rank may be making it at the same moment
    fs::create_directories(checkpoint_directory(directory_), exists);
    write_checkpoint(last_checkpoint_, sim_, record_);
    if (is_writer()) {
        prune_checkpoints(directory_, config_.checkpoint.keep);
    }
}

template <int Dim>
void Driver<Dim>::warn_of_wall_ring()
{
    if (has_warned_wall_ring_) {
        return;
    }
    const MacGrid<Dim>& grid = sim_.grid();
    if (const auto text =
            wall_ring_warning<Dim>(sim_.bodies(), grid.domain(), sim_.boundary_conditions(),
                                   grid.spacing(), config_.coupling, sim_.clock().time)) {
        has_warned_wall_ring_ = true;
        monitor_.message(*text);
    }
}

template <int Dim>
void Driver<Dim>::write_summary(const std::string& status) const
{
    // Rank 0's phase times and communication, the other ranks' memory.
    const RankCosts costs{ranks_.size(), other_ranks_peak_mib_,
                          sim_.grid().communicator().traffic(), sim_.phase_times().communication};
    write_run_summary(sim_, config_, record_, status, directory_ / "summary.json", costs);
}

template class Driver<2>;
template class Driver<3>;

} // namespace fddem
