// SPDX-License-Identifier: MIT
#include "fddem/run/run_messages.hpp"

#include "fddem/io/case_names.hpp"
#include "fddem/run/memory_estimate.hpp"
#include "fddem/run/thread_placement.hpp"

#include <fmt/format.h>

#include <algorithm>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

namespace fddem {
namespace {

/// Courant number above which a step is reported (implicit Euler is stable beyond it, but the
/// SIMPLE iterations and the time accuracy degrade).
constexpr double courant_warning = 2.0;
/// Not-converged steps reported one by one before only the count goes on.
constexpr long max_reported_unconverged = 10;
/// Relative contact overlap that gets a warning.
constexpr double overlap_warning = 0.05;

/// The end of both contact messages: what the lightest body's wall collision comes to.
std::string collision_text(const CaseConfig& config)
{
    return fmt::format("with restitution {:.4g}; {} DEM sub-steps per time step",
                       config.contact.derived.restitution, config.contact.derived.substeps);
}

/// Spheres finer than about 10 cells per diameter whose eq. (15) is the paper's: their forcing
/// operator has eigenvalues above 2 (2.6–2.9 at d/h = 12, 3.2 at 16), and a moving sphere then
/// diverges at small time steps (docs/method.md §4, "Finer than d = 8 h the sphere's forcing
/// overshoots").
void warn_of_overshooting_forcing(const CaseConfig& config, RunMonitor& monitor)
{
    if (config.coupling.is_forcing_normalised || config.domain.cells.empty()) {
        return;
    }
    double spacing = 0.0;
    for (std::size_t d = 0; d < std::min(config.domain.cells.size(), config.domain.size.size());
         ++d) {
        spacing = std::max(spacing, config.domain.size[d] / config.domain.cells[d]);
    }
    double finest = 0.0;
    for (const BodyConfig& body : config.bodies) {
        if (body.shape == BodyShape::sphere) {
            finest = std::max(finest, body.diameter / spacing);
        }
    }
    if (finest > 10.0) {
        monitor.message(fmt::format(
            "warning: spheres of {:.3g} cells per diameter with the paper's eq. (15): their "
            "forcing overshoots (the largest eigenvalue of I·D is 2.6-2.9 at d/h = 12, 3.2 at 16), "
            "and a moving sphere then diverges at small time steps; set "
            "coupling.normalised_forcing = true (docs/method.md §4, \"Finer than d = 8 h the "
            "sphere's forcing overshoots\")",
            finest));
    }
}

} // namespace

void report_start(const CaseConfig& config, RunMonitor& monitor, int n_ranks, int ranks_on_node)
{
    monitor.message(memory_message(config, run_memory_limit(config), n_ranks, ranks_on_node));
#ifdef FDDEM_HAVE_OPENMP
    const std::string placement = thread_placement_warning(omp_get_max_threads(), usable_cpus());
    if (!placement.empty()) {
        monitor.message(placement);
    }
#endif
}

void report_derived_values(const CaseConfig& config, RunMonitor& monitor)
{
    const ContactConfig& contact = config.contact;
    const ContactDerived& derived = contact.derived;
    if (derived.impact_velocity > 0.0) {
        monitor.message(fmt::format("fddem: contact ({}, {} coupling): a wall collision of the "
                                    "lightest body at impact speed {:.3g} lasts {:.3g} s "
                                    "(undamped) {}",
                                    name_of(contact.model), name_of(contact.coupling),
                                    derived.impact_velocity, derived.duration,
                                    collision_text(config)));
    }
    if (derived.stiffness > 0.0) {
        monitor.message(fmt::format("fddem: contact ({} coupling): k = {:.6g}, c = {:.6g}; a wall "
                                    "collision of the lightest body lasts {:.3g} s {}",
                                    name_of(contact.coupling), derived.stiffness, derived.damping,
                                    derived.duration, collision_text(config)));
    }
    if (derived.minimum_impact_velocity > 0.0) {
        monitor.message(fmt::format("fddem: contact (adaptive, {} coupling): every collision "
                                    "lasts {} time steps ({:.3g} s) {}; impacts slower than "
                                    "{:.3g} are given the constants of one at that speed",
                                    name_of(contact.coupling), contact.collision_steps,
                                    derived.duration, collision_text(config),
                                    derived.minimum_impact_velocity));
    }
    if (contact.fluid_force == ContactFluidForce::automatic && !config.bodies.empty() &&
        contact.model != ContactModelKind::none) {
        const LubricationConfig& lubrication = config.lubrication;
        monitor.message(
            lubrication.is_enabled && !lubrication.is_implicit()
                ? "fddem: contact.fluid_force auto -> held (lubrication on): a body the DEM "
                  "moves keeps the last step's resolved fluid force while it touches nothing"
            : lubrication.is_implicit()
                ? "fddem: contact.fluid_force auto -> none (lubrication implicit in eqs. "
                  "(13)-(14)): the DEM moves a body in contact, within the margin or leaving a "
                  "collision within the lubrication range by its buoyant weight, the contact "
                  "forces and the lubrication correction"
                : "fddem: contact.fluid_force auto -> none (lubrication off): the DEM moves a "
                  "body in contact by its buoyant weight and the contact forces, as the "
                  "paper");
    }
    const bool has_sphere =
        std::any_of(config.bodies.begin(), config.bodies.end(),
                    [](const BodyConfig& body) { return body.shape == BodyShape::sphere; });
    if (has_sphere && config.coupling.markers == MarkerLayout::paper) {
        monitor.message("warning: coupling.markers = \"paper\" on spheres: their drag is about "
                        "20 % low at d/h = 8 (the outer shell lies 0.7 h inside the surface), and "
                        "their forcing overshoots (the largest eigenvalue of a sphere's I·D is "
                        "2.8-3.7, above 2); the 3D cases use \"retracted\" (docs/method.md §4, "
                        "\"The marker layout in 3D\", \"The forcing operator\")");
    }
    if (has_sphere && config.coupling.markers == MarkerLayout::surface &&
        config.coupling.marker_spacing_ratio > 1.0) {
        // Measured (docs/method.md §4, "The fluid inside a body"): ten Cate's E4 sphere at
        // d/h 8.25 falls 6.1 % faster than Table 2 with the shell's markers 1.4 h apart and
        // 1.2 % faster with them h apart (hat kernel; measured with it only, so said of every
        // kernel: the wider ones reach further, and no run says how much they close the gaps).
        monitor.message(fmt::format(
            "warning: coupling.markers = \"surface\" on spheres with markers {:g} h apart: the "
            "shell leaks between them (a settling sphere 6 % fast at 1.4 h, 1.2 % at 1.0 h); "
            "surface markers are usually about h apart (Uhlmann 2005): set "
            "coupling.marker_spacing_ratio = 1.0",
            config.coupling.marker_spacing_ratio));
    }
    warn_of_overshooting_forcing(config, monitor);
    const NondimensionalConfig& nondimensional = config.nondimensional;
    if (!nondimensional.reynolds) {
        return;
    }
    std::string text =
        fmt::format("fddem: derived from [nondimensional] (Re = {:g}", *nondimensional.reynolds);
    if (nondimensional.density_ratio) {
        text += fmt::format(", density ratio {:g}, W/D = {:g}): viscosity {:.6g}, body "
                            "density {:.6g}, gravity {:.6g}, wall factor K = {:.6f}",
                            *nondimensional.density_ratio,
                            config.domain.size[0] / config.bodies.front().diameter,
                            config.fluid.viscosity, config.bodies.front().density,
                            -config.fluid.gravity[1], nondimensional.wall_factor);
    } else {
        text += fmt::format("): viscosity {:.6g}", config.fluid.viscosity);
    }
    monitor.message(text);
}

void watch_step(const StepReport& report, const Clock& clock, const CaseConfig& config,
                RunRecord& record, RunMonitor& monitor)
{
    if (report.max_relative_overlap > record.max_relative_overlap) {
        record.max_overlap = report.max_overlap;
        record.max_relative_overlap = report.max_relative_overlap;
        record.max_overlap_time = clock.time;
        if (record.max_relative_overlap > overlap_warning && !record.has_warned_overlap) {
            record.has_warned_overlap = true;
            // The adaptive model's overlap grows with the stretched duration N_c Δt.
            const char* remedy = config.contact.model == ContactModelKind::adaptive
                                     ? "shorten the collisions (contact.collision_steps or "
                                       "time.dt)"
                                     : "stiffen the contact (contact.stiffness or a shorter "
                                       "contact.duration)";
            monitor.message(fmt::format("warning: t = {:g} s: contact overlap {:.3g} is {:.1f} % "
                                        "of the radius (above {:g} %); {}",
                                        clock.time, record.max_overlap,
                                        100.0 * record.max_relative_overlap,
                                        100.0 * overlap_warning, remedy));
        }
    }
    // The joint film solve's iteration limits are safeguards (contact/film_solve.cpp): a solve
    // that stops at one is said once, with its step, and counted in summary.json.
    if (report.unfinished_film_solves > 0) {
        if (record.unfinished_film_solves == 0) {
            monitor.message(fmt::format(
                "warning: step {} (t = {:g} s): {} of the lubrication films' joint solves "
                "(lubrication.film_solve = \"joint\") stopped at an iteration limit before "
                "their tolerance; their last iterate is used. Further ones are counted in "
                "summary.json (unfinished_film_solves)",
                clock.step, clock.time, report.unfinished_film_solves));
        }
        record.unfinished_film_solves += report.unfinished_film_solves;
    }
    // A pseudo-time march to a steady state (time.steady) takes steps of growing Δt whose
    // outer iterations need not converge on the way: its Courant numbers and unconverged steps
    // are counted but not reported one by one; the last line says what the march reached.
    const bool is_pseudo_time = config.time.is_steady;
    if (!report.is_converged) {
        ++record.unconverged_steps;
        const char* const more = record.unconverged_steps == max_reported_unconverged
                                     ? "; further ones only counted"
                                     : "";
        const bool is_reported =
            !is_pseudo_time && record.unconverged_steps <= max_reported_unconverged;
        // A projection step (simple.algorithm; not one near a contact, which iterates).
        if (is_reported && report.momentum_rounds > 0) {
            monitor.message(fmt::format(
                "warning: step {} (t = {:g} s): the momentum predictor's residual {:.2e} is above "
                "simple.tolerance {:g} after {} round{} of its solve, simple.max_outer_iterations: "
                "raise it{}",
                clock.step, clock.time, report.momentum_residual, config.simple.tolerance,
                report.momentum_rounds, report.momentum_rounds == 1 ? "" : "s", more));
        } else if (is_reported) {
            monitor.message(fmt::format(
                "warning: step {} (t = {:g} s): SIMPLE not converged in {} outer iterations "
                "(mass residual {:.2e}, momentum residual {:.2e}, tolerance {:g}){}",
                clock.step, clock.time, report.outer_iterations, report.mass_residual,
                report.momentum_residual, config.simple.tolerance, more));
        }
    }
    if (!is_pseudo_time && report.courant > courant_warning && !record.has_warned_courant) {
        record.has_warned_courant = true;
        monitor.message(fmt::format("warning: step {}: Courant number {:.2f} > {:g}; "
                                    "consider a smaller time.dt",
                                    clock.step, report.courant, courant_warning));
    }
    record.max_courant = std::max(record.max_courant, report.courant);
}

} // namespace fddem
