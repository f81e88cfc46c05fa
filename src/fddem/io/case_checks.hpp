// SPDX-License-Identifier: MIT
#pragma once
/// What the keys of a case say together, checked once each key is right on its own
/// (io/case_keys.cpp): a way to stop the run, walls and sides that exist, an inflow with a speed
/// and an outflow, line samples in the box, bodies in the box and apart. Each problem stops the
/// reading with the file, the line and the key.

#include "fddem/simulation/case_config.hpp"

namespace fddem {

class CaseDocument;

/// [time], [walls], [boundaries], [inflow] and [[output.lines]] together.
void check_case(const CaseDocument& doc, const CaseConfig& c);

/// Bodies: the right shape for the dimension, inside the box, apart, resolved by the grid.
void check_bodies(const CaseDocument& doc, const CaseConfig& c);

} // namespace fddem
