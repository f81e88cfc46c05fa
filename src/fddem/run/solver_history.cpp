// SPDX-License-Identifier: MIT
#include "fddem/run/solver_history.hpp"

#include "fddem/run/csv_columns.hpp"

namespace fddem {
namespace {

/// The one list of solver.csv's columns (csv_columns.hpp).
auto solver_row(const Clock& clock, const StepReport& report, long total_outer_iterations,
                double wall_seconds)
{
    return [clock, report, total_outer_iterations, wall_seconds](auto& visit) {
        visit(ColumnName{"step"}, static_cast<double>(clock.step));
        visit(ColumnName{"time"}, clock.time);
        visit(ColumnName{"dt"}, clock.dt);
        visit(ColumnName{"outer_iterations"}, static_cast<double>(report.outer_iterations));
        visit(ColumnName{"total_outer_iterations"}, static_cast<double>(total_outer_iterations));
        visit(ColumnName{"is_converged"}, report.is_converged ? 1.0 : 0.0);
        visit(ColumnName{"mass_residual"}, report.mass_residual);
        visit(ColumnName{"momentum_residual"}, report.momentum_residual);
        visit(ColumnName{"courant"}, report.courant);
        visit(ColumnName{"rate_of_change"}, report.rate_of_change);
        visit(ColumnName{"retries"}, static_cast<double>(report.retries));
        visit(ColumnName{"wall_seconds"}, wall_seconds);
    };
}

} // namespace

std::vector<std::string> solver_columns()
{
    return column_names(solver_row(Clock{}, StepReport{}, 0, 0.0));
}

void append_solver_row(CsvHistory& history, const Clock& clock, const StepReport& report,
                       long total_outer_iterations, double wall_seconds)
{
    std::vector<double> values;
    row_values(solver_row(clock, report, total_outer_iterations, wall_seconds), values);
    history.append(values);
}

} // namespace fddem
