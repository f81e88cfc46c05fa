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

/// The widest cell of the box: the grid spacing that resolves a body the least.
double coarsest_cell(const DomainConfig& box);

/// The fewest cells across a body that the marker layout accepts.
inline constexpr double min_cells_across = 4.0;

/// Bodies: the right shape for the dimension, inside the box, apart, resolved by the grid.
void check_bodies(const CaseDocument& doc, const CaseConfig& c);

} // namespace fddem
