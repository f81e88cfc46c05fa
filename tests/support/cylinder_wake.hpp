// SPDX-License-Identifier: MIT
#pragma once
// What the fixed-cylinder cases measure (cases/verification/cylinder_re20, cylinder_re40), from a
// finished 2D Simulation: the drag and lift coefficients, the length of the recirculation behind
// the cylinder on its axis and the pressure difference between its front and rear points. The
// same definitions as python/fddem/wake.py (tools/cylinder_wake.py), which reads them from a run
// directory.

#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/sampling.hpp"
#include "fddem/simulation/simulation.hpp"

#include <optional>

namespace fddem::test {

struct CylinderWake {
    double drag_coefficient = 0.0; ///< C_D = 2 F_x / (ρ Ū² D)
    double lift_coefficient = 0.0; ///< C_L = 2 F_y / (ρ Ū² D)
    /// L = x_r − x_rear, x_r the first point behind the rear where u on the axis turns from
    /// negative to positive (linear interpolation between samples h/8 apart); none if u stays
    /// negative (or never is) within `search_length` [m].
    std::optional<double> recirculation_length;
    double pressure_difference = 0.0; ///< p(front point) − p(rear point) [Pa]
    double inflow_flux = 0.0;         ///< volume flux in [m²/s]
    double outflow_flux = 0.0;        ///< volume flux out [m²/s]
};

/// The numbers of the first body (a fixed disk) of `sim`, for a reference speed Ū.
inline CylinderWake measure_cylinder_wake(const Simulation<2>& sim, double mean_velocity,
                                          double search_length)
{
    const Particle<2>& body = sim.bodies().front();
    const double diameter = body.shape.diameter;
    const double radius = 0.5 * diameter;
    const double scale =
        0.5 * sim.fluid_properties().density * mean_velocity * mean_velocity * diameter;
    CylinderWake wake;
    wake.drag_coefficient = body.force[0] / scale;
    wake.lift_coefficient = body.force[1] / scale;

    const MacGrid<2>& grid = sim.grid();
    const Vec<2> rear = body.centre + Vec<2>(radius, 0.0);
    const Vec<2> front = body.centre - Vec<2>(radius, 0.0);
    const double step = grid.spacing(0) / 8.0;
    const auto u_at = [&](double x) {
        return sample_velocity(grid, sim.fluid().u, Vec<2>(x, rear.y()))[0];
    };
    double x_previous = rear.x();
    double u_previous = u_at(x_previous);
    for (double x = rear.x() + step; x <= rear.x() + search_length; x += step) {
        const double u = u_at(x);
        if (u_previous < 0.0 && u >= 0.0) {
            const double crossing =
                x_previous + (x - x_previous) * (-u_previous) / (u - u_previous);
            wake.recirculation_length = crossing - rear.x();
            break;
        }
        x_previous = x;
        u_previous = u;
    }
    wake.pressure_difference = sample_cell_field(grid, sim.fluid().p, front) -
                               sample_cell_field(grid, sim.fluid().p, rear);
    const auto [inflow, outflow] = boundary_fluxes(grid, sim.boundary_conditions(), sim.fluid().u);
    wake.inflow_flux = inflow;
    wake.outflow_flux = outflow;
    return wake;
}

} // namespace fddem::test
