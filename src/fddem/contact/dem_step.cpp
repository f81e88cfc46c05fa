// SPDX-License-Identifier: MIT
#include "fddem/contact/dem_step.hpp"

#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/dem_integrator.hpp"

#include <algorithm>

namespace fddem {
namespace {

template <int Dim>
BallState<Dim> ball_of(const DemBody<Dim>& b)
{
    return {b.centre, b.radius, b.velocity, b.omega};
}

/// Contact forces and torques on every body at the current state; tracks the largest overlap.
template <int Dim>
class ContactForces {
public:
    ContactForces(std::size_t n, const DemWalls<Dim>& walls, const DemSettings& settings)
        : force(n), torque(n), walls_(walls), law_(settings.law)
    {
    }

    void evaluate(std::span<const DemBody<Dim>> bodies, CellList<Dim>& cells,
                  DemOutcome<Dim>& outcome)
    {
        std::fill(force.begin(), force.end(), Vec<Dim>::Zero());
        std::fill(torque.begin(), torque.end(), zero_angular<Dim>());
        centres_.resize(bodies.size());
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            centres_[b] = bodies[b].centre;
        }
        cells.find_pairs(centres_, pairs_);
        in_contact = 0;
        for (const auto& [i, j] : pairs_) {
            const auto a = static_cast<std::size_t>(i);
            const auto b = static_cast<std::size_t>(j);
            const ContactGeometry<Dim> g =
                ball_ball_contact(ball_of(bodies[a]), ball_of(bodies[b]));
            if (g.overlap <= 0.0) {
                continue;
            }
            apply(g, a, b, std::min(bodies[a].radius, bodies[b].radius), outcome);
        }
        for (std::size_t a = 0; a < bodies.size(); ++a) {
            for (int d = 0; d < Dim; ++d) {
                if (!walls_.has_walls[static_cast<std::size_t>(d)]) {
                    continue;
                }
                for (int side = 0; side < 2; ++side) {
                    const double at = walls_.origin[d] + side * walls_.length[d];
                    const ContactGeometry<Dim> g =
                        ball_wall_contact(ball_of(bodies[a]), d, side, at);
                    if (g.overlap > 0.0) {
                        apply(g, a, bodies.size(), bodies[a].radius, outcome);
                    }
                }
            }
        }
    }

    std::vector<Vec<Dim>> force;
    std::vector<AngularVec<Dim>> torque;
    int in_contact = 0;

private:
    /// The spring–dashpot force F = kα + cα̇ along n (paper, after eq. (18)) on both bodies;
    /// `second` = n is the wall.
    void apply(const ContactGeometry<Dim>& g, std::size_t first, std::size_t second,
               double smaller_radius, DemOutcome<Dim>& outcome)
    {
        const double magnitude = law_.stiffness * g.overlap + law_.damping * g.overlap_rate;
        const Vec<Dim> on_second = magnitude * g.normal;
        force[first] -= on_second;
        torque[first] += cross(g.lever_first, Vec<Dim>(-on_second));
        if (second < force.size()) {
            force[second] += on_second;
            torque[second] += cross(g.lever_second, on_second);
        }
        outcome.max_overlap = std::max(outcome.max_overlap, g.overlap);
        outcome.max_relative_overlap =
            std::max(outcome.max_relative_overlap, g.overlap / smaller_radius);
        outcome.has_contact[first] = true;
        if (second < force.size()) {
            outcome.has_contact[second] = true;
        }
        ++in_contact;
    }

    const DemWalls<Dim>& walls_;
    LinearSpringDashpot::Params law_;
    std::vector<Vec<Dim>> centres_;
    std::vector<std::pair<int, int>> pairs_;
};

} // namespace

template <int Dim>
DemOutcome<Dim> advance_contacts(std::span<DemBody<Dim>> bodies, const DemWalls<Dim>& walls,
                                 const DemSettings& settings, double dt, CellList<Dim>& cells)
{
    const std::size_t n = bodies.size();
    DemOutcome<Dim> outcome;
    outcome.mean_force.assign(n, Vec<Dim>::Zero());
    outcome.mean_torque.assign(n, zero_angular<Dim>());
    outcome.has_contact.assign(n, false);
    ContactForces<Dim> contacts(n, walls, settings);
    contacts.evaluate(bodies, cells, outcome);

    const double step = dt / settings.substeps;
    const double half = 0.5 * step;
    const double weight = 1.0 / settings.substeps; // each sub-step's share of the mean
    for (int s = 0; s < settings.substeps; ++s) {
        for (std::size_t b = 0; b < n; ++b) {
            DemBody<Dim>& body = bodies[b];
            if (body.is_mobile) {
                outcome.mean_force[b] += 0.5 * weight * contacts.force[b];
                outcome.mean_torque[b] += 0.5 * weight * contacts.torque[b];
                body.velocity =
                    half_kick(body.velocity, Vec<Dim>(contacts.force[b] + body.steady_force),
                              body.mass, settings.beta, half);
                body.omega =
                    half_kick(body.omega, AngularVec<Dim>(contacts.torque[b] + body.steady_torque),
                              body.inertia, settings.beta, half);
            }
            body.centre = drift<Dim>(body.centre, body.velocity, step);
        }
        contacts.evaluate(bodies, cells, outcome);
        for (std::size_t b = 0; b < n; ++b) {
            DemBody<Dim>& body = bodies[b];
            if (!body.is_mobile) {
                continue;
            }
            outcome.mean_force[b] += 0.5 * weight * contacts.force[b];
            outcome.mean_torque[b] += 0.5 * weight * contacts.torque[b];
            body.velocity =
                half_kick(body.velocity, Vec<Dim>(contacts.force[b] + body.steady_force), body.mass,
                          settings.beta, half);
            body.omega =
                half_kick(body.omega, AngularVec<Dim>(contacts.torque[b] + body.steady_torque),
                          body.inertia, settings.beta, half);
        }
    }
    outcome.n_contacts = contacts.in_contact;
    return outcome;
}

template DemOutcome<2> advance_contacts<2>(std::span<DemBody<2>>, const DemWalls<2>&,
                                           const DemSettings&, double, CellList<2>&);
template DemOutcome<3> advance_contacts<3>(std::span<DemBody<3>>, const DemWalls<3>&,
                                           const DemSettings&, double, CellList<3>&);

} // namespace fddem
