// SPDX-License-Identifier: MIT
#pragma once
/// How much memory a run will take, known before anything is allocated: printed at the start of
/// every run (users size their jobs by it), and a run that would not fit stops with exit status
/// 2 and the estimate instead of failing in the allocator (std::bad_alloc, exit 1) or being
/// killed by the kernel.

#include "fddem/simulation/case_config.hpp"

#include <optional>
#include <string>

namespace fddem {

/// The estimated peak resident memory of a run of `config` [B]: a fixed part plus a measured
/// amount per cell and per marker (memory_estimate.cpp says how it was measured). Pure; no
/// overflow for any grid (the cell count is a double).
[[nodiscard]] double estimate_run_memory(const CaseConfig& config);

/// The estimated peak resident memory of the rank with the largest block of a run of `config`
/// on `n_ranks` processes [B]: the fixed part, the per-cell part for its block's cells (scaled
/// by its storage with ghosts against the whole grid's), and every body's markers (every rank
/// holds every body). On one rank, estimate_run_memory.
[[nodiscard]] double estimate_rank_memory(const CaseConfig& config, int n_ranks);

/// The memory this process may use [B]: the machine's physical memory, or its cgroup's limit
/// where that is lower; none if neither can be read.
[[nodiscard]] std::optional<double> available_memory();

/// The most a run of `config` may take [B]: run.max_memory if given, else available_memory().
[[nodiscard]] std::optional<double> run_memory_limit(const CaseConfig& config);

/// "1.23 GiB", "512 MiB": a size for messages.
[[nodiscard]] std::string memory_text(double bytes);

/// Before anything is allocated: throws InputError (naming domain.cells, with the estimate)
/// when what the ranks on this machine need exceeds `limit` [B]: on `n_ranks` processes of which
/// `ranks_on_node` share this machine, ranks_on_node × estimate_rank_memory (a run split over
/// several machines needs on each only its ranks' share).
void check_run_memory(const CaseConfig& config, std::optional<double> limit, int n_ranks = 1,
                      int ranks_on_node = 1);

/// "fddem: memory estimate 1.2 GiB for 512 × 512 cells (limit 15.6 GiB)", which every run
/// prints at its start; on several ranks it adds the largest rank's estimate and what the ranks
/// on this machine need.
[[nodiscard]] std::string memory_message(const CaseConfig& config, std::optional<double> limit,
                                         int n_ranks = 1, int ranks_on_node = 1);

} // namespace fddem
