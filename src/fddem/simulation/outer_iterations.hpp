// SPDX-License-Identifier: MIT
#pragma once
/// The SIMPLE outer iterations of one implicit-Euler (or BDF2) time step (paper §2.2–2.3), as
/// one unit:
///
///   repeat, k = 1, 2, …:
///     eqs. (7)–(8)   momentum coefficients about the latest iterate; stop if converged;
///                    else relax them → u*
///     eqs. (9)–(12)  pressure correction: p′, then p and u corrected
///     eqs. (13)–(14) rigid-body velocities U, ω                  ┐ coupling/rigid_update.hpp,
///     eq. (15)       marker forces λ                               │ with bodies only
///     eq. (16)       u ← u + Δt D(λ − λ*), λ* ← λ                 ┘
///                    Anderson mixing of the iterate (docs/method.md §4), from k = 3
///                    the body force ρf D(λ*) for the next iteration
///
/// With simple.algorithm = "projection" (fddem's, not the paper's; docs/method.md §1) a step
/// whose bodies are all clear of contact is instead, once (project):
///
///     u ← u^n + ω (u^n − u^{n−1})   the iterate the predictor is linearised about
///     eqs. (7)–(8)   momentum solved until its residual is below simple.tolerance → u*
///     eqs. (9)–(12)  pressure correction
///     eqs. (13)–(16) with bodies, one pass (before (9)–(12) with force_before_projection)
///
/// It owns what only the iterations use (the momentum systems, the pressure solver, the
/// mixing's history and per-step scratch, allocated once), so that no allocation happens inside
/// the loop.

#include "fddem/bodies/particles.hpp"
#include "fddem/core/phase_timer.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/coupling/rigid_update.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/fluid/momentum.hpp"
#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/linsolve/anderson_mixing.hpp"
#include "fddem/linsolve/poisson_solver.hpp"
#include "fddem/simulation/case_config.hpp"
#include "fddem/simulation/step_report.hpp"

#include <memory>
#include <vector>

namespace fddem {

/// What a step gives the iterations besides the fluid and the bodies.
template <int Dim>
struct StepInputs {
    double dt;                     ///< Δt [s]
    TimeLevels levels;             ///< the time derivative's Δt_e and ũ^n (time.scheme)
    const Vec<Dim>& uniform_force; ///< on the fluid [N/m³]
    long step;                     ///< the step being taken (for messages)
    double time;                   ///< its end time [s] (for messages)
};

template <int Dim>
class OuterIterations {
public:
    /// Borrows the grid, boundary conditions, fluid properties and kernel, which must outlive it.
    /// `is_paper_contact`: a free body in contact moves as the DEM says (contact.coupling).
    OuterIterations(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                    const FluidProperties& properties, const AnyKernel& kernel,
                    const CaseConfig& config, const Vec<Dim>& gravity, bool is_paper_contact);

    /// Adopts Δt [s] and what derives from it (the momentum multigrid's cycles).
    void set_time_step(double dt);

    /// Eqs. (7)–(16) to convergence (or the iteration limit); fills the report's residuals,
    /// iteration count and convergence flag. Throws NumericalError if the flow blows up.
    void iterate(const StepInputs<Dim>& in, FluidState<Dim>& state, Particles<Dim>& bodies,
                 PhaseTimes& times, StepReport& report);

    /// ρf D(λ) plus the uniform force, into state.body_force (eq. (4a)'s pseudo body force).
    void spread_body_force(const Particles<Dim>& bodies, const Vec<Dim>& uniform_force,
                           FluidState<Dim>& state) const;

    /// The momentum systems, for checkpoints (their b carries the time level).
    [[nodiscard]] std::vector<MomentumSystem<Dim>>& systems() noexcept { return systems_; }
    [[nodiscard]] const std::vector<MomentumSystem<Dim>>& systems() const noexcept
    {
        return systems_;
    }
    /// True if the systems were assembled about the current iterate with the same Δt and forcing
    /// (by the convergence test that ended the last step), so the next step may reuse them.
    /// Never with BDF2, whose b would need u^{n−2} to be moved to the new level.
    [[nodiscard]] bool& is_reusable_assembly() noexcept { return is_reusable_assembly_; }
    [[nodiscard]] const bool& is_reusable_assembly() const noexcept
    {
        return is_reusable_assembly_;
    }
    [[nodiscard]] PoissonSolver<Dim>& pressure_solver() noexcept { return *poisson_; }
    [[nodiscard]] const PoissonSolver<Dim>& pressure_solver() const noexcept { return *poisson_; }
    [[nodiscard]] const MomentumSettings& momentum_settings() const noexcept { return momentum_; }

private:
    /// eqs. (7)–(8): assembles the systems (or moves a reused assembly to the new level);
    /// returns the momentum residual max |r/a_P| [m/s] of the current iterate.
    double assemble(int k, const StepInputs<Dim>& in, const FluidState<Dim>& state);
    /// The step's convergence test, on the residuals and body change of the last iteration.
    [[nodiscard]] bool is_step_converged(bool has_bodies, const StepReport& report) const;
    /// simple.algorithm = "projection": one predictor, its momentum systems solved until their
    /// residual is below tolerance (at most max_outer_iterations rounds), one projection and,
    /// with bodies, one pass of eqs. (13)–(16).
    void project(const StepInputs<Dim>& in, FluidState<Dim>& state, Particles<Dim>& bodies,
                 PhaseTimes& times, StepReport& report);
    /// simple.algorithm = "projection": a free body is in contact, linked by a film, or within
    /// two kernel widths of a wall or another body in this step (which then takes SIMPLE's
    /// iterations).
    [[nodiscard]] bool is_any_body_near_contact(const Particles<Dim>& bodies) const;
    /// state.u ← u^n + ω (u^n − u^{n−1}) (ghosts filled), ω = in.levels.step_ratio; nothing at
    /// a run's first step.
    void extrapolate_start(const StepInputs<Dim>& in, FluidState<Dim>& state);
    /// Throws NumericalError if the momentum residual of outer iteration k is not finite.
    void check_finite(int k, const StepInputs<Dim>& in, const FluidState<Dim>& state,
                      const StepReport& report) const;
    /// Relaxes every component towards its system's solution → u*.
    void solve_momentum_systems(FluidState<Dim>& state, PhaseTimes& times);
    /// eqs. (9)–(12): p′ from ∇·u*, then p and u corrected; returns the mass residual
    /// max |∇·u*| h relative to `velocity_scale`.
    double correct_pressure(double dt, double velocity_scale, FluidState<Dim>& state,
                            PhaseTimes& times);
    /// eqs. (13)–(16) and the mixing; sets report.body_change and rigid_defect.
    void couple_bodies(int k, double velocity_scale, const StepInputs<Dim>& in,
                       FluidState<Dim>& state, Particles<Dim>& bodies, StepReport& report);
    /// The outer iterate as Anderson mixing sees it (docs/method.md §4): the bodies' U and ω
    /// (measured), then λ, u and p (carried along).
    void collect_iterate(FluidState<Dim>& state, Particles<Dim>& bodies);
    [[nodiscard]] bool is_mixed_iteration(int k) const noexcept;
    /// Outer iterations a step takes before its test may end it: simple.min_outer_iterations_dem
    /// with a free body the DEM moves, else 1.
    [[nodiscard]] int fewest_iterations(const Particles<Dim>& bodies) const;
    /// simple.hold_mass_residual: with bodies, the mass residual `now` of outer iteration k is
    /// no larger than the step's `start` one (or below simple.tolerance), or no smaller than the
    /// `previous` iteration's.
    [[nodiscard]] bool is_mass_residual_kept(bool has_bodies, int k, double start, double previous,
                                             double now) const;
    /// The boundary conditions spreading is folded back through (coupling.adjoint_at_walls),
    /// or null.
    [[nodiscard]] const BoundaryConditions<Dim>* adjoint_walls() const noexcept
    {
        return is_adjoint_at_walls_ ? &bc_ : nullptr;
    }

    const MacGrid<Dim>& grid_;
    const BoundaryConditions<Dim>& bc_;
    const FluidProperties& properties_;
    const AnyKernel& kernel_;
    double tolerance_;
    bool is_fluid_converged_with_bodies_;
    int min_iterations_dem_;     ///< simple.min_outer_iterations_dem
    bool is_mass_residual_held_; ///< simple.hold_mass_residual
    bool is_forcing_before_projection_;
    int max_iterations_;
    StepAlgorithm algorithm_; ///< simple.algorithm
    double pressure_relaxation_;
    PressureUpdate pressure_update_;
    MomentumSolver momentum_solver_; ///< simple.momentum_solver: how set_time_step picks cycles
    int momentum_cycles_;            ///< simple.momentum_cycles
    MomentumSettings momentum_;
    Vec<Dim> gravity_;
    bool is_paper_contact_;
    bool is_wall_marker_off_;  ///< coupling.markers_off_at_walls
    double wall_marker_reach_; ///< coupling.markers_off_reach [cells]; 0: the kernel's default
    bool is_body_marker_off_;  ///< coupling.markers_off_between_bodies
    bool is_adjoint_at_walls_; ///< coupling.adjoint_at_walls
    bool is_simultaneous_;     ///< coupling.body_sweep = "simultaneous"
    /// lubrication.enabled with lubrication.coupling = "implicit"
    bool is_lubrication_implicit_;
    bool is_inner_fluid_volume_; ///< coupling.inner_fluid = "volume"
    TimeScheme scheme_;          ///< time.scheme
    double dt_ = 0.0;

    std::vector<MomentumSystem<Dim>> systems_;
    std::unique_ptr<PoissonSolver<Dim>> poisson_;
    bool is_reusable_assembly_ = false;
    AndersonMixing mixing_;  ///< of the outer iterate, reset every step
    bool is_mixing_ = false; ///< this step: mixing on, and a free body to measure
    std::vector<MixedSegment> iterate_;
    std::vector<Vec<Dim>> previous_velocity_;     ///< U of the last iteration, per body
    std::vector<AngularVec<Dim>> previous_omega_; ///< ω of the last iteration, per body
};

} // namespace fddem
