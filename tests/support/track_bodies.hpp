// SPDX-License-Identifier: MIT
#pragma once

#include "fddem/simulation/simulation.hpp"

#include <algorithm>

namespace fddem::test {

/// What a run with bodies did, step by step.
struct BodyHistory {
    double first_contact = -1.0;       ///< time of the first step with a contact, −1: none
    double max_relative_overlap = 0.0; ///< largest α / r of any step
    double max_speed = 0.0;            ///< largest |U| of any body at any step
    double rest_from = -1.0; ///< time from which every body had |U| < rest_speed, −1: never
};

/// Advances to the case's end, recording contacts, overlaps, speeds and when all bodies rest.
template <int Dim>
BodyHistory run_and_track(Simulation<Dim>& sim, double rest_speed = 1e-3)
{
    BodyHistory out;
    StepReport report;
    do {
        report = sim.advance();
        const double t = sim.clock().time;
        if (report.max_overlap > 0.0 && out.first_contact < 0.0) {
            out.first_contact = t;
        }
        out.max_relative_overlap = std::max(out.max_relative_overlap, report.max_relative_overlap);
        double fastest = 0.0;
        for (const Particle<Dim>& body : sim.bodies()) {
            fastest = std::max(fastest, body.velocity.norm());
        }
        out.max_speed = std::max(out.max_speed, fastest);
        if (fastest >= rest_speed) {
            out.rest_from = -1.0;
        } else if (out.rest_from < 0.0) {
            out.rest_from = t;
        }
    } while (!sim.is_finished(report));
    return out;
}

} // namespace fddem::test
