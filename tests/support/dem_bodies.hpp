// SPDX-License-Identifier: MIT
#pragma once
// Bodies, boxes and a sub-step driver for tests of the DEM (contact/dem_step.hpp).

#include "fddem/bodies/ball.hpp"
#include "fddem/contact/dem_step.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace fddem::test {

/// A free ball (a disk per unit depth in 2D, a sphere in 3D) of radius r [m] and density ρ
/// [kg/m³], at rest in rotation.
template <int Dim>
Particle<Dim> ball(const Vec<Dim>& centre, const Vec<Dim>& velocity, double radius, double density,
                   const Material& material = {})
{
    Particle<Dim> b;
    b.shape = Ball<Dim>{2.0 * radius};
    b.density = density;
    b.centre = centre;
    b.velocity = velocity;
    b.material = material;
    return b;
}

/// One call of advance_contacts on bodies with the ids they have (in any order), after which
/// each body takes the DEM's end state as its own.
template <int Dim>
DemOutcome step_dem_keeping_ids(std::vector<Particle<Dim>>& bodies, const DemWalls<Dim>& walls,
                                const DemSettings& settings, double dt, CellList<Dim>& cells,
                                ContactHistory<Dim>& history)
{
    const DemOutcome outcome = advance_contacts<Dim>(bodies, walls, settings, dt, cells, history);
    for (Particle<Dim>& b : bodies) {
        b.centre = b.contact.centre;
        b.velocity = b.contact.velocity;
        b.omega = b.contact.omega;
    }
    return outcome;
}

/// One call of advance_contacts on bodies numbered by their position (as the body store numbers
/// them), after which each body takes the DEM's end state as its own: the DEM alone, as the
/// paper's coupling moves a body in contact.
template <int Dim>
DemOutcome step_dem(std::vector<Particle<Dim>>& bodies, const DemWalls<Dim>& walls,
                    const DemSettings& settings, double dt, CellList<Dim>& cells,
                    ContactHistory<Dim>& history)
{
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        bodies[k].id = static_cast<int>(k);
    }
    return step_dem_keeping_ids<Dim>(bodies, walls, settings, dt, cells, history);
}

/// The box [0, length] with walls across the axes marked in `walled`.
template <int Dim>
DemWalls<Dim> box(const Vec<Dim>& length, const std::array<bool, Dim>& walled,
                  const Material& material = {})
{
    DemWalls<Dim> walls{Vec<Dim>::Zero(), length, walled};
    walls.material = material;
    return walls;
}

/// The overlap α at which `model` pushes with `load` [N] at rest (F_n(α, α̇ = 0) = load), by
/// bisection on [0, upper] [m]. Not for a model whose constants are fixed per contact.
inline double static_overlap(const AnyContactModel& model, const ContactPair& pair, double load,
                             double upper)
{
    double low = 0.0;
    double high = upper;
    for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (low + high);
        const double force = std::visit(
            [&](const auto& m) -> double {
                if constexpr (PerContactModel<std::decay_t<decltype(m)>>) {
                    throw std::invalid_argument("static_overlap: the model's constants are "
                                                "fixed per contact");
                } else {
                    return m.law({mid, 0.0}, pair).normal_force;
                }
            },
            model);
        (force < load ? low : high) = mid;
    }
    return low;
}

/// A point on axis `axis` of a Dim-vector: value `x` along `axis`, `rest` elsewhere.
template <int Dim>
Vec<Dim> along(int axis, double x, double rest = 0.0)
{
    Vec<Dim> v = Vec<Dim>::Constant(rest);
    v[axis] = x;
    return v;
}

/// Runs `settings` one DEM sub-step of `step` [s] per call of advance_contacts (as Simulation
/// calls it once per time step), calling `observe(bodies, history)` after each; stops when it
/// returns false or after `max_steps`. Returns the sub-steps taken.
template <int Dim, class Observe>
long run_substeps(std::vector<Particle<Dim>>& bodies, const DemWalls<Dim>& walls,
                  const DemSettings& settings, double step, long max_steps,
                  ContactHistory<Dim>& history, Observe observe)
{
    double largest = 0.0;
    for (const Particle<Dim>& b : bodies) {
        largest = std::max(largest, 2.0 * b.radius());
    }
    CellList<Dim> cells(walls.origin, walls.length, largest);
    DemSettings one = settings;
    one.substeps = 1;
    long s = 0;
    while (s < max_steps) {
        (void)step_dem<Dim>(bodies, walls, one, step, cells, history);
        ++s;
        if (!observe(bodies, history)) {
            break;
        }
    }
    return s;
}

} // namespace fddem::test
