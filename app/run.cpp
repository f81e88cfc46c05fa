// SPDX-License-Identifier: MIT
// A run from its start: the run directory, the initial outputs, the time loop with its outputs
// and checkpoints, and the end of the run (also the end of a restarted run).

#include "run.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/sampling.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/build_info.hpp"
#include "fddem/io/case_names.hpp"
#include "fddem/io/checkpoint.hpp"
#include "fddem/io/run_directory.hpp"
#include "fddem/io/summary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <utility>

#include "interrupt.hpp"

namespace fddem::app {
namespace {

namespace fs = std::filesystem;
using Seconds = std::chrono::duration<double>;

/// Courant number above which a step is reported (implicit Euler is stable beyond it, but the
/// SIMPLE iterations and the time accuracy degrade).
constexpr double courant_warning = 2.0;
/// Not-converged steps reported one by one before only the count goes on.
constexpr long max_reported_unconverged = 10;
/// Relative contact overlap that gets a warning.
constexpr double overlap_warning = 0.05;

} // namespace

template <int Dim>
Run<Dim>::Run(const CaseConfig& config, fs::path directory, const RunOptions& options)
    : config_(config), sim_(config), directory_(std::move(directory)),
      progress_(stderr, !options.quiet && ::isatty(STDERR_FILENO) != 0,
                options.quiet ? std::numeric_limits<long>::max() : config.output.log_interval,
                config.time.end),
      pvd_(directory_ / "fields.pvd"), particles_pvd_(directory_ / "particles.pvd")
{
}

template <int Dim>
std::vector<std::string> Run<Dim>::solver_columns()
{
    return {"step",
            "time",
            "dt",
            "outer_iterations",
            "total_outer_iterations",
            "is_converged",
            "mass_residual",
            "momentum_residual",
            "courant",
            "rate_of_change",
            "wall_seconds"};
}

template <int Dim>
std::vector<std::string> Run<Dim>::particle_columns()
{
    if constexpr (Dim == 2) {
        return {"time",  "id", "x",  "y",      "u",          "v",          "omega",
                "theta", "fx", "fy", "torque", "contact_fx", "contact_fy", "contact_torque"};
    } else {
        return {"time",     "id",       "x",        "y",          "z",          "u",         "v",
                "w",        "omega_x",  "omega_y",  "omega_z",    "fx",         "fy",        "fz",
                "torque_x", "torque_y", "torque_z", "contact_fx", "contact_fy", "contact_fz"};
    }
}

template <int Dim>
int Run<Dim>::start(bool force)
{
    prepare_run_directory(directory_, force);
    // A forced rerun must not leave the old run's checkpoints for a later --restart to find.
    for (const CheckpointEntry& old : list_checkpoints(directory_)) {
        fs::remove(old.path);
    }
    write_file_atomically(directory_ / "case.toml", config_.as_run);
    solver_ = std::make_unique<CsvHistory>(directory_ / "solver.csv", solver_columns());
    if (!sim_.bodies().empty()) {
        particles_ = std::make_unique<CsvHistory>(directory_ / "particles.csv", particle_columns());
        write_particles();
    }
    report_derived();
    write_fields();
    record_.next_particle_time = config_.output.particle_interval;
    record_.next_field_time = config_.output.field_interval;
    record_.next_checkpoint_time = config_.checkpoint.time_interval;
    return step_to_end();
}

template <int Dim>
double Run<Dim>::wall_seconds() const
{
    return wall_seconds_before_ + Seconds(std::chrono::steady_clock::now() - loop_start_).count();
}

template <int Dim>
int Run<Dim>::step_to_end()
{
    install_interrupt_handlers();
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
            solver_->append({static_cast<double>(clock.step), clock.time, clock.dt,
                             static_cast<double>(report.outer_iterations),
                             static_cast<double>(record_.total_outer_iterations),
                             report.is_converged ? 1.0 : 0.0, report.mass_residual,
                             report.momentum_residual, report.courant, report.rate_of_change,
                             wall_seconds()});
            watch(report);
            progress_.update(clock.step, clock.time, report.outer_iterations);
            if (particles_ && clock.time >= record_.next_particle_time - 0.5 * clock.dt) {
                write_particles();
                record_.next_particle_time += config_.output.particle_interval;
            }
            if (config_.output.field_interval > 0.0 &&
                clock.time >= record_.next_field_time - 0.5 * clock.dt) {
                write_fields();
                record_.next_field_time += config_.output.field_interval;
            }
            is_finished = sim_.is_finished(report);
            signal = is_finished ? 0 : pending_interrupt();
            // The last step's checkpoint follows the end-of-run outputs (below).
            if (!is_finished && (is_checkpoint_due() || signal != 0)) {
                write_checkpoint_now(pvd_.entries().size());
            }
        } while (!is_finished && signal == 0);
    } catch (const NumericalError& e) {
        failure =
            fmt::format("step {}, t = {:g} s, in {}: {}", e.step(), e.time(), e.where(), e.what());
    }
    progress_.finish();
    record_.wall_seconds = wall_seconds();
    if (!failure.empty()) {
        // The simulation is back at the end of the last good step (Simulation::advance): its
        // fields and samples close the outputs, and its checkpoint lets the run go on from
        // there, with a smaller Δt say.
        const Clock& clock = sim_.clock();
        close_outputs("failed: " + failure);
        std::fprintf(stderr,
                     "fddem: numerical failure at %s\n  the outputs up to the last good step "
                     "(step %ld, t = %.6g s) are in %s,\n  with a checkpoint of that state, "
                     "%s; continue from it with: fddem run --restart %s --set time.dt=...\n",
                     failure.c_str(), clock.step, clock.time, directory_.c_str(),
                     last_checkpoint_.c_str(), directory_.c_str());
        return exit_numerical_failure;
    }
    if (signal != 0) {
        write_summary(
            fmt::format("interrupted by {} at step {}", signal_name(signal), sim_.clock().step));
        std::fprintf(stderr,
                     "fddem: interrupted by %s: stopped after step %ld (t = %.6g s) with a "
                     "checkpoint, %s\n  continue with: fddem run --restart %s\n",
                     signal_name(signal), sim_.clock().step, sim_.clock().time,
                     last_checkpoint_.c_str(), directory_.c_str());
        return exit_interrupted_base + signal;
    }
    // Its checkpoint lets `fddem run --restart DIR --set time.end=…` extend a finished run.
    close_outputs("completed");
    const auto rest = sim_.at_rest_since();
    const std::string settled =
        rest && config_.time.rest_speed
            ? fmt::format(" (every free body slower than time.rest_speed = {:g} since t = {:g} s)",
                          *config_.time.rest_speed, *rest)
            : std::string();
    std::fprintf(stderr,
                 "fddem: %s: %ld steps to t = %.6g s%s, %ld outer iterations, %.2f s; results "
                 "in %s\n",
                 config_.source_file.c_str(), sim_.clock().step, sim_.clock().time, settled.c_str(),
                 record_.total_outer_iterations, record_.wall_seconds, directory_.c_str());
    return exit_success;
}

template <int Dim>
void Run<Dim>::close_outputs(const std::string& status)
{
    // A closing field frame off the output schedule is left out of the checkpoint's frames:
    // a continued run drops it and writes its frames on the schedule.
    const std::size_t n_frames = pvd_.entries().size();
    if (pvd_.entries().empty() || pvd_.entries().back().first < sim_.clock().time) {
        write_fields();
    }
    write_samples();
    write_summary(status);
    write_checkpoint_now(n_frames);
}

template <int Dim>
bool Run<Dim>::is_checkpoint_due()
{
    const Clock& clock = sim_.clock();
    const long every = config_.checkpoint.step_interval;
    bool is_due = every > 0 && clock.step % every == 0;
    const double interval = config_.checkpoint.time_interval;
    if (interval > 0.0 && clock.time >= record_.next_checkpoint_time - 0.5 * clock.dt) {
        is_due = true;
        while (record_.next_checkpoint_time < clock.time + 0.5 * clock.dt) {
            record_.next_checkpoint_time += interval;
        }
    }
    return is_due;
}

template <int Dim>
void Run<Dim>::write_checkpoint_now(std::size_t n_frames)
{
    const auto frames = [n_frames](const PvdCollection& pvd) {
        const auto& all = pvd.entries();
        return std::vector<std::pair<double, std::string>>(
            all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(n_frames, all.size())));
    };
    record_.field_frames = frames(pvd_);
    record_.particle_frames = frames(particles_pvd_);
    // The histories reach the disk before a checkpoint that records their lengths does.
    solver_->sync();
    record_.solver_csv_bytes = solver_->size();
    if (particles_) {
        particles_->sync();
        record_.particles_csv_bytes = particles_->size();
    }
    record_.wall_seconds = wall_seconds();
    fs::create_directories(checkpoint_directory(directory_));
    last_checkpoint_ = checkpoint_path(directory_, sim_.clock().step);
    write_checkpoint(last_checkpoint_, sim_, record_);
    prune_checkpoints(directory_, config_.checkpoint.keep);
}

template <int Dim>
void Run<Dim>::write_particles()
{
    for (std::size_t k = 0; k < sim_.bodies().size(); ++k) {
        const Particle<Dim>& b = sim_.bodies()[k];
        std::vector<double> row;
        row.reserve(particle_columns().size());
        row.push_back(sim_.clock().time);
        row.push_back(static_cast<double>(b.id));
        for (int d = 0; d < Dim; ++d) {
            row.push_back(b.centre[d]);
        }
        for (int d = 0; d < Dim; ++d) {
            row.push_back(b.velocity[d]);
        }
        if constexpr (Dim == 2) {
            for (const double x :
                 {b.omega, b.angle, b.force[0], b.force[1], b.torque, b.contact.mean_force[0],
                  b.contact.mean_force[1], b.contact.mean_torque}) {
                row.push_back(x);
            }
        } else {
            for (int d = 0; d < 3; ++d) {
                row.push_back(b.omega[d]);
            }
            for (int d = 0; d < 3; ++d) {
                row.push_back(b.force[d]);
            }
            for (int d = 0; d < 3; ++d) {
                row.push_back(b.torque[d]);
            }
            for (int d = 0; d < 3; ++d) {
                row.push_back(b.contact.mean_force[d]);
            }
        }
        particles_->append(row);
    }
}

/// Says what [nondimensional] made of the case (the values are also in case.toml).
template <int Dim>
void Run<Dim>::report_derived()
{
    const ContactConfig& contact = config_.contact;
    const ContactDerived& derived = contact.derived;
    if (derived.impact_velocity > 0.0) {
        progress_.message(fmt::format(
            "fddem: contact ({}, {} coupling): a wall collision of the lightest body at "
            "impact speed {:.3g} lasts {:.3g} s (undamped) with restitution {:.4g}; {} DEM "
            "sub-steps per time step",
            name_of(contact.model), name_of(contact.coupling), derived.impact_velocity,
            derived.duration, derived.restitution, derived.substeps));
    }
    if (derived.stiffness > 0.0) {
        progress_.message(fmt::format(
            "fddem: contact ({} coupling): k = {:.6g}, c = {:.6g}; a wall collision of the "
            "lightest body lasts {:.3g} s with restitution {:.4g}; {} DEM sub-steps per "
            "time step",
            name_of(contact.coupling), derived.stiffness, derived.damping, derived.duration,
            derived.restitution, derived.substeps));
    }
    const NondimensionalConfig& nondimensional = config_.nondimensional;
    if (!nondimensional.reynolds) {
        return;
    }
    std::string text =
        fmt::format("fddem: derived from [nondimensional] (Re = {:g}", *nondimensional.reynolds);
    if (nondimensional.density_ratio) {
        text += fmt::format(", density ratio {:g}, W/D = {:g}): viscosity {:.6g}, body "
                            "density {:.6g}, gravity {:.6g}, wall factor K = {:.6f}",
                            *nondimensional.density_ratio,
                            config_.domain.size[0] / config_.bodies.front().diameter,
                            config_.fluid.viscosity, config_.bodies.front().density,
                            -config_.fluid.gravity[1], nondimensional.wall_factor);
    } else {
        text += fmt::format("): viscosity {:.6g}", config_.fluid.viscosity);
    }
    progress_.message(text);
}

template <int Dim>
void Run<Dim>::watch(const StepReport& report)
{
    RunRecord& r = record_;
    if (report.max_relative_overlap > r.max_relative_overlap) {
        r.max_overlap = report.max_overlap;
        r.max_relative_overlap = report.max_relative_overlap;
        r.max_overlap_time = sim_.clock().time;
        if (r.max_relative_overlap > overlap_warning && !r.has_warned_overlap) {
            r.has_warned_overlap = true;
            progress_.message(
                fmt::format("warning: t = {:g} s: contact overlap {:.3g} is {:.1f} % of the radius "
                            "(above {:g} %); stiffen the contact (contact.stiffness or a shorter "
                            "contact.duration)",
                            sim_.clock().time, r.max_overlap, 100.0 * r.max_relative_overlap,
                            100.0 * overlap_warning));
        }
    }
    if (!report.is_converged) {
        ++r.unconverged_steps;
        if (r.unconverged_steps <= max_reported_unconverged) {
            progress_.message(fmt::format(
                "warning: step {} (t = {:g} s): SIMPLE not converged in {} outer iterations "
                "(mass residual {:.2e}, momentum residual {:.2e}, tolerance {:g}){}",
                sim_.clock().step, sim_.clock().time, report.outer_iterations, report.mass_residual,
                report.momentum_residual, config_.simple.tolerance,
                r.unconverged_steps == max_reported_unconverged ? "; further ones only counted"
                                                                : ""));
        }
    }
    if (report.courant > courant_warning && !r.has_warned_courant) {
        r.has_warned_courant = true;
        progress_.message(fmt::format("warning: step {}: Courant number {:.2f} > {:g}; "
                                      "consider a smaller time.dt",
                                      sim_.clock().step, report.courant, courant_warning));
    }
    r.max_courant = std::max(r.max_courant, report.courant);
}

template <int Dim>
void Run<Dim>::write_fields()
{
    const std::size_t frame = pvd_.entries().size();
    const std::string name = fmt::format("fields/fields_{:06d}.vtr", frame);
    // Read-only access: the mutable fluid() would invalidate the reusable assembly and make
    // the results depend on when outputs are written (and a continued run differ).
    const FluidState<Dim>& fluid = std::as_const(sim_).fluid();
    write_vtr(directory_ / name, sim_.grid(), fluid.u, fluid.p);
    pvd_.add(sim_.clock().time, name);
    if (sim_.bodies().empty()) {
        return;
    }
    std::vector<std::array<double, 3>> centres;
    std::vector<double> radii;
    std::vector<std::array<double, 3>> velocities;
    std::vector<std::array<double, 3>> spins;
    for (const Particle<Dim>& b : sim_.bodies()) {
        std::array<double, 3> x{};
        std::array<double, 3> v{};
        std::array<double, 3> w{};
        for (int d = 0; d < Dim; ++d) {
            x[static_cast<std::size_t>(d)] = b.centre[d];
            v[static_cast<std::size_t>(d)] = b.velocity[d];
        }
        if constexpr (Dim == 2) {
            w[2] = b.omega;
        } else {
            w = {b.omega[0], b.omega[1], b.omega[2]};
        }
        centres.push_back(x);
        radii.push_back(b.shape.radius());
        velocities.push_back(v);
        spins.push_back(w);
    }
    const std::string particles = fmt::format("particles/particles_{:06d}.vtp", frame);
    fs::create_directories(directory_ / "particles");
    write_vtp(directory_ / particles, centres, radii, velocities, spins);
    particles_pvd_.add(sim_.clock().time, particles);
}

template <int Dim>
void Run<Dim>::write_samples()
{
    std::vector<std::string> columns;
    const char* axes[] = {"x", "y", "z"};
    const char* velocities[] = {"u", "v", "w"};
    for (int d = 0; d < Dim; ++d) {
        columns.emplace_back(axes[d]);
    }
    for (int d = 0; d < Dim; ++d) {
        columns.emplace_back(velocities[d]);
    }
    columns.emplace_back("p");
    for (const LineSample& line : config_.output.lines) {
        Vec<Dim> from;
        Vec<Dim> to;
        for (int d = 0; d < Dim; ++d) {
            from[d] = line.from[static_cast<std::size_t>(d)];
            to[d] = line.to[static_cast<std::size_t>(d)];
        }
        write_csv(directory_ / "samples" / (line.name + ".csv"), columns,
                  sample_line(sim_.grid(), std::as_const(sim_).fluid().u,
                              std::as_const(sim_).fluid().p, from, to, line.n_points));
    }
}

template <int Dim>
void Run<Dim>::write_summary(const std::string& status)
{
    const StepReport& last = record_.last;
    const double stepping = record_.wall_seconds;
    RunSummary summary;
    summary.set("status", status);
    summary.set("steps", sim_.clock().step);
    summary.set("time", sim_.clock().time);
    summary.set("total_outer_iterations", record_.total_outer_iterations);
    summary.set("unconverged_steps", record_.unconverged_steps);
    summary.set("max_courant", record_.max_courant);
    summary.set("last_mass_residual", last.mass_residual);
    summary.set("last_momentum_residual", last.momentum_residual);
    summary.set("last_rate_of_change", last.rate_of_change);
    summary.set("cells", static_cast<long>(sim_.grid().n_cells()));
    summary.set("pressure_solver", sim_.pressure_solver().name());
    const MomentumSettings& momentum = sim_.momentum_settings();
    summary.set("momentum_solver", momentum.cycles > 0
                                       ? fmt::format("multigrid ({} V-cycle(s) of {} sweeps)",
                                                     momentum.cycles, momentum.sweeps)
                                       : fmt::format("Gauss-Seidel ({} sweeps)", momentum.sweeps));
    summary.set("wall_seconds_stepping", stepping);
    summary.set("restarts", record_.restarts);
    summary.set("peak_memory_mib", peak_memory_mib());
    for (const auto& [name, value] : build_info()) {
        summary.set("build_" + name, value);
    }
    const PhaseTimes& times = sim_.phase_times();
    for (const Phase phase : {Phase::momentum, Phase::pressure, Phase::coupling, Phase::contact}) {
        summary.set_phase_seconds(std::string(phase_name(phase)), times[phase]);
    }
    summary.set_phase_seconds("other", stepping - times.total());
    if (!config_.bodies.empty()) {
        summary.set("bodies", static_cast<long>(config_.bodies.size()));
        summary.set("markers_per_body",
                    static_cast<long>(sim_.bodies().front().coupling.markers.size()));
        summary.set("last_rigid_defect", last.rigid_defect);
        summary.set("contact_model", name_of(config_.contact.model));
        summary.set("max_overlap", record_.max_overlap);
        summary.set("max_relative_overlap", record_.max_relative_overlap);
        summary.set("max_overlap_time", record_.max_overlap_time);
        if (const auto since = sim_.at_rest_since()) {
            summary.set("at_rest_since", *since); // every free body below time.rest_speed
        }
        if (config_.nondimensional.reynolds) {
            const double velocity = config_.nondimensional.velocity;
            summary.set("characteristic_velocity", velocity);
            summary.set("characteristic_time", config_.bodies.front().diameter / velocity);
        }
    }
    summary.write(directory_ / "summary.json");
}

template class Run<2>;
template class Run<3>;

} // namespace fddem::app
