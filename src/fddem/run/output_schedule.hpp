// SPDX-License-Identifier: MIT
#pragma once
/// When outputs are due. Times are simulated times; an output whose time falls within half a
/// step after the end of a step is written at that step, so the rounding in t = n Δt neither
/// skips nor doubles one.

#include "fddem/simulation/simulation.hpp"

namespace fddem {

/// Whether the step that `clock` ends reaches `target` [s], to half a step.
[[nodiscard]] bool is_time_reached(const Clock& clock, double target) noexcept;

/// A periodic output (particles.csv rows, field frames): true when the one at `next_time` is due,
/// and then `next_time` moves on by `interval` [s].
[[nodiscard]] bool take_due_output(const Clock& clock, double interval, double& next_time) noexcept;

/// A checkpoint: due every `step_interval` steps (0: not by steps) and/or every `time_interval`
/// of simulated time (0: not by time); `next_time` then moves past the current time.
[[nodiscard]] bool take_due_checkpoint(const Clock& clock, long step_interval, double time_interval,
                                       double& next_time) noexcept;

} // namespace fddem
