// SPDX-License-Identifier: MIT
#pragma once
/// summary.json of a run: what it did, how long each phase took, the build (the keys are in
/// docs/output-files.md).

#include "fddem/io/run_record.hpp"
#include "fddem/simulation/simulation.hpp"

#include <filesystem>
#include <string>

namespace fddem {

/// Writes `path` atomically; `status` is "completed", "failed: …" or "interrupted by …". On
/// `ranks` > 1 processes it adds them and rank 0's `traffic` (its messages and collectives).
template <int Dim>
void write_run_summary(const Simulation<Dim>& sim, const CaseConfig& config,
                       const RunRecord& record, const std::string& status,
                       const std::filesystem::path& path, int ranks = 1,
                       const Traffic& traffic = {});

} // namespace fddem
