// SPDX-License-Identifier: MIT
#pragma once
/// The decaying Taylor–Green vortex in the periodic box [0, 2π]²: u = sin x cos y e^{−2νt},
/// v = −cos x sin y e^{−2νt} (test_taylor_green.cpp, test_time_order.cpp).

#include "fddem/grid/loops.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cmath>
#include <numbers>

#include "support/case_builders.hpp"

namespace fddem::test {

/// An n² periodic box [0, 2π]² with ν = 1/reynolds (ρf = 1), no walls.
inline CaseConfig taylor_green_config(int n, double reynolds, double dt, double end_time)
{
    const double length = 2.0 * std::numbers::pi;
    CaseConfig config = cavity_config(n, reynolds, dt, end_time);
    config.domain.size = {length, length};
    config.domain.periodic = {true, true};
    config.walls.velocity.clear();
    return config;
}

/// The vortex at t = 0 (unit amplitude) on the faces of `sim`.
inline void set_taylor_green_vortex(Simulation<2>& sim)
{
    const auto& grid = sim.grid();
    for_each_index(grid.face_box(0), [&](const Index<2>& c) {
        const Vec<2> x = grid.face_centre(0, c);
        sim.fluid().u[0](c) = std::sin(x[0]) * std::cos(x[1]);
    });
    for_each_index(grid.face_box(1), [&](const Index<2>& c) {
        const Vec<2> x = grid.face_centre(1, c);
        sim.fluid().u[1](c) = -std::cos(x[0]) * std::sin(x[1]);
    });
}

/// ½ ∫ |u|² over the box, from the face values of each cell [kg/s² per unit density and depth].
inline double kinetic_energy(const Simulation<2>& sim)
{
    const auto& grid = sim.grid();
    double e = 0.0;
    for (int a = 0; a < 2; ++a) {
        e += sum_over(grid.communicator(), grid.owned_cells(), [&](const Index<2>& c) {
            return 0.5 * std::pow(sim.fluid().u[a](c), 2) * grid.cell_volume();
        });
    }
    return e;
}

} // namespace fddem::test
