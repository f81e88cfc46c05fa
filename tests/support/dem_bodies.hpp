// SPDX-License-Identifier: MIT
#pragma once
// Bodies, boxes and a sub-step driver for tests of the DEM (contact/dem_step.hpp).

#include "fddem/bodies/ball.hpp"
#include "fddem/contact/dem_step.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace fddem::test {

/// A free ball (a disk per unit depth in 2D, a sphere in 3D) of radius r [m] and density ρ
/// [kg/m³], at rest in rotation.
template <int Dim>
DemBody<Dim> ball(const Vec<Dim>& centre, const Vec<Dim>& velocity, double radius, double density,
                  const Material& material = {})
{
    const Ball<Dim> shape{2.0 * radius};
    DemBody<Dim> b;
    b.centre = centre;
    b.velocity = velocity;
    b.omega = zero_angular<Dim>();
    b.radius = radius;
    b.mass = density * shape.volume();
    b.inertia = density * shape.second_moment();
    b.is_mobile = true;
    b.steady_force = Vec<Dim>::Zero();
    b.steady_torque = zero_angular<Dim>();
    b.material = material;
    return b;
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
long run_substeps(std::vector<DemBody<Dim>>& bodies, const DemWalls<Dim>& walls,
                  const DemSettings& settings, double step, long max_steps,
                  ContactHistory<Dim>& history, Observe observe)
{
    double largest = 0.0;
    for (const DemBody<Dim>& b : bodies) {
        largest = std::max(largest, 2.0 * b.radius);
    }
    CellList<Dim> cells(walls.origin, walls.length, largest);
    DemSettings one = settings;
    one.substeps = 1;
    long s = 0;
    while (s < max_steps) {
        (void)advance_contacts<Dim>(bodies, walls, one, step, cells, history);
        ++s;
        if (!observe(bodies, history)) {
            break;
        }
    }
    return s;
}

} // namespace fddem::test
