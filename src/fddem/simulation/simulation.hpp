// SPDX-License-Identifier: MIT
#pragma once
/// Simulation<Dim> owns everything of one run and advances it one time step at a time.

#include "fddem/bodies/particles.hpp"
#include "fddem/contact/dem_step.hpp"
#include "fddem/core/phase_timer.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/simulation/case_config.hpp"
#include "fddem/simulation/outer_iterations.hpp"
#include "fddem/simulation/step_report.hpp"
#include "fddem/simulation/time_step_control.hpp"

#include <optional>
#include <string>

namespace fddem {

/// Time and step counters.
struct Clock {
    double time = 0.0; ///< [s]
    long step = 0;
    double dt = 0.0;          ///< [s]
    double previous_dt = 0.0; ///< Δt of the last step taken [s]; 0 before the first (BDF2's ω)
};

/// The contacts of a run with free bodies and a contact model (eq. (18)).
template <int Dim>
struct ContactSetup {
    DemSettings settings;
    bool is_paper_coupling = false; ///< contact.coupling = "paper"
    CellList<Dim> cells;            ///< the broad phase of the DEM's neighbour list
    DemWalls<Dim> walls;
};

template <int Dim>
class Simulation {
public:
    /// Builds the run from a checked case. Throws InputError if the case's dimension is not Dim.
    /// On `ranks` (more than one process: the grid split over them, make_grid).
    explicit Simulation(const CaseConfig& config, const Communicator& ranks = Communicator::self());
    // Its stages hold references to its members.
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;
    Simulation(Simulation&&) = delete;
    Simulation& operator=(Simulation&&) = delete;
    ~Simulation() = default;

    /// One implicit-Euler (or BDF2) time step: DEM sub-steps (18), SIMPLE outer iterations (7)–(16)
    /// to convergence, the move (17). Throws NumericalError if the step blows up (a non-finite
    /// residual, a body leaving the box); the simulation is then back in the state it had before
    /// the step, exactly, so that it can be checkpointed and continued (with a smaller Δt, say).
    /// With time.max_courant, a step that blows up or crosses a time.retry_* limit is first
    /// taken again from its start at half its Δt, up to time.max_retries times (the report's
    /// `retries`; last_retry_note() says why).
    StepReport advance();
    /// Why the last step was retried (the last failure, in words), empty if it was not.
    [[nodiscard]] const std::string& last_retry_note() const noexcept { return retry_note_; }
    /// When a step is retried: the case's time.max_retries and time.retry_* keys, with the
    /// Courant limit's default (retry_courant_limit) filled in.
    [[nodiscard]] const RetrySettings& retry_settings() const noexcept { return retry_; }
    /// time.min_dt, or its default share of time.dt [s]: with time.max_courant, the adaptive
    /// Δt below which the run stops.
    [[nodiscard]] double shortest_step() const noexcept;

    /// The one place Δt [s] is set: adopts it for the next step, with everything derived from
    /// it (the momentum multigrid's cycles, the DEM's sub-step count N_i; a reused momentum
    /// assembly is dropped). With time.max_courant or time.steady, advance() sets it itself.
    void set_time_step(double dt);

    /// True when the end time or the step limit is reached, or (not before time.min_end) the
    /// flow is steady or every free body has settled (time.rest_speed).
    [[nodiscard]] bool is_finished(const StepReport& last) const;
    /// The time from which every free body has been slower than time.rest_speed, if it is now.
    [[nodiscard]] std::optional<double> at_rest_since() const
    {
        return rest_since_ >= 0.0 ? std::optional<double>(rest_since_) : std::nullopt;
    }

    [[nodiscard]] const MacGrid<Dim>& grid() const noexcept { return grid_; }
    [[nodiscard]] const BoundaryConditions<Dim>& boundary_conditions() const noexcept
    {
        return bc_;
    }
    [[nodiscard]] const FluidState<Dim>& fluid() const noexcept { return state_; }
    /// Mutable access (initial conditions, forcing in tests). Call before the first step, or
    /// call invalidate_assembly() after changing anything between steps.
    [[nodiscard]] FluidState<Dim>& fluid() noexcept
    {
        outer_.is_reusable_assembly() = false;
        return state_;
    }
    /// Forces a full momentum assembly at the start of the next step.
    void invalidate_assembly() noexcept { outer_.is_reusable_assembly() = false; }
    [[nodiscard]] const FluidProperties& fluid_properties() const noexcept { return properties_; }
    [[nodiscard]] const Clock& clock() const noexcept { return clock_; }
    /// The bodies, one record each (bodies/particle.hpp), in the order of their ids.
    [[nodiscard]] const Particles<Dim>& bodies() const noexcept { return bodies_; }
    [[nodiscard]] Particles<Dim>& bodies() noexcept { return bodies_; }
    /// Seconds spent so far in each phase of the steps (summary.json).
    [[nodiscard]] const PhaseTimes& phase_times() const noexcept { return times_; }
    [[nodiscard]] const CaseConfig& config() const noexcept { return config_; }
    /// The persistent contact state (tangential springs and per-contact constants of the open
    /// contacts).
    [[nodiscard]] const ContactHistory<Dim>& contact_history() const noexcept
    {
        return contact_history_;
    }
    [[nodiscard]] const PoissonSolver<Dim>& pressure_solver() const noexcept
    {
        return outer_.pressure_solver();
    }
    [[nodiscard]] const MomentumSettings& momentum_settings() const noexcept
    {
        return outer_.momentum_settings();
    }

    /// Sets a uniform force per unit volume on the fluid [N/m³] (e.g. to drive a channel).
    void set_uniform_body_force(const Vec<Dim>& force);

    /// Makes every rank's copy of the bodies' marker arrays (I(u), λ, λ*) the same. On a split
    /// grid with coupling.body_sweep = "simultaneous" only the owner of a body holds them whole
    /// (coupling/marker_routes.hpp); call this, on every rank, before save_state writes rank
    /// 0's copy. Changes nothing any rank computes with. Nothing to do otherwise.
    void share_marker_state();

    /// Writes everything the next steps depend on (io/checkpoint.hpp): see visit_state.
    template <class Archive>
    void save_state(Archive& archive) const
    {
        visit_state(*this, archive);
    }
    /// Reads what save_state wrote into a Simulation built from the same case (the grid and
    /// the bodies' markers must match; io/checkpoint checks that first and names what differs),
    /// after which advance() continues bit for bit as the saving run would have. A time.dt
    /// changed since is adopted (the momentum systems are then reassembled).
    template <class Archive>
    void load_state(Archive& archive)
    {
        visit_state(*this, archive);
        finish_load();
    }

private:
    /// The state, one `archive(name, member)` per member in one fixed order, for writing (Self
    /// const) and reading alike: a new member is one more line here (and a format version
    /// bump in io/checkpoint.hpp). Work arrays that a step rewrites before reading them are
    /// included where cheap, so that no stale value can make a continued run differ. Not here:
    /// what the constructor rebuilds from the case (grid, markers in the body frame, solvers,
    /// DEM settings) and per-step scratch (the cell list).
    template <class Self, class Archive>
    static void visit_state(Self& self, Archive& archive)
    {
        archive("clock.step", self.clock_.step);
        archive("clock.time", self.clock_.time);
        archive("clock.dt", self.clock_.dt);
        archive("clock.previous_dt", self.clock_.previous_dt);
        archive("fluid.u", self.state_.u);
        archive("fluid.u_n", self.state_.u_n);
        archive("fluid.p", self.state_.p);
        archive("fluid.p_corr", self.state_.p_corr); // hypre's initial guess (warm start)
        archive("fluid.body_force", self.state_.body_force);
        archive("fluid.divergence", self.state_.divergence);
        archive("fluid.previous_level", self.state_.u_nm1);
        archive("uniform_force", self.uniform_force_);
        auto& outer = self.outer_;
        archive("is_reusable_assembly", outer.is_reusable_assembly());
        for (auto& system : outer.systems()) {
            archive("momentum.a_p", system.a_p);
            archive("momentum.a_nb", system.a_nb);
            archive("momentum.b", system.b);
            archive("momentum.u_old", system.u_old);
        }
        std::size_t n_bodies = self.bodies_.size();
        archive("bodies", n_bodies);
        check_body_count(n_bodies, self.bodies_.size());
        for (auto& body : self.bodies_) {
            archive("body.centre", body.centre);
            if constexpr (Dim == 2) {
                archive("body.angle", body.orientation);
            } else {
                archive("body.orientation", body.orientation.coeffs()); // x, y, z, w
            }
            archive("body.velocity", body.velocity);
            archive("body.omega", body.omega);
            archive("body.force", body.force);
            archive("body.torque", body.torque);
            auto& c = body.coupling;
            archive("coupling.offsets", c.offsets);
            archive("coupling.positions", c.positions);
            archive("coupling.fluid", c.fluid);
            archive("coupling.lambda", c.lambda);
            archive("coupling.lambda_star", c.lambda_star);
            archive("coupling.velocity_n", body.velocity_n);
            archive("coupling.omega_n", body.omega_n);
            archive("coupling.velocity_nm1", body.velocity_nm1);
            archive("coupling.omega_nm1", body.omega_nm1);
            auto& dem = body.contact;
            archive("contact.force", dem.mean_force);
            archive("contact.torque", dem.mean_torque);
            archive("contact.is_in_contact", dem.is_in_contact);
            archive("contact.dem_centre", dem.centre);
            archive("contact.dem_velocity", dem.velocity);
            archive("contact.dem_omega", dem.omega);
        }
        archive("contact.tangential_springs", self.contact_history_.springs);
        archive("contact.pair_coefficients", self.contact_history_.coefficients);
        archive("contact.rebounds", self.contact_history_.rebounds);
        archive("rest_since", self.rest_since_);
        archive("time_step.residual", self.step_history_.residual);
        archive("time_step.previous_residual", self.step_history_.previous_residual);
        archive("time_step.is_converged", self.step_history_.is_converged);
        archive("seconds.coupling", self.times_.seconds[static_cast<std::size_t>(Phase::coupling)]);
        archive("seconds.contact", self.times_.seconds[static_cast<std::size_t>(Phase::contact)]);
        archive("seconds.momentum", self.times_.seconds[static_cast<std::size_t>(Phase::momentum)]);
        archive("seconds.pressure", self.times_.seconds[static_cast<std::size_t>(Phase::pressure)]);
        if constexpr (Archive::is_reading) {
            std::string plans;
            archive("pressure.plans", plans);
            outer.pressure_solver().restore_plans(plans);
        } else {
            archive("pressure.plans", outer.pressure_solver().plan_record());
        }
    }
    static void check_body_count(std::size_t stored, std::size_t bodies);
    /// After load_state: the marker arrays fit the markers; the case's Δt is adopted.
    void finish_load();

    // The stages of advance(), in its order.
    StepReport advance_unguarded();
    /// Frees the prescribed bodies whose bodies.release_time has come (at the start of a
    /// step, before its Δt is chosen: a released body's buoyant weight counts in it).
    void release_bodies();
    /// The earliest release time still ahead, on which the controlled step lands.
    [[nodiscard]] std::optional<double> next_release() const;
    /// Δt of the next step by time.max_courant or time.steady (time_step_control.hpp).
    void choose_time_step();
    /// Keeps the level-n state: u^{n−1} ← u^n ← u, U^{n−1} ← U^n ← U, ω^{n−1} ← ω^n ← ω
    /// (λ* = λ^n already); with coupling.inner_fluid = "volume" also each free body's ∫_P u^n
    /// (eqs. (13')–(14'), coupling/inner_fluid.hpp).
    void begin_step();
    /// eq. (18): the DEM sub-steps over the whole step, from the level-n state, with the
    /// buoyant weight held over them.
    void resolve_contacts(StepReport& report);
    /// The Courant number and rate of change of the step just iterated.
    void measure_step(StepReport& report) const;
    /// eq. (17) and what follows from it: hydrodynamic forces for output, the bodies moved,
    /// their markers placed and the body force spread for the next step.
    void move_bodies_and_markers(const TimeLevels& levels);
    /// Whether the bodies' eqs. (13)–(15) are evaluated by their owners alone (a split grid
    /// and the simultaneous sweep: coupling/marker_routes.hpp).
    [[nodiscard]] bool is_owner_split() const noexcept;
    /// Tracks rest_since_ after a step (time.rest_speed).
    void track_rest();

    /// Undoes a step that threw or is to be retried: the state of the step's start (except
    /// per-step scratch and u^{n−2}, which only a reused assembly needs; the next step
    /// reassembles, and its begin_step() sets u^{n−1} again from u^n), its clock and Δt
    /// included.
    void roll_back_step();
    /// Whether a step of `dt` [s] that failed after `retries` retries is taken again.
    [[nodiscard]] bool may_retry_step(int retries, double dt) const noexcept;

    CaseConfig config_;
    MacGrid<Dim> grid_;
    BoundaryConditions<Dim> bc_;
    FluidProperties properties_;
    FluidState<Dim> state_;
    Clock clock_;
    double length_scale_; ///< smallest box side [m], for the steady-state measure
    Particles<Dim> bodies_;
    AnyKernel kernel_;
    Vec<Dim> gravity_ = Vec<Dim>::Zero();
    Vec<Dim> uniform_force_ = Vec<Dim>::Zero();
    std::optional<ContactSetup<Dim>> contacts_; ///< none: no collisions
    /// The tangential springs and per-contact constants of the open contacts, kept across time
    /// steps (checkpointed).
    ContactHistory<Dim> contact_history_;
    OuterIterations<Dim> outer_;
    PhaseTimes times_;
    TimeStepSettings step_control_;
    TimeStepHistory step_history_;
    double rest_since_ = -1.0; ///< see at_rest_since() [s]; negative: some body is moving

    /// What a failed step must be able to give back (roll_back_step). u^n and u^{n−1} are
    /// not here: the step keeps them in state_.u_n and state_.u_nm1 anyway.
    struct StepStart {
        GridArray<Dim> p;
        GridArray<Dim> p_corr;
        Particles<Dim> bodies;
        ContactHistory<Dim> contacts;
        Clock clock;
        TimeStepHistory history;
        double rest_since = -1.0;
    };
    StepStart step_start_;
    RetrySettings retry_; ///< time.max_retries, time.retry_*
    /// The longest Δt the step being retried may take (half the failed attempt's) [s].
    std::optional<double> retry_dt_;
    double attempt_dt_ = 0.0;    ///< Δt of the step being taken; 0 before choose_time_step
    bool is_step_begun_ = false; ///< begin_step() has moved u^n and u^{n−1} on for this step
    std::string retry_note_;     ///< why the last step was retried, empty if it was not
};

} // namespace fddem
