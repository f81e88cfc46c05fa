// SPDX-License-Identifier: MIT
#pragma once
/// solver.csv: one row per time step (docs/output-files.md).

#include "fddem/io/csv_history.hpp"
#include "fddem/simulation/simulation.hpp"

#include <string>
#include <vector>

namespace fddem {

/// step,time,dt,outer_iterations,total_outer_iterations,is_converged,mass_residual,
/// momentum_residual,courant,rate_of_change,retries,wall_seconds
[[nodiscard]] std::vector<std::string> solver_columns();

/// The row of the step that `clock` ends and `report` describes.
void append_solver_row(CsvHistory& history, const Clock& clock, const StepReport& report,
                       long total_outer_iterations, double wall_seconds);

} // namespace fddem
