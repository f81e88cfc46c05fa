// SPDX-License-Identifier: MIT
#pragma once

#include "fddem/simulation/simulation.hpp"

namespace fddem::test {

/// Advances until the case's end (end time, steady state or step limit); returns the last
/// report and the total outer iterations through `total_outer`.
template <int Dim>
StepReport run_to_end(Simulation<Dim>& sim, long* total_outer = nullptr)
{
    StepReport report;
    long total = 0;
    do {
        report = sim.advance();
        total += report.outer_iterations;
    } while (!sim.is_finished(report));
    if (total_outer != nullptr) {
        *total_outer = total;
    }
    return report;
}

} // namespace fddem::test
