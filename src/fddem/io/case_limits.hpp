// SPDX-License-Identifier: MIT
#pragma once
/// What floating point and the step count can hold, checked once each key is right on its own:
/// a box whose cells can be told apart at their coordinates, and a fixed time step that lands on
/// time.end within time.max_steps. Each problem stops the reading with the file, line and key.
/// Extreme values may overflow here: call with floating-point traps held.

#include "fddem/simulation/case_config.hpp"

namespace fddem {

class CaseDocument;

/// [domain] and [time] against the limits of doubles and of the step count.
void check_limits(const CaseDocument& doc, const CaseConfig& c);

} // namespace fddem
