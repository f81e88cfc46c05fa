// SPDX-License-Identifier: MIT
#pragma once
// Small programmatic cases for tests (the same keys a case file sets).

#include "fddem/simulation/case_config.hpp"

namespace fddem::test {

/// Unit-square lid-driven cavity, lid speed 1, ρ = 1, μ = 1/Re, n × n cells.
inline CaseConfig cavity_config(int n, double reynolds, double dt, double end_time)
{
    CaseConfig c;
    c.source_file = "test:cavity";
    c.dimension = 2;
    c.origin = {0.0, 0.0};
    c.size = {1.0, 1.0};
    c.cells = {n, n};
    c.periodic = {false, false};
    c.wall_velocity = {{std::vector<double>{0.0, 0.0}, std::vector<double>{0.0, 0.0}},
                       {std::vector<double>{0.0, 0.0}, std::vector<double>{1.0, 0.0}}};
    c.density = 1.0;
    c.viscosity = 1.0 / reynolds;
    c.gravity = {0.0, 0.0};
    c.body_force = {0.0, 0.0};
    c.dt = dt;
    c.end_time = end_time;
    return c;
}

} // namespace fddem::test
