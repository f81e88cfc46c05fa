// SPDX-License-Identifier: MIT
#include "fddem/simulation/outer_iterations.hpp"

#include "fddem/contact/cell_list.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/coupling/force_spreading.hpp"
#include "fddem/coupling/marker_routes.hpp"
#include "fddem/coupling/rigid_update.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/simulation/step_diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace fddem {
namespace {

/// The outer iteration from which Anderson mixing keeps its history: the first two or three
/// iterations of a step shrink the change by 0.05–0.6 each and need no help, and a step that
/// converges in them (most steps of a single body or a dilute suspension) pays nothing for it.
constexpr int first_mixed_iteration = 3;

/// |U| + |ω| R: the largest speed of a point of a ball of radius R moving with (U, ω) [m/s].
template <int Dim>
double rim_speed(const Vec<Dim>& velocity, const AngularVec<Dim>& omega, double radius)
{
    return velocity.norm() + magnitude<Dim>(omega) * radius;
}

/// Whether the film links a free body in this step (lubrication.coupling = "implicit": the DEM
/// records each free body's gaps within the range at the step's start, also for a body it moves
/// this step, in contact or within contact.margin). The bodies and their links are the same on
/// every rank (every rank runs the DEM on every body), so every rank decides alike.
template <int Dim>
bool is_any_free_body_film_linked(const Particles<Dim>& bodies)
{
    return std::any_of(bodies.begin(), bodies.end(), [](const Particle<Dim>& body) {
        return body.is_free() && !body.contact.lubrication_links.empty();
    });
}

std::span<double> flat(double& value)
{
    return {&value, 1};
}
std::span<double> flat(Vec<3>& value)
{
    return {value.data(), 3};
}

} // namespace

template <int Dim>
OuterIterations<Dim>::OuterIterations(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                      const FluidProperties& properties, const AnyKernel& kernel,
                                      const CaseConfig& config, const Vec<Dim>& gravity,
                                      bool is_paper_contact)
    : grid_(grid), bc_(bc), properties_(properties), kernel_(kernel),
      tolerance_(config.simple.tolerance),
      is_fluid_converged_with_bodies_(config.simple.is_fluid_converged_with_bodies),
      min_iterations_dem_(config.simple.min_outer_iterations_dem),
      is_mass_residual_held_(config.simple.is_mass_residual_held),
      is_forcing_before_projection_(config.coupling.is_forcing_before_projection),
      max_iterations_(config.simple.max_outer_iterations), algorithm_(config.simple.algorithm),
      pressure_relaxation_(config.simple.pressure_relaxation),
      pressure_update_(config.simple.pressure_update),
      momentum_solver_(config.simple.momentum_solver),
      momentum_cycles_(config.simple.momentum_cycles), momentum_{config.simple.convection,
                                                                 config.simple.velocity_relaxation,
                                                                 config.simple.momentum_sweeps,
                                                                 config.simple.momentum_cycles},
      gravity_(gravity), is_paper_contact_(is_paper_contact),
      is_wall_marker_off_(config.coupling.is_wall_marker_off),
      wall_marker_reach_(config.coupling.wall_marker_reach.value_or(0.0)),
      is_body_marker_off_(config.coupling.is_body_marker_off),
      is_adjoint_at_walls_(config.coupling.is_adjoint_at_walls),
      is_simultaneous_(config.coupling.body_sweep == BodySweep::simultaneous),
      is_lubrication_implicit_(config.lubrication.is_implicit()),
      is_inner_fluid_volume_(config.coupling.inner_fluid == InnerFluidSource::volume),
      scheme_(config.time.scheme),
      poisson_(make_poisson_solver<Dim>(
          grid, bc.is_periodic,
          PoissonSettings{config.simple.pressure_solver, config.simple.linear_tolerance,
                          config.simple.linear_max_iterations, config.simple.fft_planning})),
      mixing_(config.simple.acceleration_depth, config.simple.acceleration_weight_bits,
              config.simple.acceleration_max_step)
{
    if (is_lubrication_implicit_ && is_simultaneous_ && grid.communicator().size() > 1) {
        // The owners of a split grid's simultaneous sweep each solve their own bodies' eqs.
        // (13)–(14); a group the film joins would need its members on one rank (not built).
        throw InputError(config.source_file, 0, "lubrication.coupling",
                         "\"implicit\" (the default) with coupling.body_sweep = "
                         "\"simultaneous\" on more than one MPI rank is not supported yet; use "
                         "body_sweep = \"sequential\" (the default), lubrication.coupling = "
                         "\"dem\" or one rank");
    }
    for (int a = 0; a < Dim; ++a) {
        systems_.emplace_back(grid_);
    }
    set_time_step(config.time.dt);
}

template <int Dim>
void OuterIterations<Dim>::set_time_step(double dt)
{
    if (dt != dt_) {
        is_reusable_assembly_ = false; // its coefficients hold the old ρ ΔV / Δt
    }
    dt_ = dt;
    momentum_.cycles = momentum_cycles_for(momentum_solver_, momentum_cycles_,
                                           time_term_share(grid_, properties_, dt));
}

template <int Dim>
void OuterIterations<Dim>::iterate(const StepInputs<Dim>& in, FluidState<Dim>& state,
                                   Particles<Dim>& bodies, PhaseTimes& times, StepReport& report)
{
    if (algorithm_ == StepAlgorithm::projection && !is_any_body_near_contact(bodies)) {
        project(in, state, bodies, times, report);
        return;
    }
    const bool has_bodies = !bodies.empty();
    double mass_residual = compute_divergence(grid_, state.u, state.divergence) *
                           grid_.spacing().minCoeff() / reference_velocity(grid_, bc_, state.u);
    mixing_.reset();
    // Only free bodies have velocities to measure (fixed and prescribed ones converge on λ).
    // Nor in a step in which the film links a free body: mixed, the eighteen disks' steps passed
    // the bodies' test while the mass residual drifted up until the flow ran away at t ≈ 0.6 s.
    // The mixing weighs the iterates by the bodies' velocities alone, which the film's damping
    // holds nearly still whatever the fluid does (a reading, not checked iteration by iteration).
    // Counting only the linked bodies eqs. (13)–(14) move was not enough (docs/method.md §5,
    // "The default coupling of the film").
    is_mixing_ = mixing_.depth() > 0 && bodies.has_free_body() &&
                 !(is_lubrication_implicit_ && is_any_free_body_film_linked(bodies));
    const int fewest = fewest_iterations(bodies); // before the step's test may end it
    // simple.hold_mass_residual compares each outer iteration's mass residual (of u*) with
    // this one, of the velocity the step starts from, and with the iteration before.
    const double start_mass_residual = mass_residual;
    double previous_mass_residual = mass_residual;
    for (int k = 1; k <= max_iterations_; ++k) {
        const double velocity_scale = reference_velocity(grid_, bc_, state.u);
        if (is_mixed_iteration(k)) {
            collect_iterate(state, bodies);
            mixing_.remember(iterate_); // x_k, for the mixing after eqs. (13)–(16)
        }
        {
            const ScopedPhase timer(times, Phase::momentum); // eqs. (7)–(8) about the iterate
            report.momentum_residual = relative_to(assemble(k, in, state), velocity_scale);
        }
        report.mass_residual = mass_residual;
        check_finite(k, in, state, report);
        const bool is_mass_kept = is_mass_residual_kept(
            has_bodies, k, start_mass_residual, previous_mass_residual, report.mass_residual);
        previous_mass_residual = report.mass_residual;
        if (k > fewest && is_step_converged(has_bodies, report) && is_mass_kept) {
            report.is_converged = true;
            // The next step starts from this assembly (Euler: see is_reusable_assembly()).
            is_reusable_assembly_ = !has_bodies && scheme_ == TimeScheme::euler;
            break;
        }
        solve_momentum_systems(state, times); // eqs. (7)–(8) relaxed → u*
        if (has_bodies && is_forcing_before_projection_) {
            const ScopedPhase timer(times, Phase::coupling); // eqs. (13)–(16) on u*
            couple_bodies(k, velocity_scale, in, state, bodies, report);
        }
        // eqs. (9)–(12), with d = Δt_e/ρf: the time term's coefficient in a_P (BDF2's leading one)
        mass_residual = correct_pressure(in.levels.dt_effective, velocity_scale, state, times);
        if (has_bodies && !is_forcing_before_projection_) {
            const ScopedPhase timer(times, Phase::coupling); // eqs. (13)–(16)
            couple_bodies(k, velocity_scale, in, state, bodies, report);
        }
        report.outer_iterations = k;
    }
}

template <int Dim>
void OuterIterations<Dim>::project(const StepInputs<Dim>& in, FluidState<Dim>& state,
                                   Particles<Dim>& bodies, PhaseTimes& times, StepReport& report)
{
    // The incremental pressure-correction (projection) scheme, as reviewed by Guermond, Minev
    // & Shen (2006, Comput. Methods Appl. Mech. Engrg. 195, 6011): the predictor of eqs.
    // (7)–(8) with the pressure of the step's start, then eqs. (9)–(12) once, with the
    // rotational update by default (Timmermans, Minev & van de Vosse 1996). It is SIMPLE's
    // first outer iteration, with two differences:
    // - the predictor is solved to the step's tolerance, not by a fixed number of sweeps (with
    //   4 sweeps the 64³ lid-driven cube's time error was 6 times SIMPLE's; docs/method.md §1);
    // - it is linearised (the convecting velocity, the deferred convection correction, the
    //   sweeps' first guess) about the extrapolation u^n + ω (u^n − u^{n−1}), ω = Δt_n/Δt_{n−1},
    //   not about u^n: about u^n that linearisation error is O(Δt), and BDF2 was no better
    //   than first order on the Taylor–Green vortex; about the extrapolation it is O(Δt²), BDF2
    //   second order and Euler's error below SIMPLE's there (TimeOrder.*). The first step of
    //   a run starts from u^n.
    extrapolate_start(in, state);
    // Never the shortcut of a SIMPLE step's last assembly (a run restarted with the algorithm
    // changed would carry it): this step's systems are about the extrapolation.
    is_reusable_assembly_ = false;
    const double velocity_scale = reference_velocity(grid_, bc_, state.u);
    double residual = 0.0;
    {
        const ScopedPhase timer(times, Phase::momentum);
        report.momentum_residual = relative_to(assemble(1, in, state), velocity_scale);
        check_finite(1, in, state, report);
        const MomentumStop stop{tolerance_ * velocity_scale, max_iterations_};
        for (int a = 0; a < Dim; ++a) {
            const MomentumSolveResult solved = solve_momentum_to(
                grid_, bc_, momentum_, systems_[static_cast<std::size_t>(a)], a, state, stop);
            residual = max_keeping_nan(residual, solved.residual);
            report.momentum_rounds = std::max(report.momentum_rounds, solved.rounds);
        }
    }
    report.momentum_residual = relative_to(residual, velocity_scale);
    check_finite(1, in, state, report);
    // With bodies, eqs. (13)–(16) once, before or after the projection as in SIMPLE's outer
    // iterations (coupling.force_before_projection): the fictitious-domain step not iterated
    // (Sharma & Patankar 2005), for free bodies no lighter than the fluid (io/case_checks.cpp)
    // and none near a contact (is_any_body_near_contact).
    const bool has_bodies = !bodies.empty();
    if (has_bodies && is_forcing_before_projection_) {
        const ScopedPhase timer(times, Phase::coupling);
        couple_bodies(1, velocity_scale, in, state, bodies, report);
    }
    report.mass_residual =
        correct_pressure(in.levels.dt_effective, velocity_scale, state, times); // of u*
    if (has_bodies && !is_forcing_before_projection_) {
        const ScopedPhase timer(times, Phase::coupling);
        couple_bodies(1, velocity_scale, in, state, bodies, report);
    }
    report.outer_iterations = 1;
    // The predictor's convergence (simple.converge_fluid_with_bodies and the bodies' change
    // are not tested: there is no second pass to compare with).
    report.is_converged = report.momentum_residual <= tolerance_;
}

template <int Dim>
bool OuterIterations<Dim>::is_any_body_near_contact(const Particles<Dim>& bodies) const
{
    // A free body in contact, within the contact margin or linked by a lubrication film in this
    // step's DEM, or within two kernel widths (2 h with the hat kernel, 4 h with the wider ones)
    // of a wall or of another body: where the markers' kernels reach a wall's ghost cells or
    // another body's kernels, one pass of eqs. (13)–(16) is far from their converged answer
    // (measured: the Fig. 5 disk at h = 1/64 left the floor at 20 cm/s, 3.6 times its settling
    // speed, after its first touch). Such a step takes SIMPLE's outer iterations. The bodies are
    // the same on every rank, so every rank decides alike.
    const int half_width = std::visit(
        [](const auto& kernel) { return std::decay_t<decltype(kernel)>::half_width; }, kernel_);
    const double near = 2.0 * half_width * grid_.spacing().maxCoeff();
    const PeriodicDomain<Dim> domain = grid_.domain();
    double largest_radius = 0.0;
    bool has_free_body = false;
    for (const Particle<Dim>& body : bodies) {
        largest_radius = std::max(largest_radius, body.radius());
        if (!body.is_free()) {
            continue;
        }
        has_free_body = true;
        if (body.contact.is_in_contact || !body.contact.lubrication_links.empty()) {
            return true;
        }
        for (int d = 0; d < Dim; ++d) {
            const double low = body.centre[d] - domain.origin[d];
            const double high = domain.origin[d] + domain.length[d] - body.centre[d];
            if (!domain.periodic(d) && std::min(low, high) - body.radius() < near) {
                return true;
            }
        }
    }
    if (!has_free_body || bodies.size() < 2) {
        return false;
    }
    // Every pair with a free body whose surfaces are closer than `near`: its centres are closer
    // than 2 R_max + near, so a cell list of that range finds it (contact/cell_list.hpp; linear
    // in the bodies, where testing every pair was quadratic).
    std::vector<Vec<Dim>> centres;
    centres.reserve(bodies.size());
    for (const Particle<Dim>& body : bodies) {
        centres.push_back(body.centre);
    }
    CellList<Dim> cells(domain, 2.0 * largest_radius + near);
    std::vector<std::pair<int, int>> pairs;
    cells.find_pairs(centres, pairs);
    for (const auto& [i, j] : pairs) {
        const Particle<Dim>& a = bodies[static_cast<std::size_t>(i)];
        const Particle<Dim>& b = bodies[static_cast<std::size_t>(j)];
        if ((a.is_free() || b.is_free()) &&
            domain.minimum_image(b.centre - a.centre).norm() - a.radius() - b.radius() < near) {
            return true;
        }
    }
    return false;
}

template <int Dim>
void OuterIterations<Dim>::extrapolate_start(const StepInputs<Dim>& in, FluidState<Dim>& state)
{
    const double ratio = in.levels.step_ratio;
    if (ratio <= 0.0) {
        return; // a run's first step: no u^{n−1}
    }
    for (int a = 0; a < Dim; ++a) {
        double* u = state.u[a].data();
        const double* now = state.u_n[a].data();
        const double* before = state.u_nm1[a].data();
        for (std::size_t i = 0; i < state.u[a].size(); ++i) {
            u[i] = now[i] + ratio * (now[i] - before[i]);
        }
    }
    fill_velocity_ghosts(grid_, bc_, state.u);
}

template <int Dim>
int OuterIterations<Dim>::fewest_iterations(const Particles<Dim>& bodies) const
{
    // A step is judged on how much the bodies changed from one outer iteration to the next.
    // A free body the DEM moves (paper coupling, in contact or within the lubrication range) has
    // its velocity given for the step, so the first such change says nothing: at rest it is
    // zero at once, and every step of a pile at rest is one momentum solve, one projection and
    // one forcing correction, a map that grows the mass residual by a fixed factor a step
    // whatever Δt (the soak's collapse). simple.min_outer_iterations_dem = 2, the default,
    // holds the pile; converging those bodies on their force instead made a hard collision
    // diverge (docs/method.md §5, "A pile at rest").
    const bool has_given_free_body =
        std::any_of(bodies.begin(), bodies.end(), [&](const Particle<Dim>& body) {
            return body.is_free() && !is_moved_by_fluid(body, is_paper_contact_);
        });
    return has_given_free_body ? min_iterations_dem_ : 1;
}

template <int Dim>
bool OuterIterations<Dim>::is_step_converged(bool has_bodies, const StepReport& report) const
{
    // Paper deviation (the paper does not state its test): with bodies, a step has converged
    // when the body velocities change by less than tolerance · U_ref from one outer iteration
    // to the next. The marker defect and the fluid residuals are reported, not required: asking
    // I(u) to be rigid at every marker of a discretely divergence-free u asks slightly more than
    // the grid can give, and λ then creeps on without the fluid converging further (Fig. 3
    // case: mass residual 0.05, 0.03, 0.01 after 50, 200, 800 iterations of one step).
    const bool is_fluid_converged =
        report.momentum_residual < tolerance_ && report.mass_residual < tolerance_;
    if (has_bodies) {
        return report.body_change < tolerance_ &&
               (!is_fluid_converged_with_bodies_ || is_fluid_converged);
    }
    return is_fluid_converged;
}

template <int Dim>
bool OuterIterations<Dim>::is_mass_residual_kept(bool has_bodies, int k, double start,
                                                 double previous, double now) const
{
    // Back at (or below) the step's start, or no longer falling: from k = 3 on, an iteration
    // that did not lower the residual says the coupled iteration has stopped helping (a body
    // driven into a wall, whose markers ask for a flow the projection forbids).
    return !has_bodies || !is_mass_residual_held_ || now <= std::max(tolerance_, start) ||
           (k > 2 && now >= previous);
}

template <int Dim>
void OuterIterations<Dim>::check_finite(int k, const StepInputs<Dim>& in,
                                        const FluidState<Dim>& state,
                                        const StepReport& report) const
{
    if (!std::isfinite(report.momentum_residual)) {
        throw NumericalError(in.step, in.time,
                             fmt::format("momentum equations, outer iteration {}", k),
                             locate_non_finite(grid_, state) + ": the flow has blown up");
    }
}

template <int Dim>
double OuterIterations<Dim>::assemble(int k, const StepInputs<Dim>& in,
                                      const FluidState<Dim>& state)
{
    double residual = 0.0;
    if (k == 1 && is_reusable_assembly_) {
        // The convergence test that ended the last step assembled the coefficients about this
        // very iterate; only the time level in b moved on: b += ρΔV/Δt (u^n − u^{n−1}).
        const double a_time = properties_.density * grid_.cell_volume() / in.dt;
        for (int a = 0; a < Dim; ++a) {
            GridArray<Dim>& b = systems_[static_cast<std::size_t>(a)].b;
            const GridArray<Dim>& now = state.u_n[a];
            const GridArray<Dim>& before = state.u_nm1[a];
            for_each_index(unknown_faces(grid_, bc_, a), [&](const Index<Dim>& c) {
                const std::ptrdiff_t o = grid_.offset(c);
                b[o] += a_time * (now[o] - before[o]);
            });
        }
    } else {
        for (int a = 0; a < Dim; ++a) {
            residual = std::max(residual,
                                assemble_momentum(grid_, bc_, properties_, momentum_, in.levels,
                                                  state, a, systems_[static_cast<std::size_t>(a)]));
        }
    }
    is_reusable_assembly_ = false;
    return residual;
}

template <int Dim>
void OuterIterations<Dim>::solve_momentum_systems(FluidState<Dim>& state, PhaseTimes& times)
{
    const ScopedPhase timer(times, Phase::momentum);
    for (int a = 0; a < Dim; ++a) {
        solve_momentum(grid_, bc_, momentum_, systems_[static_cast<std::size_t>(a)], a, state);
    }
}

template <int Dim>
double OuterIterations<Dim>::correct_pressure(double dt, double velocity_scale,
                                              FluidState<Dim>& state, PhaseTimes& times)
{
    const ScopedPhase timer(times, Phase::pressure);
    const double max_divergence = correct_pressure_and_velocity(
        grid_, bc_, properties_, dt, pressure_relaxation_, pressure_update_, *poisson_, state);
    return relative_to(max_divergence * grid_.spacing().minCoeff(), velocity_scale);
}

template <int Dim>
void OuterIterations<Dim>::couple_bodies(int k, double velocity_scale, const StepInputs<Dim>& in,
                                         FluidState<Dim>& state, Particles<Dim>& bodies,
                                         StepReport& report)
{
    double scale = std::max(velocity_scale, reference_velocity(grid_, bc_, state.u));
    previous_velocity_.resize(bodies.size());
    previous_omega_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        previous_velocity_[b] = bodies[b].velocity;
        previous_omega_[b] = bodies[b].omega;
    }
    RigidUpdateSettings<Dim> settings{properties_.density,      gravity_,
                                      in.levels.dt_effective,   is_paper_contact_,
                                      in.levels.history_weight, is_wall_marker_off_,
                                      is_simultaneous_,         adjoint_walls(),
                                      is_lubrication_implicit_, is_inner_fluid_volume_};
    settings.wall_marker_reach = wall_marker_reach_;
    settings.is_body_marker_off = is_body_marker_off_;
    const double defect =
        update_rigid_bodies<Dim>(bodies.all(), grid_, kernel_, settings, state.u); // (13)–(16)
    if (scale <= std::numeric_limits<double>::min()) {
        // Fluid and bodies at rest until this update (the first iteration of a run from rest):
        // measure against the motion it started, not the floor of reference_velocity(), which
        // would overflow (a light disk under g = 980).
        scale = reference_velocity(grid_, bc_, state.u);
    }
    report.body_change = 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        // A free body converges on its velocity; a prescribed or fixed one, whose velocity is
        // given, on the force the fluid puts on it. (A free body the DEM moves is measured on
        // its velocity too, which the iterations do not change; its steps take at least
        // simple.min_outer_iterations_dem of them, fewest_iterations(). Converging it on its
        // force instead made a hard collision diverge: docs/method.md §5, "A pile at rest".)
        const Particle<Dim>& body = bodies[b];
        const double change = body.is_free()
                                  ? rim_speed<Dim>(body.velocity - previous_velocity_[b],
                                                   body.omega - previous_omega_[b], body.radius())
                                  : body.coupling.forcing_change;
        report.body_change = std::max(report.body_change, change / scale);
    }
    if (is_mixed_iteration(k) && report.body_change < tolerance_) {
        // G(x_k) has passed the step's test on the bodies: it is what the step keeps, not an
        // extrapolation from it that no iteration has evaluated. (Mixed here, a converged step
        // ended on x_{k+1}, up to 0.06 U away from G(x_k) when γ was large: the lone disk's
        // blow-up and Fig. 3's run-away at D/8, docs/method.md §4, "The mixing's step
        // bounded".) Should the step go on, the mixing starts afresh from G(x_k).
        mixing_.reset();
    } else if (is_mixed_iteration(k)) {
        // Paper deviation (docs/method.md §4): this iteration's output G(x_k) is replaced by
        // Anderson's combination x_{k+1} of the last outputs; then what derives from the mixed
        // values is restored: λ* = λ (eq. (16) is done) and p's ghosts (u's follow below). A
        // step out of bounds (AndersonMixing::mix) is refused, and G(x_k) stays as it is.
        collect_iterate(state, bodies);
        if (mixing_.mix(iterate_)) {
            for (Particle<Dim>& body : bodies) {
                body.coupling.lambda_star = body.coupling.lambda;
            }
            fill_cell_ghosts(grid_, bc_, state.p);
        }
    }
    spread_body_force(bodies, in.uniform_force, state); // the next iteration's ρf D(λ*)
    fill_velocity_ghosts(grid_, bc_, state.u);
    report.rigid_defect = defect / scale;
}

template <int Dim>
void OuterIterations<Dim>::spread_body_force(const Particles<Dim>& bodies,
                                             const Vec<Dim>& uniform_force,
                                             FluidState<Dim>& state) const
{
    spread_marker_forces<Dim>(bodies.all(), grid_, kernel_, properties_.density, uniform_force,
                              state.body_force, adjoint_walls());
}

template <int Dim>
void OuterIterations<Dim>::collect_iterate(FluidState<Dim>& state, Particles<Dim>& bodies)
{
    // Measured: the bodies' U and ω (ω at the rim, ×R), what the step's convergence test
    // measures; measuring the fluid's u instead took 8 % more outer iterations in the
    // Figs. 9–13 pile and cost a pass over the grid for every residual.
    iterate_.clear();
    for (Particle<Dim>& body : bodies) {
        iterate_.push_back({std::span<double>(body.velocity.data(), Dim), 1.0});
        iterate_.push_back({flat(body.omega), body.radius()});
    }
    for (Particle<Dim>& body : bodies) {
        // Mixed entry by entry with the weights the measured values give, so a body's λ can be
        // left out where it is not read: with the simultaneous sweep on a split grid, on a rank
        // that neither owns the body nor holds any of its markers (the set is fixed within a
        // step, as the mixing's layout must be).
        if (!is_simultaneous_ || holds_markers_of(grid_, body)) {
            iterate_.push_back({flat_values<Dim>(body.coupling.lambda), 0.0});
        }
    }
    for (int a = 0; a < Dim; ++a) {
        iterate_.push_back({state.u[a].values(), 0.0});
    }
    iterate_.push_back({state.p.values(), 0.0});
}

template <int Dim>
bool OuterIterations<Dim>::is_mixed_iteration(int k) const noexcept
{
    return is_mixing_ && k >= first_mixed_iteration;
}

template class OuterIterations<2>;
template class OuterIterations<3>;

} // namespace fddem
