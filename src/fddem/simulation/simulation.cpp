// SPDX-License-Identifier: MIT
// The time step (DESIGN.md §1, STYLE.md §2): implicit Euler, SIMPLE outer iterations.

#include "fddem/simulation/simulation.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/coupling/rigid_coupling.hpp"
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/loops.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace fddem {
namespace {

template <int Dim>
MacGrid<Dim> make_grid(const CaseConfig& config)
{
    if (config.dimension != Dim || config.size.size() != static_cast<std::size_t>(Dim) ||
        config.cells.size() != static_cast<std::size_t>(Dim)) {
        throw InputError(config.source_file, 0, "domain.size",
                         "the case is " + std::to_string(config.dimension) + "-dimensional, not " +
                             std::to_string(Dim) + "-dimensional");
    }
    Index<Dim> cells{};
    Vec<Dim> origin = Vec<Dim>::Zero();
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        cells[k] = config.cells[k];
        length[d] = config.size[k];
        if (config.origin.size() == static_cast<std::size_t>(Dim)) {
            origin[d] = config.origin[k];
        }
    }
    return MacGrid<Dim>(cells, origin, length);
}

template <int Dim>
BoundaryConditions<Dim> make_boundary_conditions(const CaseConfig& config)
{
    BoundaryConditions<Dim> bc = BoundaryConditions<Dim>::closed_box();
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        bc.is_periodic[k] = k < config.periodic.size() && config.periodic[k];
        for (std::size_t side = 0; side < 2 && k < config.boundary_kind.size(); ++side) {
            const std::string& kind = config.boundary_kind[k][side];
            bc.kind[k][side] = kind == "inflow"    ? BoundaryKind::inflow
                               : kind == "outflow" ? BoundaryKind::outflow
                                                   : BoundaryKind::wall;
        }
        if (k >= config.wall_velocity.size()) {
            continue;
        }
        for (std::size_t side = 0; side < 2; ++side) {
            const std::vector<double>& w = config.wall_velocity[k][side];
            for (int a = 0; a < Dim && static_cast<std::size_t>(a) < w.size(); ++a) {
                bc.wall_velocity[k][side][a] = w[static_cast<std::size_t>(a)];
            }
        }
    }
    bc.inflow = {config.inflow_profile == "parabolic", config.inflow_velocity};
    return bc;
}

template <int Dim>
double max_speed(const MacGrid<Dim>& grid, const FaceField<Dim>& u)
{
    double result = 0.0;
    for (int a = 0; a < Dim; ++a) {
        result = std::max(result, max_over(grid.face_box(a),
                                           [&](const Index<Dim>& c) { return std::abs(u[a](c)); }));
    }
    return result;
}

using Seconds = std::chrono::duration<double>;

/// A residual `value` ≥ 0 [m/s] relative to the velocity scale. A fluid at rest (the scale at
/// reference_velocity()'s floor) under a force has a residual before it has a velocity: it
/// then counts as 1, not as value/2.2e-308, which overflowed into a false blow-up (a periodic
/// channel driven by fluid.body_force = 1000 from rest, Δt = 0.01). Where the residual is
/// below the scale, as whenever the iterations near convergence, this is value/scale.
double relative_to(double value, double scale)
{
    return value / std::max(scale, value);
}

/// |U| + |ω| R: the largest speed of a point of a ball of radius R moving with (U, ω) [m/s].
template <int Dim>
double rim_speed(const Vec<Dim>& velocity, const AngularVec<Dim>& omega, double radius)
{
    return velocity.norm() + magnitude<Dim>(omega) * radius;
}

/// The outer iteration from which Anderson mixing keeps its history: the first two or three
/// iterations of a step shrink the change by 0.05–0.6 each and need no help, and a step that
/// converges in them (most steps of a single body or a dilute suspension) pays nothing for it.
constexpr int first_mixed_iteration = 3;

/// The values of a list of small vectors (λ on the markers) as one span of doubles; a
/// Vec<Dim> is Dim contiguous doubles.
template <int Dim>
std::span<double> flat(std::vector<Vec<Dim>>& values)
{
    static_assert(sizeof(Vec<Dim>) == Dim * sizeof(double));
    return values.empty() ? std::span<double>()
                          : std::span<double>(values.front().data(), Dim * values.size());
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
Simulation<Dim>::Simulation(const CaseConfig& config)
    : config_(config), grid_(make_grid<Dim>(config)),
      bc_(make_boundary_conditions<Dim>(config)), properties_{config.density, config.viscosity},
      momentum_settings_{config.dt,
                         config.convection == "upwind" ? ConvectionScheme::upwind
                                                       : ConvectionScheme::central,
                         config.velocity_relaxation, config.momentum_sweeps,
                         momentum_cycles_for(config.momentum_solver, config.momentum_cycles,
                                             time_term_share(grid_, properties_, config.dt))},
      state_(grid_), previous_level_(grid_),
      length_scale_(*std::min_element(config.size.begin(), config.size.end())),
      kernel_(kernel_from_name(config.kernel)),
      pressure_update_(config.pressure_update == "standard" ? PressureUpdate::standard
                                                            : PressureUpdate::rotational),
      mixing_(config.acceleration_depth)
{
    for (int a = 0; a < Dim; ++a) {
        systems_.emplace_back(grid_);
    }
    poisson_ = make_poisson_solver<Dim>(
        grid_, bc_.is_periodic,
        PoissonSettings{config.pressure_solver, config.linear_tolerance,
                        config.linear_max_iterations, config.fft_planning == "measure"});
    clock_.dt = config.dt;
    Vec<Dim> force = Vec<Dim>::Zero();
    for (int a = 0; a < Dim && static_cast<std::size_t>(a) < config.body_force.size(); ++a) {
        force[a] = config.body_force[static_cast<std::size_t>(a)];
    }
    for (int a = 0; a < Dim && static_cast<std::size_t>(a) < config.gravity.size(); ++a) {
        gravity_[a] = config.gravity[static_cast<std::size_t>(a)];
    }
    for (std::size_t k = 0; k < config.bodies.size(); ++k) {
        const BodyConfig& b = config.bodies[k];
        RigidBody<Dim> body;
        body.id = static_cast<int>(k);
        body.shape = Ball<Dim>{b.diameter};
        body.density = b.density;
        body.motion = b.motion == "fixed"        ? Motion::fixed
                      : b.motion == "prescribed" ? Motion::prescribed
                                                 : Motion::free;
        for (int d = 0; d < Dim; ++d) {
            body.centre[d] = b.position[static_cast<std::size_t>(d)];
            body.velocity[d] = body.motion == Motion::fixed || b.velocity.empty()
                                   ? 0.0
                                   : b.velocity[static_cast<std::size_t>(d)];
        }
        if constexpr (Dim == 2) {
            body.omega = body.motion == Motion::fixed ? 0.0 : b.omega;
        } else {
            body.omega = Vec<3>::Zero();
            body.torque = Vec<3>::Zero();
        }
        const int n_rings = b.n_rings > 0
                                ? b.n_rings
                                : rings_for_spacing(body.shape.radius(), grid_.spacing().maxCoeff(),
                                                    config.marker_spacing_ratio);
        bodies_.push_back(body);
        couplings_.emplace_back(make_ball_markers(body.shape, n_rings));
    }
    const bool has_free_body =
        std::any_of(bodies_.begin(), bodies_.end(),
                    [](const RigidBody<Dim>& body) { return body.motion == Motion::free; });
    const ContactModelInput input{
        {config.contact_stiffness, config.contact_damping, config.contact_tangential_ratio},
        config.contact_reference_mass};
    std::optional<AnyContactModel> model;
    if (has_free_body) {
        model = make_contact_model(config.contact_model, input); // none: no collisions
    }
    if (model) {
        dem_ = DemSettings{std::move(*model), config.contact_beta,
                           std::max(1, config.contact_substeps), config.contact_margin};
        is_paper_contact_ = config.contact_coupling == "paper";
        double largest = 0.0;
        for (const RigidBody<Dim>& body : bodies_) {
            largest = std::max(largest, body.shape.diameter);
        }
        // The range reaches one smallest radius beyond contact + margin: the skin of the DEM's
        // neighbour list (contact/neighbour_list.hpp), rebuilt when a body has moved half of it.
        double smallest = largest;
        for (const RigidBody<Dim>& body : bodies_) {
            smallest = std::min(smallest, body.shape.diameter);
        }
        contact_cells_.emplace(grid_.origin(), grid_.length(),
                               largest + config.contact_margin + 0.5 * smallest);
        walls_.origin = grid_.origin();
        walls_.length = grid_.length();
        walls_.material = config.wall_material;
        for (int d = 0; d < Dim; ++d) {
            const auto axis = static_cast<std::size_t>(d);
            walls_.has_walls[axis] = !bc_.is_periodic[axis];
            for (int side = 0; side < 2; ++side) {
                walls_.velocity[axis][static_cast<std::size_t>(side)] = bc_.wall(d, side);
            }
        }
    }
    place_markers(0, 0.0);
    set_uniform_body_force(force);
    fill_velocity_ghosts(grid_, bc_, state_.u);
    fill_cell_ghosts(grid_, bc_, state_.p);
}

template <int Dim>
void Simulation<Dim>::advance_time_level_in_systems()
{
    const double a_time = properties_.density * grid_.cell_volume() / clock_.dt;
    for (int a = 0; a < Dim; ++a) {
        GridArray<Dim>& b = systems_[static_cast<std::size_t>(a)].b;
        const GridArray<Dim>& now = state_.u_n[a];
        const GridArray<Dim>& before = previous_level_[a];
        for_each_index(unknown_faces(grid_, bc_, a), [&](const Index<Dim>& c) {
            const std::ptrdiff_t o = grid_.offset(c);
            b[o] += a_time * (now[o] - before[o]);
        });
    }
}

template <int Dim>
void Simulation<Dim>::collect_iterate(std::vector<MixedSegment>& segments)
{
    // Measured: the bodies' U and ω (ω at the rim, ×R), what the step's convergence test
    // measures; measuring the fluid's u instead took 8 % more outer iterations in the
    // Figs. 9–13 pile and cost a pass over the grid for every residual.
    segments.clear();
    for (RigidBody<Dim>& body : bodies_) {
        segments.push_back({std::span<double>(body.velocity.data(), Dim), 1.0});
        segments.push_back({flat(body.omega), body.shape.radius()});
    }
    for (BodyCoupling<Dim>& c : couplings_) {
        segments.push_back({flat<Dim>(c.lambda), 0.0});
    }
    for (int a = 0; a < Dim; ++a) {
        segments.push_back({state_.u[a].values(), 0.0});
    }
    segments.push_back({state_.p.values(), 0.0});
}

template <int Dim>
void Simulation<Dim>::mix_iterate()
{
    // The paper iterates eqs. (7)–(16) plainly; fddem replaces this iteration's output by
    // Anderson's combination of the last outputs, then restores what derives from the mixed
    // values: λ* = λ (eq. (16) is done) and p's ghosts (u's follow the body-force spread).
    collect_iterate(iterate_);
    mixing_.mix(iterate_);
    for (BodyCoupling<Dim>& c : couplings_) {
        c.lambda_star = c.lambda;
    }
    fill_cell_ghosts(grid_, bc_, state_.p);
}

template <int Dim>
void Simulation<Dim>::set_uniform_body_force(const Vec<Dim>& force)
{
    is_reusable_assembly_ = false;
    uniform_force_ = force;
    spread_marker_forces();
}

template <int Dim>
void Simulation<Dim>::place_markers(long step, double time)
{
    std::visit(
        [&](auto kernel) {
            using Kernel = decltype(kernel);
            for (std::size_t b = 0; b < bodies_.size(); ++b) {
                const RigidBody<Dim>& body = bodies_[b];
                BodyCoupling<Dim>& c = couplings_[b];
                if (!body.centre.allFinite() || !body.velocity.allFinite()) {
                    throw NumericalError(step, time, "body " + std::to_string(b),
                                         "the body's motion is not finite: the coupling has "
                                         "blown up");
                }
                for (std::size_t l = 0; l < c.markers.size(); ++l) {
                    const Vec<Dim>& r = c.markers.offsets[l];
                    if constexpr (Dim == 2) {
                        const double cs = std::cos(body.angle);
                        const double sn = std::sin(body.angle);
                        c.offsets[l] = Vec<2>(cs * r.x() - sn * r.y(), sn * r.x() + cs * r.y());
                    } else {
                        c.offsets[l] = r; // a sphere's markers need not turn with it
                    }
                    c.positions[l] = body.centre + c.offsets[l];
                    if (!fits_in_storage<Dim, Kernel>(grid_, c.positions[l])) {
                        throw NumericalError(
                            step, time, "body " + std::to_string(b),
                            fmt::format("a marker of the body left the box (its kernel support "
                                        "reaches past the ghost layers): centre ({:.6g}), "
                                        "velocity ({:.6g})",
                                        fmt::join(body.centre, ", "),
                                        fmt::join(body.velocity, ", ")));
                    }
                }
            }
        },
        kernel_);
}

template <int Dim>
void Simulation<Dim>::spread_marker_forces()
{
    // f = uniform force + ρf D(λ): the pseudo body force of eq. (4a) on the faces.
    for (int a = 0; a < Dim; ++a) {
        state_.body_force[a].fill(uniform_force_[a]);
    }
    std::visit(
        [&](auto kernel) {
            using Kernel = decltype(kernel);
            for (const BodyCoupling<Dim>& c : couplings_) {
                for (std::size_t l = 0; l < c.markers.size(); ++l) {
                    spread_vector<Dim, Kernel>(grid_, state_.body_force, c.positions[l],
                                               properties_.density * c.lambda[l],
                                               c.markers.volumes[l]);
                }
            }
        },
        kernel_);
}

template <int Dim>
double Simulation<Dim>::update_bodies(double dt)
{
    double defect = 0.0;
    std::visit(
        [&](auto kernel) {
            using Kernel = decltype(kernel);
            for (std::size_t b = 0; b < bodies_.size(); ++b) {
                RigidBody<Dim>& body = bodies_[b];
                BodyCoupling<Dim>& c = couplings_[b];
                for (std::size_t l = 0; l < c.markers.size(); ++l) {
                    c.fluid[l] = interpolate_velocity<Dim, Kernel>(grid_, state_.u, c.positions[l]);
                }
                RigidVelocity<Dim> motion{body.velocity, body.omega};
                if (body.motion == Motion::free && is_paper_contact_ && c.is_in_contact) {
                    // §2.3: "When the collision happens, the DEM is used in place of (13) and
                    // (14)": the body moves as the sub-steps say; the fluid is made to follow.
                    motion = {c.dem_velocity, c.dem_omega};
                } else if (body.motion == Motion::free) {
                    const RigidUpdateInput<Dim> in{
                        c.velocity_n,          c.omega_n,       body.density,
                        body.volume(),         body.inertia(),  properties_.density,
                        c.fluid_second_moment, gravity_,        dt,
                        c.contact_force,       c.contact_torque};
                    motion = rigid_velocity<Dim>(in, c.offsets, c.markers.volumes, c.fluid,
                                                 c.lambda_star); // eqs. (13)–(14)
                }
                defect = std::max(defect, update_marker_force<Dim>(motion, c.offsets, c.fluid,
                                                                   c.lambda_star, dt,
                                                                   c.lambda)); // eq. (15)
                c.forcing_change =
                    forcing_change<Dim>(c.offsets, c.markers.volumes, c.lambda, c.lambda_star, dt,
                                        body.volume(), body.shape.radius());
                for (std::size_t l = 0; l < c.markers.size(); ++l) {
                    // eq. (16): u ← u + Δt D(λ − λ*)
                    spread_vector<Dim, Kernel>(grid_, state_.u, c.positions[l],
                                               dt * (c.lambda[l] - c.lambda_star[l]),
                                               c.markers.volumes[l]);
                }
                c.lambda_star = c.lambda; // λ* ← λ
                body.velocity = motion.velocity;
                body.omega = motion.omega;
            }
        },
        kernel_);
    return defect;
}

template <int Dim>
void Simulation<Dim>::move_bodies(double dt)
{
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        RigidBody<Dim>& body = bodies_[b];
        const BodyCoupling<Dim>& c = couplings_[b];
        // Hydrodynamic force and torque from the fluid's momentum balance over the body:
        // F_H = ρf V (U^{n+1} − U^n)/Δt − ρf Σ ΔV_l λ_l (and likewise with r ×).
        Vec<Dim> lambda_sum = Vec<Dim>::Zero();
        AngularVec<Dim> lambda_moment{};
        if constexpr (Dim == 3) {
            lambda_moment = Vec<3>::Zero();
        }
        for (std::size_t l = 0; l < c.markers.size(); ++l) {
            lambda_sum += c.markers.volumes[l] * c.lambda[l];
            lambda_moment += c.markers.volumes[l] * cross(c.offsets[l], c.lambda[l]);
        }
        const double rho = properties_.density;
        body.force = rho * body.volume() * (body.velocity - c.velocity_n) / dt - rho * lambda_sum;
        body.torque =
            rho * c.fluid_second_moment * (body.omega - c.omega_n) / dt - rho * lambda_moment;
        if (body.motion == Motion::fixed) {
            continue;
        }
        if (is_paper_contact_ && c.is_in_contact) {
            body.centre = c.dem_centre; // §2.3: "DEM is used to update the position"
        } else {
            body.centre += 0.5 * dt * (body.velocity + c.velocity_n); // eq. (17)
        }
        if constexpr (Dim == 2) {
            body.angle += 0.5 * dt * (body.omega + c.omega_n);
        }
    }
}

template <int Dim>
void Simulation<Dim>::resolve_contacts(double dt, StepReport& report)
{
    // eq. (18) in N_i sub-steps from the level-n state, with the buoyant weight (ρs − ρf) V g
    // held over the sub-steps, as the paper's eq. (18). The last step's hydrodynamic force is
    // deliberately left out: it is mostly the fluid's reaction to the body's own acceleration
    // (added mass), and holding it over the next step feeds back on a body resting on a wall
    // (Fig. 5 case: the lagged force pushed the disk off the floor again and again).
    dem_bodies_.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const RigidBody<Dim>& body = bodies_[b];
        DemBody<Dim>& d = dem_bodies_[b];
        d.centre = body.centre;
        d.velocity = body.velocity;
        d.omega = body.omega;
        d.radius = body.shape.radius();
        d.mass = body.mass();
        d.inertia = body.inertia();
        d.is_mobile = body.motion == Motion::free;
        d.steady_force = (body.density - properties_.density) * body.volume() * gravity_;
        d.steady_torque = zero_angular<Dim>();
        d.material = config_.bodies[b].material;
    }
    const DemOutcome<Dim> outcome =
        advance_contacts<Dim>(dem_bodies_, walls_, *dem_, dt, *contact_cells_, contact_history_);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        BodyCoupling<Dim>& c = couplings_[b];
        c.is_in_contact = outcome.has_contact[b];
        c.contact_force = outcome.mean_force[b];
        c.contact_torque = outcome.mean_torque[b];
        c.dem_centre = dem_bodies_[b].centre;
        c.dem_velocity = dem_bodies_[b].velocity;
        c.dem_omega = dem_bodies_[b].omega;
    }
    report.max_overlap = outcome.max_overlap;
    report.max_relative_overlap = outcome.max_relative_overlap;
    report.contacts = outcome.n_contacts;
}

template <int Dim>
double Simulation<Dim>::reference_velocity() const
{
    double wall = 0.0;
    for (int d = 0; d < Dim; ++d) {
        for (int side = 0; side < 2; ++side) {
            wall = std::max(wall, bc_.wall(d, side).cwiseAbs().maxCoeff());
        }
    }
    // The floor only avoids 0/0 for a fluid entirely at rest (all residuals are then zero).
    return std::max({max_speed(grid_, state_.u), wall, std::numeric_limits<double>::min()});
}

template <int Dim>
StepReport Simulation<Dim>::advance()
{
    // One grid array and the (small) body state per step: cheap beside the step itself.
    step_start_.p = state_.p;
    step_start_.bodies = bodies_;
    step_start_.couplings = couplings_;
    step_start_.contacts = contact_history_;
    try {
        return advance_unguarded();
    } catch (const NumericalError&) {
        roll_back_step();
        throw;
    }
}

template <int Dim>
void Simulation<Dim>::roll_back_step()
{
    for (int a = 0; a < Dim; ++a) {
        state_.u[a] = state_.u_n[a];        // advance() moved u^n here
        state_.u_n[a] = previous_level_[a]; // and u^{n−1} here
    }
    state_.p = step_start_.p;
    state_.p_corr.fill(0.0); // only hypre's initial guess
    state_.divergence.fill(0.0);
    bodies_ = step_start_.bodies;
    couplings_ = step_start_.couplings;
    contact_history_ = step_start_.contacts;
    is_reusable_assembly_ = false;
    spread_marker_forces(); // the body force of the step's start, from its λ
}

template <int Dim>
std::string Simulation<Dim>::locate_non_finite_velocity() const
{
    // The first non-finite value in storage order (serial) of a field, at `where`'s position.
    const auto first_in = [&](const GridArray<Dim>& field, const Box<Dim>& box, auto where,
                              const std::string& name) -> std::optional<std::string> {
        std::optional<Index<Dim>> found;
        for_each_cell_in_vtk_order(box, [&](const Index<Dim>& c) {
            if (!found && !std::isfinite(field(c))) {
                found = c;
            }
        });
        if (!found) {
            return std::nullopt;
        }
        return fmt::format("{} not finite at ({:.6g})", name, fmt::join(where(*found), ", "));
    };
    for (int a = 0; a < Dim; ++a) {
        const auto face = [&](const Index<Dim>& c) { return grid_.face_centre(a, c); };
        if (auto at = first_in(state_.u[a], grid_.face_box(a), face,
                               fmt::format("velocity component {}", a))) {
            return *at;
        }
        if (auto at = first_in(state_.body_force[a], grid_.face_box(a), face,
                               fmt::format("body force component {} (the markers' λ)", a))) {
            return *at;
        }
    }
    const auto cell = [&](const Index<Dim>& c) { return grid_.cell_centre(c); };
    if (auto at = first_in(state_.p, grid_.cell_box(), cell, "pressure")) {
        return *at;
    }
    // All finite: a residual overflowed. Where is the fastest fluid?
    double fastest = 0.0;
    std::string where;
    for (int a = 0; a < Dim; ++a) {
        for_each_cell_in_vtk_order(grid_.face_box(a), [&](const Index<Dim>& c) {
            if (std::abs(state_.u[a](c)) > fastest) {
                fastest = std::abs(state_.u[a](c));
                where = fmt::format("{:.6g}", fmt::join(grid_.face_centre(a, c), ", "));
            }
        });
    }
    return fmt::format("the momentum residual is not finite (largest |u| {:.3g} at ({}))", fastest,
                       where);
}

template <int Dim>
StepReport Simulation<Dim>::advance_unguarded()
{
    const double dt = clock_.dt;
    for (int a = 0; a < Dim; ++a) {
        previous_level_[a] = state_.u_n[a];
        state_.u_n[a] = state_.u[a]; // keep u^n
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        couplings_[b].velocity_n = bodies_[b].velocity; // keep U^n, ω^n; λ* = λ^n already
        couplings_[b].omega_n = bodies_[b].omega;
    }
    const bool has_bodies = !bodies_.empty();
    double rigid_defect = 0.0;
    double body_change = 0.0;
    const double cell = grid_.spacing().minCoeff();

    StepReport report;
    if (dem_) {
        // eq. (18): the DEM sub-steps over the whole step, before the SIMPLE loop (§2.3).
        const auto start = std::chrono::steady_clock::now();
        resolve_contacts(dt, report);
        contact_seconds_ += Seconds(std::chrono::steady_clock::now() - start).count();
    }
    double mass_residual =
        compute_divergence(grid_, state_.u, state_.divergence) * cell / reference_velocity();
    mixing_.reset();
    // Only free bodies have velocities to measure (fixed and prescribed ones converge on λ).
    const bool is_mixed = mixing_.depth() > 0 && std::any_of(bodies_.begin(), bodies_.end(),
                                                             [](const RigidBody<Dim>& body) {
                                                                 return body.motion == Motion::free;
                                                             });
    for (int k = 1; k <= config_.max_outer_iterations; ++k) {
        const double velocity_scale = reference_velocity();
        if (is_mixed && k >= first_mixed_iteration) {
            collect_iterate(iterate_);
            mixing_.remember(iterate_); // x_k, for the mixing after eqs. (13)–(16)
        }

        // eqs. (7)–(8): momentum coefficients about the latest iterate, and its residual.
        auto start = std::chrono::steady_clock::now();
        double momentum_residual = 0.0;
        if (k == 1 && is_reusable_assembly_) {
            // The convergence check that ended the last step assembled the coefficients about
            // this very iterate; only the time level in b moved on: b += ρΔV/Δt (u^n − u^{n−1}).
            advance_time_level_in_systems();
        } else {
            for (int a = 0; a < Dim; ++a) {
                momentum_residual =
                    std::max(momentum_residual,
                             assemble_momentum(grid_, bc_, properties_, momentum_settings_, state_,
                                               a, systems_[static_cast<std::size_t>(a)]));
            }
        }
        is_reusable_assembly_ = false;
        report.momentum_residual = relative_to(momentum_residual, velocity_scale);
        report.mass_residual = mass_residual;
        if (!std::isfinite(report.momentum_residual)) {
            throw NumericalError(clock_.step + 1, clock_.time + dt,
                                 fmt::format("momentum equations, outer iteration {}", k),
                                 locate_non_finite_velocity() + ": the flow has blown up");
        }
        // Paper deviation (the paper does not state its test): with bodies, a step has
        // converged when the body velocities change by less than tolerance · U_ref from one
        // outer iteration to the next. The marker defect and the fluid residuals are reported,
        // not required: asking I(u) to be rigid at every marker of a discretely divergence-free
        // u asks slightly more than the grid can give, and λ then creeps on without the fluid
        // converging further (Fig. 3 case: mass residual 0.05, 0.03, 0.01 after 50, 200, 800
        // iterations of one step).
        const bool is_fluid_converged =
            report.momentum_residual < config_.tolerance && mass_residual < config_.tolerance;
        const bool is_step_converged =
            has_bodies ? body_change < config_.tolerance : is_fluid_converged;
        if (k > 1 && is_step_converged) {
            report.is_converged = true;
            is_reusable_assembly_ = !has_bodies;
            momentum_seconds_ += Seconds(std::chrono::steady_clock::now() - start).count();
            break;
        }
        for (int a = 0; a < Dim; ++a) {
            solve_momentum(grid_, bc_, momentum_settings_, systems_[static_cast<std::size_t>(a)], a,
                           state_); // → u*
        }
        momentum_seconds_ += Seconds(std::chrono::steady_clock::now() - start).count();

        // eqs. (9)–(12): pressure correction, then p and u corrected.
        start = std::chrono::steady_clock::now();
        const double max_divergence =
            correct_pressure_and_velocity(grid_, bc_, properties_, dt, config_.pressure_relaxation,
                                          pressure_update_, *poisson_, state_);
        pressure_seconds_ += Seconds(std::chrono::steady_clock::now() - start).count();
        mass_residual = relative_to(max_divergence * cell, velocity_scale);

        // eqs. (13)–(16): rigid-body velocities, marker forces, the correction spread to u.
        if (has_bodies) {
            start = std::chrono::steady_clock::now();
            double scale = std::max(velocity_scale, reference_velocity());
            std::vector<Vec<Dim>> previous_velocity;
            std::vector<AngularVec<Dim>> previous_omega;
            for (const RigidBody<Dim>& body : bodies_) {
                previous_velocity.push_back(body.velocity);
                previous_omega.push_back(body.omega);
            }
            const double defect = update_bodies(dt);
            if (scale <= std::numeric_limits<double>::min()) {
                // Fluid and bodies at rest until this update (the first iteration of a run
                // from rest): measure against the motion it started, not the floor of
                // reference_velocity(), which would overflow (a light disk under g = 980).
                scale = reference_velocity();
            }
            rigid_defect = defect / scale;
            body_change = 0.0;
            for (std::size_t b = 0; b < bodies_.size(); ++b) {
                // A free body converges on its velocity; a prescribed or fixed one, whose
                // velocity is given, on the force the fluid puts on it.
                const double change =
                    bodies_[b].motion == Motion::free
                        ? rim_speed<Dim>(bodies_[b].velocity - previous_velocity[b],
                                         bodies_[b].omega - previous_omega[b],
                                         bodies_[b].shape.radius())
                        : couplings_[b].forcing_change;
                body_change = std::max(body_change, change / scale);
            }
            report.body_change = body_change;
            if (is_mixed && k >= first_mixed_iteration) {
                mix_iterate(); // Paper deviation (docs/method.md §4): G(x_k) → x_{k+1}
            }
            spread_marker_forces(); // the momentum source of the next iteration: ρf D(λ*)
            fill_velocity_ghosts(grid_, bc_, state_.u);
            coupling_seconds_ += Seconds(std::chrono::steady_clock::now() - start).count();
            report.rigid_defect = rigid_defect;
        }
        report.outer_iterations = k;
    }

    const double velocity_scale = reference_velocity();
    double courant = 0.0;
    double change = 0.0;
    for (int a = 0; a < Dim; ++a) {
        const GridArray<Dim>& ua = state_.u[a];
        const GridArray<Dim>& ua_n = state_.u_n[a];
        courant = std::max(courant, max_over(grid_.face_box(a), [&](const Index<Dim>& c) {
                               return std::abs(ua(c)) * dt / grid_.spacing(a);
                           }));
        change = std::max(change, max_over(grid_.face_box(a), [&](const Index<Dim>& c) {
                              return std::abs(ua(c) - ua_n(c));
                          }));
    }
    report.courant = courant;
    if (has_bodies) {
        move_bodies(dt); // eq. (17)
        place_markers(clock_.step + 1, clock_.time + dt);
        spread_marker_forces();
    }
    // Divided in two steps: U_ref² may underflow for a fluid at rest.
    report.rate_of_change =
        change == 0.0 ? 0.0 : (change / velocity_scale) * (length_scale_ / (dt * velocity_scale));
    clock_.time += dt;
    ++clock_.step;
    track_rest();
    return report;
}

template <int Dim>
void Simulation<Dim>::track_rest()
{
    if (!config_.rest_speed) {
        return;
    }
    const bool is_at_rest =
        std::all_of(bodies_.begin(), bodies_.end(), [&](const RigidBody<Dim>& body) {
            return body.motion != Motion::free ||
                   rim_speed<Dim>(body.velocity, body.omega, body.shape.radius()) <
                       *config_.rest_speed;
        });
    if (!is_at_rest) {
        rest_since_ = -1.0;
    } else if (rest_since_ < 0.0) {
        rest_since_ = clock_.time;
    }
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
    for (const BodyCoupling<Dim>& c : couplings_) {
        const std::size_t n = c.markers.size();
        for (const auto* values : {&c.offsets, &c.positions, &c.fluid, &c.lambda, &c.lambda_star}) {
            if (values->size() != n) {
                throw InputError("", 0, "bodies.n_rings",
                                 "the checkpoint's bodies have other markers than the case's");
            }
        }
    }
    if (clock_.dt != config_.dt) {
        clock_.dt = config_.dt;
        is_reusable_assembly_ = false; // its coefficients hold the old ρ ΔV / Δt
    }
}

template <int Dim>
bool Simulation<Dim>::is_finished(const StepReport& last) const
{
    if (clock_.step >= config_.max_steps) {
        return true;
    }
    if (config_.end_time && clock_.time >= *config_.end_time - 0.5 * clock_.dt) {
        return true;
    }
    if (clock_.time < config_.min_end - 0.5 * clock_.dt) {
        return false;
    }
    if (config_.rest_speed && rest_since_ >= 0.0 &&
        clock_.time - rest_since_ >= config_.rest_duration - 0.5 * clock_.dt) {
        return true;
    }
    return config_.steady_tolerance && clock_.step > 1 &&
           last.rate_of_change < *config_.steady_tolerance;
}

template class Simulation<2>;
template class Simulation<3>;

} // namespace fddem
