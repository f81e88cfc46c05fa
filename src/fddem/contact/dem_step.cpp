// SPDX-License-Identifier: MIT
#include "fddem/contact/dem_step.hpp"

#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/dem_integrator.hpp"
#include "fddem/contact/film_solve.hpp"
#include "fddem/contact/neighbour_list.hpp"
#include "fddem/contact/tangential_contact.hpp"

#include <algorithm>
#include <limits>
#include <optional>

namespace fddem {
namespace {

/// Whether a body within the lubrication range counts as in contact (lubrication.coupling
/// "dem"); with "implicit" only the margin does, and a gap leaving a collision within the range
/// (ContactForces::mark_if_near).
bool counts_range_as_contact(const LubricationSettings& lubrication)
{
    return lubrication.is_enabled && lubrication.coupling == LubricationCoupling::dem;
}

/// The sub-stepped state of a body (ContactState), as the contact geometry needs it.
template <int Dim>
BallState<Dim> ball_of(const Particle<Dim>& b)
{
    return {b.contact.centre, b.radius(), b.contact.velocity, b.contact.omega};
}

template <int Dim>
PairSide side_of(const Particle<Dim>& b)
{
    return ball_side(b.mass(), b.inertia(), b.radius(), b.material, b.is_free());
}

/// How far the outermost marker shell of `b` lies inside its surface [m] (0 without markers):
/// its share of the gap the grid resolves (lubrication.resolved = "shells").
template <int Dim>
double outermost_shell_depth(const Particle<Dim>& b)
{
    const MarkerSet<Dim>& markers = b.coupling.markers;
    return markers.size() == 0 ? 0.0 : std::max(0.0, b.radius() - markers.outermost_radius());
}

/// Contact forces and torques on every body at the current state, for one contact model; keeps
/// the tangential springs of the open contacts and tracks the largest overlap.
template <int Dim, class Model>
class ContactForces {
public:
    ContactForces(std::span<const Particle<Dim>> bodies, const DemWalls<Dim>& walls,
                  const Model& model, ContactHistory<Dim>& history, double margin,
                  const LubricationSettings& lubrication, const CellList<Dim>& cells, double dt)
        : force(bodies.size()), torque(bodies.size()), has_contact(bodies.size()),
          touching(bodies.size()), walls_(walls), model_(model), history_(history), dt_(dt),
          margin_(counts_range_as_contact(lubrication) ? std::max(margin, lubrication.range)
                                                       : margin),
          domain_(cells.domain()),
          neighbours_(std::max(margin, lubrication.is_enabled ? lubrication.range : 0.0),
                      largest_radius(bodies), cells),
          lubrication_(lubrication)
    {
        neighbours_.set_walls(walls.origin, walls.length, walls.has_walls);
        radii_.reserve(bodies.size());
        shell_depths_.reserve(bodies.size());
        for (const Particle<Dim>& b : bodies) {
            radii_.push_back(b.radius());
            shell_depths_.push_back(outermost_shell_depth(b));
        }
    }

    /// Forces at the bodies' state. `step` = Δt_i; the springs stretch by v_t Δt_i only if
    /// `is_new_substep` (not when the state of the last sub-step is merely re-evaluated).
    void evaluate(std::span<const Particle<Dim>> bodies, CellList<Dim>& cells, double step,
                  bool is_new_substep, DemOutcome& outcome)
    {
        std::fill(force.begin(), force.end(), Vec<Dim>::Zero());
        std::fill(torque.begin(), torque.end(), zero_angular<Dim>());
        std::fill(touching.begin(), touching.end(), char{0});
        centres_.resize(bodies.size());
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            centres_[b] = bodies[b].contact.centre;
        }
        neighbours_.refresh(centres_, radii_, cells);
        previous_.springs.swap(history_.springs);
        history_.springs.clear();
        previous_.coefficients.swap(history_.coefficients);
        history_.coefficients.clear();
        previous_.rebounds.swap(history_.rebounds);
        history_.rebounds.clear();
        step_ = step;
        stretch_ = is_new_substep ? step : 0.0;
        in_contact = 0;
        for (const auto& [i, j] : neighbours_.pairs()) {
            const auto a = static_cast<std::size_t>(i);
            const auto b = static_cast<std::size_t>(j);
            if (!bodies[a].is_free() && !bodies[b].is_free()) {
                continue; // neither can move: nothing to resolve
            }
            const ContactGeometry<Dim> g =
                ball_ball_contact(ball_of(bodies[a]), ball_of(bodies[b]), domain_);
            const ContactKey key = pair_contact_key(bodies[a].id, bodies[b].id);
            mark_if_near(g, key, a, b);
            if (g.overlap <= 0.0) {
                continue;
            }
            apply(g, a, b, key, key_orientation(bodies[a].id, bodies[b].id),
                  make_contact_pair(side_of(bodies[a]), side_of(bodies[b])),
                  std::min(bodies[a].radius(), bodies[b].radius()), outcome);
        }
        for (const auto& [body, d, side] : neighbours_.walls()) {
            const auto a = static_cast<std::size_t>(body);
            if (!bodies[a].is_free()) {
                continue;
            }
            const ContactGeometry<Dim> g = wall_contact(bodies[a], d, side);
            const ContactKey key = wall_contact_key(bodies[a].id, d, side);
            mark_if_near(g, key, a, bodies.size());
            if (g.overlap > 0.0) {
                apply(g, a, bodies.size(), key, 1.0,
                      make_contact_pair(side_of(bodies[a]), wall_side(walls_.material)),
                      bodies[a].radius(), outcome);
            }
        }
        const auto by_key = [](const auto& x, const auto& y) { return x.key < y.key; };
        std::sort(history_.springs.begin(), history_.springs.end(), by_key);
        std::sort(history_.coefficients.begin(), history_.coefficients.end(), by_key);
        std::sort(history_.rebounds.begin(), history_.rebounds.end(), by_key);
    }

    /// The contact geometry of `body` with the wall on `side` (0 low, 1 high) of axis `d`.
    [[nodiscard]] ContactGeometry<Dim> wall_contact(const Particle<Dim>& body, int d,
                                                    int side) const
    {
        const auto axis = static_cast<std::size_t>(d);
        const double at = walls_.origin[d] + side * walls_.length[d];
        return ball_wall_contact(ball_of(body), d, side, at,
                                 walls_.velocity[axis][static_cast<std::size_t>(side)]);
    }

    /// The lubrication impulses over the coming drift of one sub-step `step` from the bodies'
    /// current state, applied pair by pair (in the neighbour list's order) to contact.velocity
    /// and contact.omega by a backward-Euler damper (damp), and added to the mean force and torque
    /// as impulse / `dt`. A prescribed or fixed body keeps its velocity but gets the film's force
    /// in its mean and lubrication force (what particles.csv reports), as it gets the resolved
    /// flow's.
    void lubricate(std::span<Particle<Dim>> bodies, double step, double dt)
    {
        if (lubrication_.film_solve == LubricationFilmSolve::joint) {
            lubricate_jointly(bodies, step, dt);
            return;
        }
        for (const auto& [i, j] : neighbours_.pairs()) {
            const auto a = static_cast<std::size_t>(i);
            const auto b = static_cast<std::size_t>(j);
            const ContactGeometry<Dim> g =
                ball_ball_contact(ball_of(bodies[a]), ball_of(bodies[b]), domain_);
            damp(g, bodies[a], &bodies[b], bodies[b].radius(), shell_depths_[a] + shell_depths_[b],
                 step, dt);
        }
        for (const auto& [body, d, side] : neighbours_.walls()) {
            const auto a = static_cast<std::size_t>(body);
            const ContactGeometry<Dim> g = wall_contact(bodies[a], d, side);
            damp(g, bodies[a], nullptr, std::numeric_limits<double>::infinity(), shell_depths_[a],
                 step, dt);
        }
    }

    /// A body as the films see it.
    static FilmBody<Dim> film_body(const Particle<Dim>& b)
    {
        return {b.mass(), b.inertia(), b.is_free()};
    }

    /// lubrication.film_solve = "joint": the same films as lubricate's, every gap of the
    /// neighbour list and the walls, solved together (contact/film_solve.hpp); the free bodies
    /// take the solve's velocities, and every body the films' impulses in its forces as damp
    /// gives them.
    void lubricate_jointly(std::span<Particle<Dim>> bodies, double step, double dt)
    {
        film_bodies_.clear();
        for (const Particle<Dim>& b : bodies) {
            film_bodies_.push_back(film_body(b));
        }
        gaps_.clear();
        for (const auto& [i, j] : neighbours_.pairs()) {
            const auto a = static_cast<std::size_t>(i);
            const auto b = static_cast<std::size_t>(j);
            gaps_.push_back(
                {a, b, ball_ball_contact(ball_of(bodies[a]), ball_of(bodies[b]), domain_),
                 bodies[a].radius(), bodies[b].radius(), shell_depths_[a] + shell_depths_[b]});
        }
        for (const auto& [body, d, side] : neighbours_.walls()) {
            const auto a = static_cast<std::size_t>(body);
            gaps_.push_back({a, FilmGap<Dim>::wall, wall_contact(bodies[a], d, side),
                             bodies[a].radius(), std::numeric_limits<double>::infinity(),
                             shell_depths_[a]});
        }
        const JointFilms<Dim> films =
            joint_film_impulses<Dim>(film_bodies_, gaps_, step, lubrication_);
        unfinished_film_solves += films.n_unfinished;
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            if (bodies[b].is_free()) {
                bodies[b].contact.velocity += films.velocity_change[b];
                bodies[b].contact.omega += films.omega_change[b];
            }
        }
        for (std::size_t k = 0; k < gaps_.size(); ++k) {
            const FilmGap<Dim>& g = gaps_[k];
            const Vec<Dim>& on_second = films.on_second[k];
            if (on_second.isZero(0.0)) {
                continue;
            }
            take_film_impulse(bodies[g.first], Vec<Dim>(-on_second), g.geometry.lever_first, dt,
                              false);
            if (g.second != FilmGap<Dim>::wall) {
                take_film_impulse(bodies[g.second], on_second, g.geometry.lever_second, dt, false);
            }
        }
    }

    /// lubrication.coupling = "implicit": each body's gaps within the range at the current state
    /// (the step's start), with their corrections averaged over the gaps the start velocities would
    /// cross in Δt, appended to contact.lubrication_links (both
    /// sides of a pair; only the free bodies moved by eqs. (13)–(14) read them).
    void link(std::span<Particle<Dim>> bodies) const
    {
        for (const auto& [i, j] : neighbours_.pairs()) {
            const auto a = static_cast<std::size_t>(i);
            const auto b = static_cast<std::size_t>(j);
            const ContactGeometry<Dim> g =
                ball_ball_contact(ball_of(bodies[a]), ball_of(bodies[b]), domain_);
            const LubricationResistance c = lubrication_correction_over<Dim>(
                -g.overlap, -g.overlap - dt_ * g.overlap_rate, bodies[a].radius(),
                bodies[b].radius(), lubrication_, shell_depths_[a] + shell_depths_[b]);
            if (c.normal == 0.0 && c.tangential == 0.0) {
                continue;
            }
            const Vec<Dim> none = Vec<Dim>::Zero();
            bodies[a].contact.lubrication_links.push_back(
                {b, g.normal, g.lever_first, g.lever_second, none, c});
            bodies[b].contact.lubrication_links.push_back(
                {a, Vec<Dim>(-g.normal), g.lever_second, g.lever_first, none, c});
        }
        for (const auto& [body, d, side] : neighbours_.walls()) {
            const auto a = static_cast<std::size_t>(body);
            const ContactGeometry<Dim> g = wall_contact(bodies[a], d, side);
            const LubricationResistance c = lubrication_correction_over<Dim>(
                -g.overlap, -g.overlap - dt_ * g.overlap_rate, bodies[a].radius(),
                std::numeric_limits<double>::infinity(), lubrication_, shell_depths_[a]);
            if (c.normal == 0.0 && c.tangential == 0.0) {
                continue;
            }
            bodies[a].contact.lubrication_links.push_back(
                {LubricationLink<Dim>::wall, g.normal, g.lever_first, Vec<Dim>::Zero(),
                 walls_.velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)], c});
        }
    }

    std::vector<Vec<Dim>> force;
    std::vector<AngularVec<Dim>> torque;
    /// touched, came within the margin (or, lubrication.coupling "implicit", left a collision
    /// within the lubrication range) during the step
    std::vector<char> has_contact;
    std::vector<char> touching; ///< overlaps a body or a wall at the state last evaluated
    int in_contact = 0;
    int unfinished_film_solves = 0; ///< over the step's sub-steps (JointFilms::n_unfinished)

private:
    /// A pair apart by less than the margin counts as in contact (DemSettings::margin) but
    /// exerts no force; `second` = n is a wall. With lubrication.coupling = "implicit" so does
    /// a pair leaving a collision (the rebound rule): it touched, its gap has not opened beyond
    /// the lubrication range since, and it opens now (α̇ < 0, any rate: no threshold). Such a
    /// body is moved by the DEM until it is out of the range, as with "dem" but without the
    /// held fluid force ("auto" is none with "implicit"); both bodies of a pair are marked
    /// (docs/method.md §5, "Implicit coupling of the film": back on eqs. (13)–(14) right after
    /// the contact, a rebounding sphere met a resolved force up to 40 times its drag and lost
    /// half its speed at St 431). A gap that opens without a collision before (bodies drifting
    /// apart in a settling cloud) stays with eqs. (13)–(14): handed to the DEM, without a fluid
    /// force, such spheres fell as in vacuum (the 200-sphere soak).
    void mark_if_near(const ContactGeometry<Dim>& g, const ContactKey& key, std::size_t first,
                      std::size_t second)
    {
        const bool is_rebounding =
            lubrication_.is_enabled && lubrication_.coupling == LubricationCoupling::implicit &&
            g.overlap > -lubrication_.range && (g.overlap > 0.0 || previous_.is_rebounding(key));
        if (is_rebounding) {
            history_.rebounds.push_back({key});
        }
        if (g.overlap > -margin_ || (is_rebounding && g.overlap_rate < 0.0)) {
            mark(first, second);
        }
    }
    void mark(std::size_t first, std::size_t second)
    {
        has_contact[first] = 1;
        if (second < force.size()) {
            has_contact[second] = 1;
        }
    }

    /// The model's normal force F_n n, the friction force F_t and the rolling torque on both
    /// bodies; `second` = n is a wall. `orientation` = key_orientation of the pair as met here:
    /// the spring is stored as the key's second body's displacement relative to its first.
    void apply(const ContactGeometry<Dim>& g, std::size_t first, std::size_t second,
               const ContactKey& key, double orientation, const ContactPair& pair,
               double smaller_radius, DemOutcome& outcome)
    {
        const ContactLaw law = law_of(g, key, pair);
        Vec<Dim> on_second = law.normal_force * g.normal;
        AngularVec<Dim> rolling = zero_angular<Dim>();
        if (pair.friction > 0.0) {
            const TangentialSpring<Dim>* old = previous_.find(key);
            Vec<Dim> xi = old != nullptr ? Vec<Dim>(orientation * old->displacement)
                                         : Vec<Dim>(Vec<Dim>::Zero());
            on_second +=
                tangential_force<Dim>(g.normal, g.slip_velocity, law, pair.friction, stretch_, xi);
            history_.springs.push_back({key, Vec<Dim>(orientation * xi)});
        }
        if (pair.rolling_friction > 0.0) {
            rolling = rolling_torque<Dim>(g.rolling_omega, g.normal, law.normal_force, pair, step_);
        }
        force[first] -= on_second;
        torque[first] += cross(g.lever_first, Vec<Dim>(-on_second)) + rolling;
        if (second < force.size()) {
            force[second] += on_second;
            torque[second] += cross(g.lever_second, on_second) - rolling;
        }
        outcome.max_overlap = std::max(outcome.max_overlap, g.overlap);
        outcome.max_relative_overlap =
            std::max(outcome.max_relative_overlap, g.overlap / smaller_radius);
        mark(first, second);
        touching[first] = 1;
        if (second < force.size()) {
            touching[second] = 1;
        }
        ++in_contact;
    }

    /// The model's law for the open contact `key`. A PerContactModel's constants are those of
    /// the history if the contact was open before, else fixed now from the approach speed α̇
    /// (the contact has just opened) and the fluid step Δt; kept for the next evaluation.
    ContactLaw law_of(const ContactGeometry<Dim>& g, const ContactKey& key, const ContactPair& pair)
    {
        const NormalContact normal{g.overlap, g.overlap_rate};
        if constexpr (PerContactModel<Model>) {
            const PairCoefficients* old = previous_.find_coefficients(key);
            const NormalCoefficients k =
                old != nullptr ? old->normal : model_.coefficients(pair, g.overlap_rate, dt_);
            history_.coefficients.push_back({key, k});
            return model_.law(normal, pair, k);
        } else {
            return model_.law(normal, pair);
        }
    }

    /// One pair's (`second` null: a wall's) lubrication impulse over the coming drift of Δt_i;
    /// `shell_gap` the sum of the pair's outermost_shell_depth. The gap rate is damped by backward
    /// Euler with the resistance averaged over the drift's travel (film_step): its impulse is
    /// ∫ c_corr dh over the gap the drift then covers, exactly for a wall and to the drift's
    /// curvature for a pair, whatever Δt_i; K is the pair's inverse effective mass along the
    /// normal (1/m1 + 1/m2). The slip is damped the same way with the tangential resistance
    /// averaged over that travel, K across the normal (plus a²/J of each).
    void damp(const ContactGeometry<Dim>& g, Particle<Dim>& first, Particle<Dim>* second,
              double second_radius, double shell_gap, double step, double dt)
    {
        const FilmBody<Dim> one = film_body(first);
        const FilmBody<Dim> other = second != nullptr ? film_body(*second) : FilmBody<Dim>{};
        const std::optional<Vec<Dim>> film = lone_film_impulse<Dim>(
            {0, FilmGap<Dim>::wall, g, first.radius(), second_radius, shell_gap}, &one,
            second != nullptr ? &other : nullptr, step, lubrication_);
        if (!film) {
            return;
        }
        const Vec<Dim>& on_second = *film;
        take_film_impulse(first, Vec<Dim>(-on_second), g.lever_first, dt, true);
        if (second != nullptr) {
            take_film_impulse(*second, on_second, g.lever_second, dt, true);
        }
    }

    /// A film's impulse on body `p` at `lever` from its centre: in its mean and lubrication force
    /// and torque (impulse / `dt`), and, if `is_moved` and the body is free, in its velocity and
    /// angular velocity. A prescribed or fixed body keeps its velocity but reports the force, as
    /// it reports the resolved flow's.
    static void take_film_impulse(Particle<Dim>& p, const Vec<Dim>& impulse, const Vec<Dim>& lever,
                                  double dt, bool is_moved)
    {
        ContactState<Dim>& s = p.contact;
        const AngularVec<Dim> moment = cross(lever, impulse);
        if (is_moved && p.is_free()) {
            s.velocity += impulse / p.mass();
            s.omega += moment / p.inertia();
        }
        s.mean_force += impulse / dt;
        s.mean_torque += moment / dt;
        s.lubrication_force += impulse / dt;
        s.lubrication_torque += moment / dt;
    }

    const DemWalls<Dim>& walls_;
    const Model& model_;
    ContactHistory<Dim>& history_;
    double dt_;                    ///< the fluid step Δt [s]
    double margin_;                ///< DemSettings::margin [m]
    PeriodicDomain<Dim> domain_;   ///< the cell list's: pairs across periodic sides
    ContactHistory<Dim> previous_; ///< the springs and constants before this evaluation
    double step_ = 0.0;            ///< Δt_i [s]
    double stretch_ = 0.0;         ///< time over which the springs stretch now [s]
    std::vector<Vec<Dim>> centres_;
    std::vector<double> radii_;
    std::vector<double> shell_depths_;       ///< outermost_shell_depth of each body [m]
    NeighbourList<Dim> neighbours_;          ///< candidates for this step's sub-steps
    std::vector<FilmBody<Dim>> film_bodies_; ///< lubricate_jointly's, kept for their storage
    std::vector<FilmGap<Dim>> gaps_;         ///< lubricate_jointly's, kept for their storage
    const LubricationSettings& lubrication_;

    static double largest_radius(std::span<const Particle<Dim>> bodies)
    {
        double largest = 0.0;
        for (const Particle<Dim>& b : bodies) {
            largest = std::max(largest, b.radius());
        }
        return largest;
    }
};

template <int Dim, class Model>
DemOutcome advance_with(const Model& model, std::span<Particle<Dim>> bodies,
                        const DemWalls<Dim>& walls, const DemSettings& settings, double dt,
                        CellList<Dim>& cells, ContactHistory<Dim>& history)
{
    const std::size_t n = bodies.size();
    DemOutcome outcome;
    for (Particle<Dim>& body : bodies) {
        ContactState<Dim>& c = body.contact;
        c.centre = body.centre;
        c.velocity = body.velocity;
        c.omega = body.omega;
        c.mean_force = Vec<Dim>::Zero();
        c.mean_torque = zero_angular<Dim>();
        c.lubrication_force = Vec<Dim>::Zero();
        c.lubrication_torque = zero_angular<Dim>();
        c.lubrication_links.clear();
    }
    const double step = dt / settings.substeps;
    const double half = 0.5 * step;
    const double weight = 1.0 / settings.substeps; // each sub-step's share of the mean
    ContactForces<Dim, Model> contacts(bodies, walls, model, history, settings.margin,
                                       settings.lubrication, cells, dt);
    contacts.evaluate(bodies, cells, step, false, outcome);
    if (settings.lubrication.is_enabled &&
        settings.lubrication.coupling == LubricationCoupling::implicit) {
        contacts.link(bodies);
    }
    const auto kick = [&](std::size_t b) {
        const Particle<Dim>& body = bodies[b];
        ContactState<Dim>& c = bodies[b].contact;
        c.mean_force += 0.5 * weight * contacts.force[b];
        c.mean_torque += 0.5 * weight * contacts.torque[b];
        // The held fluid force (contact.fluid_force) acts while the body touches nothing:
        // during a contact the contact model alone acts (Kempe & Fröhlich 2012 neglect the
        // fluid force in contact, as Biegert et al. 2017 report; docs/method.md §5), unless
        // contact.fluid_force = "always" (an enduring contact keeps the fluid's drag).
        const bool is_fluid_left_out =
            contacts.touching[b] != 0 && !settings.is_fluid_force_held_in_contact;
        const Vec<Dim> fluid = is_fluid_left_out ? Vec<Dim>::Zero() : c.held_fluid_force;
        const AngularVec<Dim> fluid_torque =
            is_fluid_left_out ? zero_angular<Dim>() : c.held_fluid_torque;
        c.velocity = half_kick(c.velocity, Vec<Dim>(contacts.force[b] + c.steady_force + fluid),
                               body.mass(), settings.beta, half);
        c.omega =
            half_kick(c.omega, AngularVec<Dim>(contacts.torque[b] + c.steady_torque + fluid_torque),
                      body.inertia(), settings.beta, half);
    };
    for (int s = 0; s < settings.substeps; ++s) {
        for (std::size_t b = 0; b < n; ++b) {
            if (bodies[b].is_free()) {
                kick(b);
            }
        }
        if (settings.lubrication.is_enabled) {
            // After the half-kick, on the velocity the drift then moves with: the film's
            // impulse is its integral over the drift's travel (damp).
            contacts.lubricate(bodies, step, dt);
        }
        for (Particle<Dim>& body : bodies) {
            body.contact.centre = drift<Dim>(body.contact.centre, body.contact.velocity, step);
        }
        contacts.evaluate(bodies, cells, step, true, outcome);
        for (std::size_t b = 0; b < n; ++b) {
            if (bodies[b].is_free()) {
                kick(b);
            }
        }
    }
    for (std::size_t b = 0; b < n; ++b) {
        bodies[b].contact.is_in_contact = contacts.has_contact[b] != 0;
    }
    outcome.n_contacts = contacts.in_contact;
    outcome.n_unfinished_film_solves = contacts.unfinished_film_solves;
    return outcome;
}

} // namespace

template <int Dim>
DemOutcome advance_contacts(std::span<Particle<Dim>> bodies, const DemWalls<Dim>& walls,
                            const DemSettings& settings, double dt, CellList<Dim>& cells,
                            ContactHistory<Dim>& history)
{
    return std::visit(
        [&](const auto& model) {
            return advance_with<Dim>(model, bodies, walls, settings, dt, cells, history);
        },
        settings.model);
}

template DemOutcome advance_contacts<2>(std::span<Particle<2>>, const DemWalls<2>&,
                                        const DemSettings&, double, CellList<2>&,
                                        ContactHistory<2>&);
template DemOutcome advance_contacts<3>(std::span<Particle<3>>, const DemWalls<3>&,
                                        const DemSettings&, double, CellList<3>&,
                                        ContactHistory<3>&);

} // namespace fddem
