// SPDX-License-Identifier: MIT
#pragma once
/// Simulation<Dim> owns everything of one run and advances it one time step at a time.

#include "fddem/bodies/rigid_body.hpp"
#include "fddem/contact/dem_step.hpp"
#include "fddem/core/logger.hpp"
#include "fddem/coupling/body_coupling.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/fluid/momentum.hpp"
#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/linsolve/anderson_mixing.hpp"
#include "fddem/linsolve/poisson_solver.hpp"
#include "fddem/simulation/case_config.hpp"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fddem {

/// What one time step did.
struct StepReport {
    int outer_iterations = 0;
    bool is_converged = false;      ///< residuals below tolerance within the iteration limit
    double mass_residual = 0.0;     ///< max |∇·u*| h / U_ref of the last outer iteration
    double momentum_residual = 0.0; ///< max |r/a_P| / U_ref of the accepted iterate
    double courant = 0.0;           ///< max_d max |u_d| Δt / h_d after the step
    double rate_of_change = 0.0;    ///< max |u^{n+1} − u^n| / Δt · L / U_ref² (steady check)
    double rigid_defect = 0.0; ///< max |U + ω×r − I(u)| / U_ref over markers, last iteration
    double body_change = 0.0;  ///< max (|ΔU| + R|Δω|) / U_ref over bodies, last iteration
    double max_overlap = 0.0;  ///< largest contact overlap α in the DEM sub-steps [m]
    double max_relative_overlap = 0.0; ///< largest α / radius (of the smaller body)
    int contacts = 0;                  ///< contacts at the end of the DEM sub-steps
};

/// Time and step counters.
struct Clock {
    double time = 0.0; ///< [s]
    long step = 0;
    double dt = 0.0; ///< [s]
};

template <int Dim>
class Simulation {
public:
    /// Builds the run from a checked case. Throws InputError if the case's dimension is not Dim.
    explicit Simulation(const CaseConfig& config);

    /// One implicit-Euler time step: SIMPLE outer iterations (7)–(12) to convergence.
    /// Throws NumericalError if the step blows up (a non-finite residual, a body leaving the
    /// box); the simulation is then back in the state it had before the step, exactly, so
    /// that it can be checkpointed and continued (with a smaller Δt, say).
    StepReport advance();

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
        is_reusable_assembly_ = false;
        return state_;
    }
    /// Forces a full momentum assembly at the start of the next step.
    void invalidate_assembly() noexcept { is_reusable_assembly_ = false; }
    [[nodiscard]] const FluidProperties& fluid_properties() const noexcept { return properties_; }
    [[nodiscard]] const Clock& clock() const noexcept { return clock_; }
    [[nodiscard]] const std::vector<RigidBody<Dim>>& bodies() const noexcept { return bodies_; }
    [[nodiscard]] std::vector<RigidBody<Dim>>& bodies() noexcept { return bodies_; }
    [[nodiscard]] const std::vector<BodyCoupling<Dim>>& couplings() const noexcept
    {
        return couplings_;
    }
    /// Seconds spent so far in the fictitious-domain coupling (eqs. (13)–(16)).
    [[nodiscard]] double coupling_seconds() const noexcept { return coupling_seconds_; }
    /// Seconds spent so far in the DEM sub-steps (eq. (18)).
    [[nodiscard]] double contact_seconds() const noexcept { return contact_seconds_; }
    [[nodiscard]] const CaseConfig& config() const noexcept { return config_; }
    /// The persistent contact state (tangential springs of the open contacts).
    [[nodiscard]] const ContactHistory<Dim>& contact_history() const noexcept
    {
        return contact_history_;
    }
    [[nodiscard]] const PoissonSolver<Dim>& pressure_solver() const noexcept { return *poisson_; }
    [[nodiscard]] const MomentumSettings& momentum_settings() const noexcept
    {
        return momentum_settings_;
    }
    /// Seconds spent so far in the momentum and pressure stages.
    [[nodiscard]] double momentum_seconds() const noexcept { return momentum_seconds_; }
    [[nodiscard]] double pressure_seconds() const noexcept { return pressure_seconds_; }

    /// Sets a uniform force per unit volume on the fluid [N/m³] (e.g. to drive a channel).
    void set_uniform_body_force(const Vec<Dim>& force);

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
    /// DEM settings) and per-step scratch (dem_bodies_, the cell list).
    template <class Self, class Archive>
    static void visit_state(Self& self, Archive& archive)
    {
        archive("clock.step", self.clock_.step);
        archive("clock.time", self.clock_.time);
        archive("clock.dt", self.clock_.dt);
        archive("fluid.u", self.state_.u);
        archive("fluid.u_n", self.state_.u_n);
        archive("fluid.p", self.state_.p);
        archive("fluid.p_corr", self.state_.p_corr); // hypre's initial guess (warm start)
        archive("fluid.body_force", self.state_.body_force);
        archive("fluid.divergence", self.state_.divergence);
        archive("fluid.previous_level", self.previous_level_);
        archive("uniform_force", self.uniform_force_);
        archive("is_reusable_assembly", self.is_reusable_assembly_);
        for (auto& system : self.systems_) {
            archive("momentum.a_p", system.a_p);
            archive("momentum.a_nb", system.a_nb);
            archive("momentum.b", system.b);
            archive("momentum.u_old", system.u_old);
        }
        std::size_t n_bodies = self.bodies_.size();
        archive("bodies", n_bodies);
        check_body_count(n_bodies, self.bodies_.size());
        for (std::size_t b = 0; b < self.bodies_.size(); ++b) {
            auto& body = self.bodies_[b];
            archive("body.centre", body.centre);
            archive("body.angle", body.angle);
            archive("body.velocity", body.velocity);
            archive("body.omega", body.omega);
            archive("body.force", body.force);
            archive("body.torque", body.torque);
            auto& c = self.couplings_[b];
            archive("coupling.offsets", c.offsets);
            archive("coupling.positions", c.positions);
            archive("coupling.fluid", c.fluid);
            archive("coupling.lambda", c.lambda);
            archive("coupling.lambda_star", c.lambda_star);
            archive("coupling.velocity_n", c.velocity_n);
            archive("coupling.omega_n", c.omega_n);
            archive("contact.force", c.contact_force);
            archive("contact.torque", c.contact_torque);
            archive("contact.is_in_contact", c.is_in_contact);
            archive("contact.dem_centre", c.dem_centre);
            archive("contact.dem_velocity", c.dem_velocity);
            archive("contact.dem_omega", c.dem_omega);
        }
        archive("contact.tangential_springs", self.contact_history_.springs);
        archive("rest_since", self.rest_since_);
        archive("seconds.coupling", self.coupling_seconds_);
        archive("seconds.contact", self.contact_seconds_);
        archive("seconds.momentum", self.momentum_seconds_);
        archive("seconds.pressure", self.pressure_seconds_);
        if constexpr (Archive::is_reading) {
            std::string plans;
            archive("pressure.plans", plans);
            self.poisson_->restore_plans(plans);
        } else {
            archive("pressure.plans", self.poisson_->plan_record());
        }
    }
    static void check_body_count(std::size_t stored, std::size_t bodies);
    /// After load_state: the marker arrays fit the markers; the case's Δt is adopted.
    void finish_load();

    /// What a failed step must be able to give back (roll_back_step). u^n and u^{n−1} are
    /// not here: the step keeps them in state_.u_n and previous_level_ anyway.
    struct StepStart {
        GridArray<Dim> p;
        std::vector<RigidBody<Dim>> bodies;
        std::vector<BodyCoupling<Dim>> couplings;
        ContactHistory<Dim> contacts;
    };
    StepReport advance_unguarded();
    /// Undoes a step that threw: the state of the step's start (except per-step scratch and
    /// u^{n−2}, which only a reused assembly needs; the next step reassembles).
    void roll_back_step();
    /// Where the velocity first stops being finite, for the blow-up message.
    [[nodiscard]] std::string locate_non_finite_velocity() const;

    [[nodiscard]] double reference_velocity() const;
    /// Puts the markers on the bodies; a marker whose kernel leaves the storage is a blow-up
    /// of step `step` (ending at `time`).
    void place_markers(long step, double time);
    double update_bodies(double dt);
    void spread_marker_forces();
    void move_bodies(double dt);
    void resolve_contacts(double dt, StepReport& report);
    void advance_time_level_in_systems();
    /// Tracks rest_since_ after a step (time.rest_speed).
    void track_rest();
    /// The outer iterate as Anderson mixing sees it (docs/method.md §4): the bodies' U and ω
    /// (measured), then λ, u and p (carried along).
    void collect_iterate(std::vector<MixedSegment>& segments);
    /// After eqs. (13)–(16) of outer iteration k ≥ 3: the iterate becomes Anderson's x_{k+1}.
    void mix_iterate();

    CaseConfig config_;
    MacGrid<Dim> grid_;
    BoundaryConditions<Dim> bc_;
    FluidProperties properties_;
    MomentumSettings momentum_settings_;
    FluidState<Dim> state_;
    FaceField<Dim> previous_level_; ///< u^{n−1}, to move the assembled b to the new level
    /// The momentum systems were assembled about the current iterate with the same Δt and
    /// forcing (by the convergence check that ended the last step).
    bool is_reusable_assembly_ = false;
    std::vector<MomentumSystem<Dim>> systems_;
    std::unique_ptr<PoissonSolver<Dim>> poisson_;
    Clock clock_;
    double length_scale_; ///< smallest box side [m], for the steady-state measure
    std::vector<RigidBody<Dim>> bodies_;
    std::vector<BodyCoupling<Dim>> couplings_;
    AnyKernel kernel_;
    std::optional<DemSettings> dem_; ///< none: no collisions (contact.model = "none")
    bool is_paper_contact_ = false;  ///< contact.coupling = "paper"
    std::optional<CellList<Dim>> contact_cells_;
    DemWalls<Dim> walls_{};
    std::vector<DemBody<Dim>> dem_bodies_;
    /// The tangential springs of the open contacts, kept across time steps (to be checkpointed).
    ContactHistory<Dim> contact_history_;
    StepStart step_start_;
    Vec<Dim> gravity_ = Vec<Dim>::Zero();
    Vec<Dim> uniform_force_ = Vec<Dim>::Zero();
    double coupling_seconds_ = 0.0;
    double contact_seconds_ = 0.0;
    double momentum_seconds_ = 0.0;
    double pressure_seconds_ = 0.0;
    double rest_since_ = -1.0; ///< see at_rest_since() [s]; negative: some body is moving
    PressureUpdate pressure_update_;
    AndersonMixing mixing_; ///< of the outer iterate, reset every step
    std::vector<MixedSegment> iterate_;
};

} // namespace fddem
