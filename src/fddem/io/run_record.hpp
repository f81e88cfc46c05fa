// SPDX-License-Identifier: MIT
#pragma once
/// What `fddem run` keeps besides the simulation: statistics for summary.json, the output
/// schedule and counters, and the lengths of the appended CSV histories. A checkpoint holds it
/// next to the simulation state, so a restarted run carries on with the same numbers and
/// continues every output file where the checkpoint's step left it.

#include "fddem/simulation/simulation.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

struct RunRecord {
    // Statistics (summary.json).
    long total_outer_iterations = 0;
    long unconverged_steps = 0;
    double max_courant = 0.0;
    bool has_warned_courant = false;
    double max_overlap = 0.0;          ///< [m]
    double max_relative_overlap = 0.0; ///< overlap / radius
    double max_overlap_time = 0.0;     ///< [s]
    bool has_warned_overlap = false;
    long unfinished_film_solves = 0; ///< StepReport::unfinished_film_solves summed
    double wall_seconds = 0.0;       ///< wall time of the time loop so far, over all processes [s]
    long restarts = 0;               ///< how often the run was continued from a checkpoint
    StepReport last;                 ///< of the last step (the steady-state test reads it)

    // Output schedule and counters.
    double next_field_time = 0.0;                                ///< [s]
    double next_particle_time = 0.0;                             ///< [s]
    double next_checkpoint_time = 0.0;                           ///< [s]
    std::vector<std::pair<double, std::string>> field_frames;    ///< fields.pvd entries
    std::vector<std::pair<double, std::string>> particle_frames; ///< particles.pvd entries
    std::uint64_t solver_csv_bytes = 0;    ///< length of solver.csv after the last step
    std::uint64_t particles_csv_bytes = 0; ///< of particles.csv (0: none)

    /// One `archive(name, member)` per member, for writing and reading alike (see
    /// io/checkpoint_archive.hpp); a new member is one more line here.
    template <class Self, class Archive>
    static void visit(Self& r, Archive& archive)
    {
        archive("run.total_outer_iterations", r.total_outer_iterations);
        archive("run.unconverged_steps", r.unconverged_steps);
        archive("run.max_courant", r.max_courant);
        archive("run.has_warned_courant", r.has_warned_courant);
        archive("run.max_overlap", r.max_overlap);
        archive("run.max_relative_overlap", r.max_relative_overlap);
        archive("run.max_overlap_time", r.max_overlap_time);
        archive("run.has_warned_overlap", r.has_warned_overlap);
        archive("run.unfinished_film_solves", r.unfinished_film_solves);
        archive("run.wall_seconds", r.wall_seconds);
        archive("run.restarts", r.restarts);
        archive("last.outer_iterations", r.last.outer_iterations);
        archive("last.is_converged", r.last.is_converged);
        archive("last.mass_residual", r.last.mass_residual);
        archive("last.momentum_residual", r.last.momentum_residual);
        archive("last.courant", r.last.courant);
        archive("last.rate_of_change", r.last.rate_of_change);
        archive("last.rigid_defect", r.last.rigid_defect);
        archive("last.body_change", r.last.body_change);
        archive("last.max_overlap", r.last.max_overlap);
        archive("last.max_relative_overlap", r.last.max_relative_overlap);
        archive("last.contacts", r.last.contacts);
        archive("output.next_field_time", r.next_field_time);
        archive("output.next_particle_time", r.next_particle_time);
        archive("output.next_checkpoint_time", r.next_checkpoint_time);
        archive("output.field_frames", r.field_frames);
        archive("output.particle_frames", r.particle_frames);
        archive("output.solver_csv_bytes", r.solver_csv_bytes);
        archive("output.particles_csv_bytes", r.particles_csv_bytes);
    }
};

} // namespace fddem
