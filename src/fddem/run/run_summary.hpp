// SPDX-License-Identifier: MIT
#pragma once
/// summary.json of a run: what it did, how long each phase took, the build (the keys are in
/// docs/output-files.md).

#include "fddem/io/run_record.hpp"
#include "fddem/simulation/simulation.hpp"

#include <array>
#include <filesystem>
#include <string>

namespace fddem {

/// What a split run costs rank 0 in communication, and the other ranks in memory (summary.json's
/// mpi_* keys).
struct RankCosts {
    int ranks = 1;
    double other_ranks_peak_memory_mib = 0.0; ///< the largest peak resident memory of ranks ≥ 1
    Traffic traffic;                          ///< its messages, collectives and their time
    std::array<double, n_phases> communication{}; ///< that time by phase (PhaseTimes)
};

/// Writes `path` atomically; `status` is "completed", "failed: …" or "interrupted by …". On
/// more than one rank it adds rank 0's `costs`.
template <int Dim>
void write_run_summary(const Simulation<Dim>& sim, const CaseConfig& config,
                       const RunRecord& record, const std::string& status,
                       const std::filesystem::path& path, const RankCosts& costs = {});

} // namespace fddem
