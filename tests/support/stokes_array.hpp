// SPDX-License-Identifier: MIT
// The exact drag of periodic arrays of bodies in creeping flow, for the tests that measure how
// large a diffuse body is (docs/method.md §4, "The retraction from the Stokes drag").
#pragma once

#include "fddem/grid/loops.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cmath>
#include <numbers>

namespace fddem::test {

/// K = F / (6π μ a U) of a simple cubic array of spheres at volume fraction φ, U the mean
/// velocity over the cell: Sangani & Acrivos (1982, Int. J. Multiphase Flow 8, 343), after
/// Hasimoto (1959); their series to φ^{10/3}, accurate to 0.1 % at φ < 0.03.
inline double sphere_array_k(double phi)
{
    const double c = std::cbrt(phi);
    return 1.0 / (1.0 - 1.7601 * c + phi - 1.5593 * phi * phi + 3.9799 * std::pow(c, 8) -
                  3.0734 * std::pow(c, 10));
}

/// F / (μ U) per unit length of a square array of cylinders at area fraction φ (Sangani &
/// Acrivos 1982, Int. J. Multiphase Flow 8, 193; their dilute series).
inline double cylinder_array_resistance(double phi)
{
    return 4.0 * std::numbers::pi /
           (-0.5 * std::log(phi) - 0.738 + phi - 0.887 * phi * phi + 2.039 * phi * phi * phi);
}

/// The mean of u_x over a periodic box's x-faces: on a periodic grid the mean velocity over the
/// cell, the fluid inside the body included (held at rest, as the exact problem's body is).
template <int Dim>
double mean_x_velocity(const Simulation<Dim>& sim)
{
    const MacGrid<Dim>& grid = sim.grid();
    const double faces = static_cast<double>(grid.owned_faces(0).size());
    return sum_over(grid.communicator(), grid.owned_faces(0),
                    [&](const Index<Dim>& f) { return sim.fluid().u[0](f); }) /
           faces;
}

} // namespace fddem::test
