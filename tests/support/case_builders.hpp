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

/// The case file of the program's tests (regression/test_cli.cpp, test_run_directory.cpp): a
/// 16 × 16 cavity (Re 100), 8 steps of 0.0625 s to t = 0.5, field frames at 0, 0.25 and 0.5 s,
/// and a line sample.
inline constexpr const char* small_cavity_case = R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[walls]
y_high = [1.0, 0.0]
[fluid]
density = 1.0
viscosity = 0.01
[time]
dt = 0.0625
end = 0.5
[output]
field_interval = 0.25
[[output.lines]]
name = "vertical_centerline"
from = [0.5, 0.0]
to = [0.5, 1.0]
points = 17
)";

} // namespace fddem::test
