// SPDX-License-Identifier: MIT
#pragma once
/// Running a case, for the `fddem` program, a test or a binding: one call runs a case into its
/// run directory (docs/output-files.md) or continues one from its newest checkpoint, and says
/// how the run ended. Progress, messages and interrupts go through the caller's RunMonitor; bad
/// input throws InputError before anything is written, an unwritable file OutputError.

#include "fddem/grid/communicator.hpp"
#include "fddem/run/driver.hpp"
#include "fddem/run/run_monitor.hpp"
#include "fddem/simulation/case_config.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fddem {

/// A new run of `config` in `directory`: the memory estimate said (and a run that would not fit
/// refused), the directory locked against other processes (io/run_lock.hpp) and created (it must
/// not hold files, unless `overwrite`: then the old run's outputs are removed, and nothing else),
/// the initial outputs written, and the case stepped to its end with outputs and checkpoints on
/// their schedule. A numerical failure stops the run at the last good step, with its outputs
/// closed and a checkpoint of it; so does an interrupt from the monitor. On several `ranks`
/// the grid is split over them and rank 0 writes (Driver).
RunResult run_case(const CaseConfig& config, const std::filesystem::path& directory,
                   RunMonitor& monitor, bool overwrite = false,
                   const Communicator& ranks = Communicator::self());

/// The case of the run in `directory`, to continue it: its case.toml read with `overrides`
/// (section.key=value, as --set). Throws InputError if `directory` is not a run directory or
/// has no checkpoint, or (`check_lock`: one process of those running it) if another process
/// holds the directory.
[[nodiscard]] CaseConfig read_restart_case(const std::filesystem::path& directory,
                                           const std::vector<std::string>& overrides,
                                           bool check_lock = true);

/// Continues the run in `directory` (`fddem run --restart`) with `config` (read_restart_case):
/// the directory locked and checked writable, the memory estimate said, before any work; its
/// newest usable checkpoint restored, its outputs cut back to that step, and the case
/// stepped to its end as run_case does. With `rewrite_case` (the case was changed by
/// overrides), case.toml is written anew. A run already at the end of its case is left as it
/// is (`completed`).
/// On several `ranks`, rank 0 reads the checkpoint and hands each rank its block: a run
/// continues on any number of processes (Driver::resume).
RunResult restart_run(const CaseConfig& config, const std::filesystem::path& directory,
                      RunMonitor& monitor, bool rewrite_case = false,
                      const Communicator& ranks = Communicator::self());

} // namespace fddem
