// SPDX-License-Identifier: MIT
#pragma once
/// What a run tells its user besides the outputs: the values it derived from the case, and
/// warnings about the steps (overlap, unconverged SIMPLE, Courant number), each said once or a
/// bounded number of times; the statistics behind them go to summary.json.

#include "fddem/io/run_record.hpp"
#include "fddem/run/run_monitor.hpp"
#include "fddem/simulation/simulation.hpp"

namespace fddem {

/// Says what [contact] and [nondimensional] made of the case (the values are also in case.toml).
void report_derived_values(const CaseConfig& config, RunMonitor& monitor);

/// What a run says before its first step: the memory it expects (on `n_ranks` processes, of
/// which `ranks_on_node` run on this machine), and a warning when its OpenMP threads share fewer
/// CPUs (run/thread_placement.hpp).
void report_start(const CaseConfig& config, RunMonitor& monitor, int n_ranks = 1,
                  int ranks_on_node = 1);

/// Adds the step that `report` describes and `clock` ends to the statistics of `record`, with a
/// warning to `monitor` where one is due.
void watch_step(const StepReport& report, const Clock& clock, const CaseConfig& config,
                RunRecord& record, RunMonitor& monitor);

} // namespace fddem
