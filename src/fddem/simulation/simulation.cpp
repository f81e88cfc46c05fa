// SPDX-License-Identifier: MIT
// The time step (DESIGN.md §1, STYLE.md §2): implicit Euler (or BDF2, time.scheme; the step's
// Δt_e and ũ^n from core/time_scheme.hpp); the DEM sub-steps of eq. (18),
// SIMPLE outer iterations for eqs. (7)–(16) (outer_iterations.hpp), and the move of eq. (17).

#include "fddem/simulation/simulation.hpp"

#include "fddem/bodies/kinematics.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/coupling/hydrodynamic_force.hpp"
#include "fddem/coupling/inner_fluid.hpp"
#include "fddem/coupling/lubrication_coupling.hpp"
#include "fddem/coupling/marker_placement.hpp"
#include "fddem/coupling/marker_routes.hpp"
#include "fddem/simulation/simulation_setup.hpp"
#include "fddem/simulation/step_diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace fddem {

template <int Dim>
Simulation<Dim>::Simulation(const CaseConfig& config, const Communicator& ranks)
    : config_(config), grid_(make_grid<Dim>(config, ranks)),
      bc_(make_boundary_conditions<Dim>(config)), properties_{config.fluid.density,
                                                              config.fluid.viscosity},
      state_(grid_),
      length_scale_(*std::min_element(config.domain.size.begin(), config.domain.size.end())),
      bodies_(make_particles<Dim>(config, grid_)), kernel_(make_kernel(config.coupling.kernel)),
      gravity_(vector_of<Dim>(config.fluid.gravity)),
      contacts_(make_contact_setup<Dim>(config, grid_, bc_, bodies_)),
      outer_(grid_, bc_, properties_, kernel_, config, gravity_,
             contacts_ && contacts_->is_paper_coupling),
      step_control_{config.time.dt, config.time.max_courant, config.time.is_steady, config.time.end,
                    config.time.is_steady ? 2.0 : 1.2},
      retry_{config.time.max_retries, config.time.retry_mass_residual,
             retry_courant_limit(config.time.retry_courant, config.time.max_courant)}
{
    clock_.dt = config.time.dt;
    times_.communication_clock = grid_.communicator().seconds_counter();
    place_markers<Dim>(bodies_.all(), grid_, kernel_, 0, 0.0, config.coupling.is_forcing_normalised,
                       is_owner_split());
    set_uniform_body_force(vector_of<Dim>(config.fluid.body_force));
    fill_velocity_ghosts(grid_, bc_, state_.u);
    fill_cell_ghosts(grid_, bc_, state_.p);
}

template <int Dim>
void Simulation<Dim>::set_time_step(double dt)
{
    clock_.dt = dt;
    outer_.set_time_step(dt);
    if (contacts_) {
        // N_i was derived for time.dt (io/case_reader): keep the sub-step Δt/N_i at most what
        // it was there. The small allowance keeps N_i itself at Δt = time.dt despite rounding.
        const double share = dt / config_.time.dt;
        contacts_->settings.substeps =
            std::max(1, static_cast<int>(std::ceil(
                            share * std::max(1, config_.contact.derived.substeps) - 1e-9)));
    }
}

template <int Dim>
void Simulation<Dim>::choose_time_step()
{
    // The fluid, the walls and inflow that drive it (a lid starts a cavity at rest), and the
    // bodies' rims, which a free body's buoyant weight speeds up within the step: a body at
    // rest would otherwise take the first step at time.dt whatever its weight (measured: a
    // disk of ρs/ρf = 100 fell 6 cells in it).
    const double h = grid_.spacing().minCoeff();
    double speed_per_cell =
        std::max(max_speed_per_cell(grid_, state_.u), std::abs(bc_.inflow.speed) / h);
    for (int d = 0; d < Dim; ++d) {
        for (int side = 0; side < 2; ++side) {
            speed_per_cell = std::max(speed_per_cell, bc_.wall(d, side).norm() / h);
        }
    }
    const double reach = config_.time.max_courant.value_or(1.0) * h; // [m] allowed per step
    for (const Particle<Dim>& body : bodies_) {
        const double s = body.velocity.norm() + magnitude<Dim>(body.omega) * body.radius();
        const double a = body.is_free()
                             ? std::abs(1.0 - properties_.density / body.density) * gravity_.norm()
                             : 0.0;
        // s Δt + a Δt²/2 = reach, solved without cancellation; Δt = reach/s when a = 0.
        const double root = s + std::sqrt(s * s + 2.0 * a * reach);
        if (root > 0.0) {
            speed_per_cell = std::max(speed_per_cell, reach / h / (2.0 * reach / root));
        }
    }
    const double min_dt = shortest_step();
    if (is_step_collapsed(step_control_, speed_per_cell, min_dt)) {
        throw NumericalError(
            clock_.step + 1, clock_.time, "the adaptive time step",
            fmt::format("time.max_courant asks for Δt = {:.3g} s, below time.min_dt = {:.3g} s: "
                        "a flow whose speed grows as Δt shrinks has diverged (if steps this "
                        "short are expected, lower time.min_dt)",
                        *step_control_.max_courant / speed_per_cell, min_dt));
    }
    double dt = next_time_step(step_control_, clock_.dt, clock_.time, speed_per_cell, step_history_,
                               next_release());
    if (retry_dt_) {
        dt = std::min(dt, *retry_dt_); // a retry: half the failed attempt's Δt, or less
    }
    set_time_step(dt);
}

template <int Dim>
void Simulation<Dim>::release_bodies()
{
    // A clock that landed on the release (or summed a whole number of fixed steps to it, which
    // the case reader requires) is within round-off of it.
    const double tolerance = 1e-9 * std::max(std::abs(clock_.time), clock_.dt);
    for (Particle<Dim>& body : bodies_) {
        if (body.release_due(clock_.time, tolerance)) {
            body.motion = Motion::free; // from the velocity it was prescribed
        }
    }
}

template <int Dim>
std::optional<double> Simulation<Dim>::next_release() const
{
    std::optional<double> next;
    for (const Particle<Dim>& body : bodies_) {
        if (body.motion == Motion::prescribed && body.release_time &&
            (!next || *body.release_time < *next)) {
            next = body.release_time;
        }
    }
    return next;
}

template <int Dim>
double Simulation<Dim>::shortest_step() const noexcept
{
    return config_.time.min_dt.value_or(collapsed_step_share * config_.time.dt);
}

template <int Dim>
bool Simulation<Dim>::may_retry_step(int retries, double dt) const noexcept
{
    return dt > 0.0 && may_retry(step_control_, retry_, retries, dt, shortest_step());
}

template <int Dim>
void Simulation<Dim>::set_uniform_body_force(const Vec<Dim>& force)
{
    outer_.is_reusable_assembly() = false;
    uniform_force_ = force;
    outer_.spread_body_force(bodies_, uniform_force_, state_);
}

template <int Dim>
StepReport Simulation<Dim>::advance()
{
    // One grid array and the (small) body state per step: cheap beside the step itself.
    step_start_.p = state_.p;
    step_start_.p_corr = state_.p_corr; // hypre's initial guess: a retry must start from it too
    step_start_.bodies = bodies_;
    step_start_.contacts = contact_history_;
    step_start_.clock = clock_;
    step_start_.history = step_history_;
    step_start_.rest_since = rest_since_;
    retry_note_.clear();
    retry_dt_.reset();
    for (int retries = 0;; ++retries) {
        attempt_dt_ = 0.0; // set once choose_time_step() has chosen (a collapse is not retried)
        is_step_begun_ = false;
        try {
            StepReport report = advance_unguarded();
            const std::string reason = retry_reason(retry_, report);
            if (reason.empty() || !may_retry_step(retries, attempt_dt_)) {
                report.retries = retries;
                return report; // kept; one still above a limit is reported as it is
            }
            retry_note_ = fmt::format("Δt = {:.3g} s: {}", attempt_dt_, reason);
            roll_back_step();
        } catch (const NumericalError& e) {
            roll_back_step();
            if (!may_retry_step(retries, attempt_dt_)) {
                throw;
            }
            retry_note_ = fmt::format("Δt = {:.3g} s: {} ({})", attempt_dt_, e.what(), e.where());
        }
        retry_dt_ = 0.5 * attempt_dt_;
    }
}

template <int Dim>
StepReport Simulation<Dim>::advance_unguarded()
{
    StepReport report;
    release_bodies(); // bodies.release_time (fddem's, not the paper's): prescribed until then
    if (config_.time.max_courant || config_.time.is_steady) {
        choose_time_step();
    }
    attempt_dt_ = clock_.dt;
    begin_step();
    is_step_begun_ = true; // u^n, U^n, ω^n kept (and u^{n−1}, …); λ* = λ^n already
    const TimeLevels levels = time_levels(config_.time.scheme, clock_.dt, clock_.previous_dt);
    if (contacts_) {
        const ScopedPhase timer(times_, Phase::contact);
        resolve_contacts(report); // eq. (18), over the whole step before the fluid (§2.3)
    }
    // eqs. (7)–(16): momentum, pressure correction, rigid bodies, marker forces, spreading.
    outer_.iterate({clock_.dt, levels, uniform_force_, clock_.step + 1, clock_.time + clock_.dt},
                   state_, bodies_, times_, report);
    measure_step(report);
    if (!std::isfinite(report.courant) || !std::isfinite(report.mass_residual)) {
        // The last outer iteration's projection can leave what the next one would have caught;
        // caught here, the step is retried (or the run stops) at this step, not the next.
        throw NumericalError(clock_.step + 1, clock_.time + clock_.dt, "the end of the step",
                             locate_non_finite(grid_, state_) + ": the flow has blown up");
    }
    if (contacts_ && config_.lubrication.is_implicit()) {
        // lubrication.coupling = "implicit" (fddem's, not the paper's): the film's force at the
        // motion eqs. (13)–(14) gave, as the lubrication force of each body they moved
        record_linked_lubrication<Dim>(bodies_.all(), contacts_->is_paper_coupling);
    }
    if (!bodies_.empty()) {
        move_bodies_and_markers(levels); // eq. (17)
    }
    clock_.time += clock_.dt;
    clock_.previous_dt = clock_.dt;
    ++clock_.step;
    step_history_.push(report.rate_of_change, report.is_converged);
    track_rest();
    return report;
}

template <int Dim>
void Simulation<Dim>::begin_step()
{
    for (int a = 0; a < Dim; ++a) {
        state_.u_nm1[a] = state_.u_n[a];
        state_.u_n[a] = state_.u[a];
    }
    for (Particle<Dim>& body : bodies_) {
        body.velocity_nm1 = body.velocity_n;
        body.omega_nm1 = body.omega_n;
        body.velocity_n = body.velocity;
        body.omega_n = body.omega;
    }
    if (config_.coupling.inner_fluid == InnerFluidSource::volume) {
        // eqs. (13')–(14') (coupling/inner_fluid.hpp): the fluid inside each free body at level
        // n, over the cells it covers at X^n, where the step's markers stay
        take_inner_fluid_of_free_bodies<Dim>(bodies_.all(), grid_, state_.u_n,
                                             &MarkerCoupling<Dim>::inner_fluid_n);
    }
}

template <int Dim>
void Simulation<Dim>::resolve_contacts(StepReport& report)
{
    // The buoyant weight (ρs − ρf) V g is held over the sub-steps, as in the paper's eq. (18).
    // Without lubrication (contact.fluid_force "auto" or "none") the last step's hydrodynamic
    // force is left out, as in the paper: it is mostly the fluid's
    // reaction to the body's own acceleration (added mass), and holding it over the next step
    // feeds back on a body resting on a wall (Fig. 5 case: the lagged force pushed the disk off
    // the floor again and again). With contact.fluid_force = "held", or "auto" (the default)
    // and the lubrication correction on (docs/method.md §5,
    // Coupling) the last step's resolved force and torque are held over the sub-steps in which
    // the body touches nothing, so that a body the DEM moves (within the margin or the
    // lubrication range) keeps the fluid's resistance, as resolved codes hold the fluid force
    // over their collision sub-steps; a body resting on a wall touches it and gets none, unless
    // contact.fluid_force = "always" (an enduring contact keeps the fluid's drag).
    // With lubrication.coupling = "implicit" the DEM takes a body in contact, within the margin
    // or leaving a collision within the range, and "auto" holds nothing (a light body beside
    // another blew up with the held force: docs/method.md §5, "Implicit coupling of the film").
    const bool is_implicit = config_.lubrication.is_implicit();
    const bool holds_fluid = held_fluid_force_applies(
        config_.contact.fluid_force, config_.lubrication.is_enabled && !is_implicit);
    for (Particle<Dim>& body : bodies_) {
        body.contact.steady_force = (body.density - properties_.density) * body.volume() * gravity_;
        body.contact.steady_torque = zero_angular<Dim>();
        body.contact.held_fluid_force = holds_fluid ? body.force : Vec<Dim>::Zero();
        body.contact.held_fluid_torque = holds_fluid ? body.torque : zero_angular<Dim>();
    }
    const DemOutcome outcome =
        advance_contacts<Dim>(bodies_.all(), contacts_->walls, contacts_->settings, clock_.dt,
                              contacts_->cells, contact_history_);
    if (is_implicit) {
        // the film on a body eqs. (13)–(14) move enters them implicitly, not as a mean force
        drop_substep_lubrication<Dim>(bodies_.all(), contacts_->is_paper_coupling);
    }
    report.max_overlap = outcome.max_overlap;
    report.max_relative_overlap = outcome.max_relative_overlap;
    report.contacts = outcome.n_contacts;
    report.unfinished_film_solves = outcome.n_unfinished_film_solves;
}

template <int Dim>
void Simulation<Dim>::measure_step(StepReport& report) const
{
    const double velocity_scale = reference_velocity(grid_, bc_, state_.u);
    const StepChange change = measure_change(grid_, state_, clock_.dt);
    report.courant = change.courant;
    // max |∂u/∂t| L / U_ref², divided in two steps: U_ref² may underflow for a fluid at rest.
    report.rate_of_change = change.largest_change == 0.0
                                ? 0.0
                                : (change.largest_change / velocity_scale) *
                                      (length_scale_ / (clock_.dt * velocity_scale));
}

template <int Dim>
void Simulation<Dim>::move_bodies_and_markers(const TimeLevels& levels)
{
    const double dt = clock_.dt;
    const bool is_inner_fluid_volume = config_.coupling.inner_fluid == InnerFluidSource::volume;
    if (is_inner_fluid_volume) {
        // The reported force's inner fluid at the step's end, every rank (before the owners
        // measure): the body's momentum balance of eqs. (13')–(14'), DEM-moved bodies too.
        take_inner_fluid_of_free_bodies<Dim>(bodies_.all(), grid_, state_.u,
                                             &MarkerCoupling<Dim>::inner_fluid);
    }
    std::vector<int> owners;
    std::vector<char> held_before; // the bodies whose markers this rank may hand over
    if (is_owner_split()) {
        // Only the owners hold every marker's λ: each measures its bodies, then shares them.
        const int me = grid_.communicator().rank();
        for (Particle<Dim>& body : bodies_) {
            held_before.push_back(holds_markers_of(grid_, body) ? 1 : 0);
            owners.push_back(owner_rank(grid_, body));
            if (owners.back() == me) {
                measure_hydrodynamic_forces<Dim>(std::span<Particle<Dim>>(&body, 1),
                                                 properties_.density, levels,
                                                 is_inner_fluid_volume);
            }
        }
        share_loads<Dim>(bodies_.all(), grid_);
    } else {
        measure_hydrodynamic_forces<Dim>(bodies_.all(), properties_.density, levels,
                                         is_inner_fluid_volume);
    }
    move_bodies<Dim>(bodies_.all(), dt, contacts_ && contacts_->is_paper_coupling); // eq. (17)
    wrap_centres<Dim>(bodies_.all(), grid_.domain()); // re-entering across periodic sides
    place_markers<Dim>(bodies_.all(), grid_, kernel_, clock_.step + 1, clock_.time + dt,
                       config_.coupling.is_forcing_normalised, is_owner_split(), held_before);
    if (is_owner_split()) {
        hand_over<Dim>(bodies_.all(), owners, grid_); // to new owners and holders
    }
    outer_.spread_body_force(bodies_, uniform_force_, state_);
}

template <int Dim>
bool Simulation<Dim>::is_owner_split() const noexcept
{
    return grid_.communicator().size() > 1 &&
           config_.coupling.body_sweep == BodySweep::simultaneous;
}

template <int Dim>
void Simulation<Dim>::share_marker_state()
{
    if (is_owner_split()) {
        // Each rank placed only the bodies it reads (place_markers): every body's arrays sized
        // and placed here, from the same state on every rank, for what a checkpoint writes.
        for (Particle<Dim>& body : bodies_) {
            body.coupling.allocate_arrays();
        }
        place_markers<Dim>(bodies_.all(), grid_, kernel_, clock_.step, clock_.time);
        share_markers<Dim>(bodies_.all(), grid_);
    }
}

template <int Dim>
void Simulation<Dim>::track_rest()
{
    if (!config_.time.rest_speed) {
        return;
    }
    // A body still to be released is not at rest, whatever its prescribed speed.
    const bool is_at_rest =
        std::all_of(bodies_.begin(), bodies_.end(), [&](const Particle<Dim>& body) {
            if (!body.is_free()) {
                return !body.moves_freely(); // fixed, or prescribed for good
            }
            return body.velocity.norm() + magnitude<Dim>(body.omega) * body.radius() <
                   *config_.time.rest_speed;
        });
    if (!is_at_rest) {
        rest_since_ = -1.0;
    } else if (rest_since_ < 0.0) {
        rest_since_ = clock_.time;
    }
}

template <int Dim>
void Simulation<Dim>::roll_back_step()
{
    if (is_step_begun_) {
        // begin_step() moved the levels on; a step stopped before it (its Δt collapsed, in
        // choose_time_step) has u, u^n and u^{n−1} as they were.
        for (int a = 0; a < Dim; ++a) {
            state_.u[a] = state_.u_n[a];     // begin_step() moved u^n here
            state_.u_n[a] = state_.u_nm1[a]; // and u^{n−1} here
        }
        is_step_begun_ = false;
    }
    state_.p = step_start_.p;
    state_.p_corr = step_start_.p_corr;
    state_.divergence.fill(0.0);
    bodies_ = step_start_.bodies;
    contact_history_ = step_start_.contacts;
    clock_ = step_start_.clock;
    step_history_ = step_start_.history;
    rest_since_ = step_start_.rest_since;
    set_time_step(clock_.dt); // the Δt the last good step took, and what derives from it
    outer_.is_reusable_assembly() = false;
    outer_.spread_body_force(bodies_, uniform_force_, state_); // the body force of the step's start
}

template <int Dim>
void Simulation<Dim>::check_body_count(std::size_t stored, std::size_t bodies)
{
    if (stored != bodies) {
        throw InputError("", 0, "bodies",
                         "the checkpoint holds " + std::to_string(stored) + " bodies, the case " +
                             std::to_string(bodies));
    }
}

template <int Dim>
void Simulation<Dim>::finish_load()
{
    for (Particle<Dim>& body : bodies_) {
        MarkerCoupling<Dim>& c = body.coupling;
        // Not in the checkpoint: derived from the orientation, as place_markers derives it. A
        // restarted 3D body kept its body-frame moment before, and its first step differed from
        // the saving run's (the 25-sphere pile: mass residual 0.13497 against 0.13516).
        c.fluid_second_moment = inertia_in_world<Dim>(body.orientation, c.body_second_moment);
        const std::size_t n = c.markers.size();
        for (const auto* values : {&c.offsets, &c.positions, &c.fluid, &c.lambda, &c.lambda_star}) {
            if (values->size() != n) {
                throw InputError("", 0, "bodies.n_rings",
                                 "the checkpoint's bodies have other markers than the case's");
            }
        }
    }
    if (config_.coupling.is_forcing_normalised) {
        set_forcing_gains<Dim>(bodies_.all(), grid_, kernel_); // from the offsets just read
    }
    if (config_.time.max_courant || config_.time.is_steady) {
        set_time_step(clock_.dt); // the controlled step continues from where it was
    } else if (clock_.dt != config_.time.dt) {
        set_time_step(config_.time.dt);
        outer_.is_reusable_assembly() = false; // its coefficients hold the old ρ ΔV / Δt
    }
}

template <int Dim>
bool Simulation<Dim>::is_finished(const StepReport& last) const
{
    if (clock_.step >= config_.time.max_steps) {
        return true;
    }
    if (config_.time.end && clock_.time >= *config_.time.end - 0.5 * clock_.dt) {
        return true;
    }
    if (clock_.time < config_.time.min_end - 0.5 * clock_.dt) {
        return false;
    }
    if (config_.time.rest_speed && rest_since_ >= 0.0 &&
        clock_.time - rest_since_ >= config_.time.rest_duration - 0.5 * clock_.dt) {
        return true;
    }
    return config_.time.steady_tolerance && clock_.step > 1 &&
           last.rate_of_change < *config_.time.steady_tolerance;
}

template class Simulation<2>;
template class Simulation<3>;

} // namespace fddem
