// SPDX-License-Identifier: MIT
// `fddem run`: read and check the case, build the simulation, prepare the run directory (in that
// order, so bad input writes nothing), then step to the end writing the outputs.

#include "fddem/core/errors.hpp"
#include "fddem/grid/sampling.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/build_info.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/csv_history.hpp"
#include "fddem/io/run_directory.hpp"
#include "fddem/io/summary.hpp"
#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "commands.hpp"
#include "progress.hpp"

namespace fddem::app {
namespace {

namespace fs = std::filesystem;
using Seconds = std::chrono::duration<double>;

/// Courant number above which a step is reported (implicit Euler is stable beyond it, but the
/// SIMPLE iterations and the time accuracy degrade).
constexpr double courant_warning = 2.0;
/// Not-converged steps reported one by one before only the count goes on.
constexpr long max_reported_unconverged = 10;

fs::path default_run_directory(const RunOptions& options, const CaseConfig& config)
{
    if (!options.output_directory.empty()) {
        return options.output_directory;
    }
    if (!config.output_directory.empty()) {
        return config.output_directory;
    }
    const fs::path file(options.case_file);
    // cases/<…>/<name>/case.toml runs into runs/<name>.
    const std::string stem = file.stem() == "case" && file.has_parent_path()
                                 ? fs::absolute(file).parent_path().filename().string()
                                 : file.stem().string();
    return fs::path("runs") / stem;
}

template <int Dim>
class Run {
public:
    Run(const CaseConfig& config, fs::path directory, const RunOptions& options)
        : config_(config), sim_(config), directory_(std::move(directory)),
          progress_(stderr, !options.quiet && ::isatty(STDERR_FILENO) != 0,
                    options.quiet ? std::numeric_limits<long>::max() : config.log_interval,
                    config.end_time),
          pvd_(directory_ / "fields.pvd"), particles_pvd_(directory_ / "particles.pvd")
    {
    }

    int execute(bool force)
    {
        prepare_run_directory(directory_, force);
        write_file_atomically(directory_ / "case.toml", config_.as_run);
        CsvHistory solver(directory_ / "solver.csv",
                          {"step", "time", "dt", "outer_iterations", "total_outer_iterations",
                           "is_converged", "mass_residual", "momentum_residual", "courant",
                           "rate_of_change", "wall_seconds"});
        if (!sim_.bodies().empty()) {
            particles_ =
                std::make_unique<CsvHistory>(directory_ / "particles.csv", particle_columns());
            write_particles();
        }
        report_derived();
        const auto start = std::chrono::steady_clock::now();
        write_fields();
        double next_particle_time = config_.particle_interval;
        double next_field_time = config_.field_interval;
        StepReport report;
        int status = exit_success;
        std::string failure;
        try {
            do {
                report = sim_.advance();
                total_outer_ += report.outer_iterations;
                const double wall = Seconds(std::chrono::steady_clock::now() - start).count();
                const Clock& clock = sim_.clock();
                solver.append({static_cast<double>(clock.step), clock.time, clock.dt,
                               static_cast<double>(report.outer_iterations),
                               static_cast<double>(total_outer_), report.is_converged ? 1.0 : 0.0,
                               report.mass_residual, report.momentum_residual, report.courant,
                               report.rate_of_change, wall});
                watch(report);
                progress_.update(clock.step, clock.time, report.outer_iterations);
                if (particles_ && clock.time >= next_particle_time - 0.5 * clock.dt) {
                    write_particles();
                    next_particle_time += config_.particle_interval;
                }
                if (config_.field_interval > 0.0 &&
                    clock.time >= next_field_time - 0.5 * clock.dt) {
                    write_fields();
                    next_field_time += config_.field_interval;
                }
            } while (!sim_.is_finished(report));
        } catch (const NumericalError& e) {
            failure = fmt::format("step {}, t = {:g} s, in {}: {}", e.step(), e.time(), e.where(),
                                  e.what());
            status = exit_numerical_failure;
        }
        const double stepping = Seconds(std::chrono::steady_clock::now() - start).count();
        progress_.finish();
        if (status == exit_success) {
            if (pvd_.entries().empty() || pvd_.entries().back().first < sim_.clock().time) {
                write_fields();
            }
            write_samples();
        }
        write_summary(stepping, report,
                      status == exit_success ? "completed" : "failed: " + failure);
        if (status != exit_success) {
            std::fprintf(stderr,
                         "fddem: numerical failure at %s\n  outputs up to the last step "
                         "are in %s\n",
                         failure.c_str(), directory_.c_str());
            return status;
        }
        std::fprintf(stderr,
                     "fddem: %s: %ld steps to t = %.6g s, %ld outer iterations, %.2f s; results "
                     "in %s\n",
                     config_.source_file.c_str(), sim_.clock().step, sim_.clock().time,
                     total_outer_, stepping, directory_.c_str());
        return exit_success;
    }

private:
    static std::vector<std::string> particle_columns()
    {
        if constexpr (Dim == 2) {
            return {"time",  "id", "x",  "y",      "u",          "v",          "omega",
                    "theta", "fx", "fy", "torque", "contact_fx", "contact_fy", "contact_torque"};
        } else {
            return {"time",     "id",       "x",          "y",          "z",
                    "u",        "v",        "w",          "omega_x",    "omega_y",
                    "omega_z",  "fx",       "fy",         "fz",         "torque_x",
                    "torque_y", "torque_z", "contact_fx", "contact_fy", "contact_fz"};
        }
    }

    void write_particles()
    {
        for (std::size_t k = 0; k < sim_.bodies().size(); ++k) {
            const RigidBody<Dim>& b = sim_.bodies()[k];
            const BodyCoupling<Dim>& coupling = sim_.couplings()[k];
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
                     {b.omega, b.angle, b.force[0], b.force[1], b.torque, coupling.contact_force[0],
                      coupling.contact_force[1], coupling.contact_torque}) {
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
                    row.push_back(coupling.contact_force[d]);
                }
            }
            particles_->append(row);
        }
    }

    /// Says what [nondimensional] made of the case (the values are also in case.toml).
    void report_derived()
    {
        if (config_.contact_impact_velocity > 0.0) {
            progress_.message(fmt::format(
                "fddem: contact ({}, {} coupling): a wall collision of the lightest body at "
                "impact speed {:.3g} lasts {:.3g} s (undamped) with restitution {:.4g}; {} DEM "
                "sub-steps per time step",
                config_.contact_model, config_.contact_coupling, config_.contact_impact_velocity,
                config_.contact_duration, config_.contact_restitution, config_.contact_substeps));
        }
        if (config_.contact_stiffness > 0.0) {
            progress_.message(fmt::format(
                "fddem: contact ({} coupling): k = {:.6g}, c = {:.6g}; a wall collision of the "
                "lightest body lasts {:.3g} s with restitution {:.4g}; {} DEM sub-steps per "
                "time step",
                config_.contact_coupling, config_.contact_stiffness, config_.contact_damping,
                config_.contact_duration, config_.contact_restitution, config_.contact_substeps));
        }
        if (!config_.reynolds) {
            return;
        }
        std::string text =
            fmt::format("fddem: derived from [nondimensional] (Re = {:g}", *config_.reynolds);
        if (config_.density_ratio) {
            text += fmt::format(", density ratio {:g}, W/D = {:g}): viscosity {:.6g}, body "
                                "density {:.6g}, gravity {:.6g}, wall factor K = {:.6f}",
                                *config_.density_ratio,
                                config_.size[0] / config_.bodies.front().diameter,
                                config_.viscosity, config_.bodies.front().density,
                                -config_.gravity[1], config_.wall_factor);
        } else {
            text += fmt::format("): viscosity {:.6g}", config_.viscosity);
        }
        progress_.message(text);
    }

    void watch(const StepReport& report)
    {
        if (report.max_relative_overlap > max_relative_overlap_) {
            max_overlap_ = report.max_overlap;
            max_relative_overlap_ = report.max_relative_overlap;
            max_overlap_time_ = sim_.clock().time;
            if (max_relative_overlap_ > overlap_warning && !has_warned_overlap_) {
                has_warned_overlap_ = true;
                progress_.message(fmt::format(
                    "warning: t = {:g} s: contact overlap {:.3g} is {:.1f} % of the radius "
                    "(above {:g} %); stiffen the contact (contact.stiffness or a shorter "
                    "contact.duration)",
                    sim_.clock().time, max_overlap_, 100.0 * max_relative_overlap_,
                    100.0 * overlap_warning));
            }
        }
        if (!report.is_converged) {
            ++n_unconverged_;
            if (n_unconverged_ <= max_reported_unconverged) {
                progress_.message(fmt::format(
                    "warning: step {} (t = {:g} s): SIMPLE not converged in {} outer iterations "
                    "(mass residual {:.2e}, momentum residual {:.2e}, tolerance {:g}){}",
                    sim_.clock().step, sim_.clock().time, report.outer_iterations,
                    report.mass_residual, report.momentum_residual, config_.tolerance,
                    n_unconverged_ == max_reported_unconverged ? "; further ones only counted"
                                                               : ""));
            }
        }
        if (report.courant > courant_warning && !has_warned_courant_) {
            has_warned_courant_ = true;
            progress_.message(fmt::format("warning: step {}: Courant number {:.2f} > {:g}; "
                                          "consider a smaller time.dt",
                                          sim_.clock().step, report.courant, courant_warning));
        }
        max_courant_ = std::max(max_courant_, report.courant);
    }

    void write_fields()
    {
        const std::size_t frame = pvd_.entries().size();
        const std::string name = fmt::format("fields/fields_{:06d}.vtr", frame);
        write_vtr(directory_ / name, sim_.grid(), sim_.fluid().u, sim_.fluid().p);
        pvd_.add(sim_.clock().time, name);
        if (sim_.bodies().empty()) {
            return;
        }
        std::vector<std::array<double, 3>> centres;
        std::vector<double> radii;
        std::vector<std::array<double, 3>> velocities;
        std::vector<std::array<double, 3>> spins;
        for (const RigidBody<Dim>& b : sim_.bodies()) {
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
        std::filesystem::create_directories(directory_ / "particles");
        write_vtp(directory_ / particles, centres, radii, velocities, spins);
        particles_pvd_.add(sim_.clock().time, particles);
    }

    void write_samples()
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
        for (const LineSample& line : config_.lines) {
            Vec<Dim> from;
            Vec<Dim> to;
            for (int d = 0; d < Dim; ++d) {
                from[d] = line.from[static_cast<std::size_t>(d)];
                to[d] = line.to[static_cast<std::size_t>(d)];
            }
            write_csv(
                directory_ / "samples" / (line.name + ".csv"), columns,
                sample_line(sim_.grid(), sim_.fluid().u, sim_.fluid().p, from, to, line.n_points));
        }
    }

    void write_summary(double stepping, const StepReport& last, const std::string& status)
    {
        RunSummary summary;
        summary.set("status", status);
        summary.set("steps", sim_.clock().step);
        summary.set("time", sim_.clock().time);
        summary.set("total_outer_iterations", total_outer_);
        summary.set("unconverged_steps", n_unconverged_);
        summary.set("max_courant", max_courant_);
        summary.set("last_mass_residual", last.mass_residual);
        summary.set("last_momentum_residual", last.momentum_residual);
        summary.set("last_rate_of_change", last.rate_of_change);
        summary.set("cells", static_cast<long>(sim_.grid().n_cells()));
        summary.set("pressure_solver", sim_.pressure_solver().name());
        summary.set("wall_seconds_stepping", stepping);
        summary.set("peak_memory_mib", peak_memory_mib());
        for (const auto& [name, value] : build_info()) {
            summary.set("build_" + name, value);
        }
        summary.set_phase_seconds("momentum", sim_.momentum_seconds());
        summary.set_phase_seconds("pressure", sim_.pressure_seconds());
        summary.set_phase_seconds("coupling", sim_.coupling_seconds());
        summary.set_phase_seconds("contact", sim_.contact_seconds());
        summary.set_phase_seconds("other", stepping - sim_.momentum_seconds() -
                                               sim_.pressure_seconds() - sim_.coupling_seconds() -
                                               sim_.contact_seconds());
        if (!config_.bodies.empty()) {
            summary.set("bodies", static_cast<long>(config_.bodies.size()));
            summary.set("markers_per_body",
                        static_cast<long>(sim_.couplings().front().markers.size()));
            summary.set("last_rigid_defect", last.rigid_defect);
            summary.set("contact_model", config_.contact_model);
            summary.set("max_overlap", max_overlap_);
            summary.set("max_relative_overlap", max_relative_overlap_);
            summary.set("max_overlap_time", max_overlap_time_);
            if (config_.reynolds) {
                summary.set("characteristic_velocity", config_.characteristic_velocity);
                summary.set("characteristic_time",
                            config_.bodies.front().diameter / config_.characteristic_velocity);
            }
        }
        summary.write(directory_ / "summary.json");
    }

    CaseConfig config_;
    Simulation<Dim> sim_;
    fs::path directory_;
    Progress progress_;
    PvdCollection pvd_;
    PvdCollection particles_pvd_;
    std::unique_ptr<CsvHistory> particles_;
    long total_outer_ = 0;
    static constexpr double overlap_warning = 0.05; ///< relative overlap that gets a warning
    double max_overlap_ = 0.0;
    double max_relative_overlap_ = 0.0;
    double max_overlap_time_ = 0.0;
    bool has_warned_overlap_ = false;
    long n_unconverged_ = 0;
    double max_courant_ = 0.0;
    bool has_warned_courant_ = false;
};

} // namespace

int run_command(const RunOptions& options)
{
    const CaseConfig config = read_case(options.case_file, options.overrides);
    const fs::path directory = default_run_directory(options, config);
    if (config.dimension == 2) {
        Run<2> run(config, directory, options);
        return run.execute(options.force);
    }
    Run<3> run(config, directory, options);
    return run.execute(options.force);
}

} // namespace fddem::app
