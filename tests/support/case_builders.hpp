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
    c.domain.dimension = 2;
    c.domain.origin = {0.0, 0.0};
    c.domain.size = {1.0, 1.0};
    c.domain.cells = {n, n};
    c.domain.periodic = {false, false};
    c.walls.velocity = {{std::vector<double>{0.0, 0.0}, std::vector<double>{0.0, 0.0}},
                        {std::vector<double>{0.0, 0.0}, std::vector<double>{1.0, 0.0}}};
    c.fluid.density = 1.0;
    c.fluid.viscosity = 1.0 / reynolds;
    c.fluid.gravity = {0.0, 0.0};
    c.fluid.body_force = {0.0, 0.0};
    c.time.dt = dt;
    c.time.end = end_time;
    return c;
}

} // namespace fddem::test
