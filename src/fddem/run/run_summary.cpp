// SPDX-License-Identifier: MIT
#include "fddem/run/run_summary.hpp"

#include "fddem/io/build_info.hpp"
#include "fddem/io/case_names.hpp"
#include "fddem/io/summary.hpp"
#include "fddem/run/body_snapshot.hpp"

#include <fmt/format.h>

namespace fddem {
namespace {

std::string momentum_solver_text(const MomentumSettings& momentum)
{
    return momentum.cycles > 0 ? fmt::format("multigrid ({} V-cycle(s) of {} sweeps)",
                                             momentum.cycles, momentum.sweeps)
                               : fmt::format("Gauss-Seidel ({} sweeps)", momentum.sweeps);
}

/// Wall time by phase of the time loop; what the phases do not account for is "other".
template <int Dim>
void set_phase_times(RunSummary& summary, const Simulation<Dim>& sim, double stepping)
{
    const PhaseTimes& times = sim.phase_times();
    for (const Phase phase : {Phase::momentum, Phase::pressure, Phase::coupling, Phase::contact}) {
        summary.set_phase_seconds(std::string(phase_name(phase)), times[phase]);
    }
    summary.set_phase_seconds("other", stepping - times.total());
}

/// The keys of a run with bodies.
template <int Dim>
void set_body_values(RunSummary& summary, const Simulation<Dim>& sim, const CaseConfig& config,
                     const RunRecord& record)
{
    summary.set("bodies", static_cast<long>(config.bodies.size()));
    summary.set("markers_per_body", static_cast<long>(markers_per_body(sim)));
    summary.set("last_rigid_defect", record.last.rigid_defect);
    summary.set("contact_model", name_of(config.contact.model));
    summary.set("max_overlap", record.max_overlap);
    summary.set("max_relative_overlap", record.max_relative_overlap);
    summary.set("max_overlap_time", record.max_overlap_time);
    if (const auto since = sim.at_rest_since()) {
        summary.set("at_rest_since", *since); // every free body below time.rest_speed
    }
    if (config.nondimensional.reynolds) {
        const double velocity = config.nondimensional.velocity;
        summary.set("characteristic_velocity", velocity);
        summary.set("characteristic_time", config.bodies.front().diameter / velocity);
    }
}

} // namespace

template <int Dim>
void write_run_summary(const Simulation<Dim>& sim, const CaseConfig& config,
                       const RunRecord& record, const std::string& status,
                       const std::filesystem::path& path, const RankCosts& costs)
{
    const StepReport& last = record.last;
    RunSummary summary;
    summary.set("status", status);
    summary.set("steps", sim.clock().step);
    summary.set("time", sim.clock().time);
    summary.set("total_outer_iterations", record.total_outer_iterations);
    summary.set("unconverged_steps", record.unconverged_steps);
    if (config.lubrication.is_enabled &&
        config.lubrication.film_solve == LubricationFilmSolve::joint) {
        summary.set("unfinished_film_solves", record.unfinished_film_solves);
    }
    summary.set("max_courant", record.max_courant);
    if (config.time.max_courant) { // the limits a step is retried at (time_step_control.hpp)
        const RetrySettings& retry = sim.retry_settings();
        summary.set("max_retries", static_cast<long>(retry.max_retries));
        summary.set("min_dt", sim.shortest_step());
        if (retry.courant) {
            summary.set("retry_courant", *retry.courant);
        }
        if (retry.mass_residual) {
            summary.set("retry_mass_residual", *retry.mass_residual);
        }
    }
    summary.set("last_mass_residual", last.mass_residual);
    summary.set("last_momentum_residual", last.momentum_residual);
    summary.set("last_rate_of_change", last.rate_of_change);
    summary.set("cells", static_cast<long>(sim.grid().n_cells()));
    summary.set("pressure_solver", sim.pressure_solver().name());
    summary.set("momentum_solver", momentum_solver_text(sim.momentum_settings()));
    summary.set("wall_seconds_stepping", record.wall_seconds);
    summary.set("restarts", record.restarts);
    summary.set("peak_memory_mib", peak_memory_mib());
    for (const auto& [name, value] : build_info()) {
        summary.set("build_" + name, value);
    }
    set_phase_times(summary, sim, record.wall_seconds);
    if (costs.ranks > 1) {
        const Traffic& traffic = costs.traffic;
        summary.set("mpi_ranks", static_cast<long>(costs.ranks));
        summary.set("mpi_other_ranks_peak_memory_mib", costs.other_ranks_peak_memory_mib);
        summary.set("mpi_rank0_messages", traffic.messages);
        summary.set("mpi_rank0_message_bytes", traffic.bytes);
        summary.set("mpi_rank0_collectives", traffic.collectives);
        summary.set("mpi_rank0_collective_bytes", traffic.collective_bytes);
        summary.set("mpi_rank0_collective_received_bytes", traffic.collective_received_bytes);
        summary.set("mpi_rank0_all_to_alls", traffic.all_to_alls);
        summary.set("mpi_rank0_all_to_all_bytes", traffic.all_to_all_bytes);
        // Wall time in fddem's own halo exchanges and collectives (hypre's not seen), in all
        // and by phase, since this process started (a restart begins them again).
        summary.set("mpi_rank0_communication_seconds", traffic.seconds);
        for (const Phase phase :
             {Phase::momentum, Phase::pressure, Phase::coupling, Phase::contact}) {
            summary.set(fmt::format("mpi_rank0_communication_seconds_{}", phase_name(phase)),
                        costs.communication[static_cast<std::size_t>(phase)]);
        }
    }
    if (!config.bodies.empty()) {
        set_body_values(summary, sim, config, record);
    }
    summary.write(path);
}

template void write_run_summary(const Simulation<2>&, const CaseConfig&, const RunRecord&,
                                const std::string&, const std::filesystem::path&, const RankCosts&);
template void write_run_summary(const Simulation<3>&, const CaseConfig&, const RunRecord&,
                                const std::string&, const std::filesystem::path&, const RankCosts&);

} // namespace fddem
