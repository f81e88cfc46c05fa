// SPDX-License-Identifier: MIT
// The output column lists, built from the dimension, are those docs/output-files.md documents
// (and the files of earlier runs have): the 2D and 3D particles.csv, solver.csv and the line
// samples; each value of a row is written under its own column.

#include "fddem/run/line_samples.hpp"
#include "fddem/run/particle_history.hpp"
#include "fddem/run/solver_history.hpp"

#include <gtest/gtest.h>

#include <map>
#include <span>
#include <string>
#include <vector>

#include "support/csv_table.hpp"
#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

using Row = std::map<std::string, double>;

/// The one row that `append(history)` writes to a CsvHistory of `columns`, read back from the
/// file by column name.
template <class Append>
Row written_row(const std::vector<std::string>& columns, const Append& append)
{
    const std::filesystem::path path = test::fresh_test_directory("fddem_columns_") / "history.csv";
    {
        CsvHistory history(path, columns);
        append(history);
    }
    const test::CsvTable table = test::read_csv_table(path);
    EXPECT_EQ(table.columns, columns);
    EXPECT_EQ(table.rows.size(), 1U);
    Row row;
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
        row[table.columns[k]] = table.rows.at(0).at(k);
    }
    return row;
}

std::string joined(const std::vector<std::string>& columns)
{
    std::string text;
    for (const std::string& column : columns) {
        text += (text.empty() ? "" : ",") + column;
    }
    return text;
}

TEST(OutputColumns, ParticleColumnsAreTheDocumentedOnes)
{
    EXPECT_EQ(joined(particle_columns<2>()),
              "time,id,x,y,u,v,omega,theta,fx,fy,torque,contact_fx,contact_fy,contact_torque,"
              "lubrication_fx,lubrication_fy,lubrication_torque");
    EXPECT_EQ(joined(particle_columns<3>()),
              "time,id,x,y,z,u,v,w,omega_x,omega_y,omega_z,q_w,q_x,q_y,q_z,fx,fy,fz,torque_x,"
              "torque_y,torque_z,contact_fx,contact_fy,contact_fz,contact_torque_x,"
              "contact_torque_y,contact_torque_z,lubrication_fx,lubrication_fy,lubrication_fz,"
              "lubrication_torque_x,lubrication_torque_y,lubrication_torque_z");
}

TEST(OutputColumns, SampleColumnsAreTheDocumentedOnes)
{
    EXPECT_EQ(joined(sample_columns<2>()), "x,y,u,v,p");
    EXPECT_EQ(joined(sample_columns<3>()), "x,y,z,u,v,w,p");
}

TEST(OutputColumns, EachParticleValueLandsInItsColumn)
{
    BodySnapshot<2> disk{.id = 3,
                         .radius = 0.5,
                         .centre = {1.0, 2.0},
                         .velocity = {3.0, 4.0},
                         .omega = 5.0,
                         .orientation = 6.0,
                         .force = {7.0, 8.0},
                         .torque = 9.0,
                         .contact_force = {10.0, 11.0},
                         .contact_torque = 12.0,
                         .lubrication_force = {13.0, 14.0},
                         .lubrication_torque = 15.0};
    EXPECT_EQ(written_row(particle_columns<2>(),
                          [&disk](CsvHistory& history) {
                              append_particle_rows<2>(history, 0.5, std::span(&disk, 1));
                          }),
              (Row{{"time", 0.5},
                   {"id", 3.0},
                   {"x", 1.0},
                   {"y", 2.0},
                   {"u", 3.0},
                   {"v", 4.0},
                   {"omega", 5.0},
                   {"theta", 6.0},
                   {"fx", 7.0},
                   {"fy", 8.0},
                   {"torque", 9.0},
                   {"contact_fx", 10.0},
                   {"contact_fy", 11.0},
                   {"contact_torque", 12.0},
                   {"lubrication_fx", 13.0},
                   {"lubrication_fy", 14.0},
                   {"lubrication_torque", 15.0}}));

    BodySnapshot<3> sphere{.id = 7,
                           .radius = 0.5,
                           .centre = {1.0, 2.0, 3.0},
                           .velocity = {4.0, 5.0, 6.0},
                           .omega = {7.0, 8.0, 9.0},
                           .orientation = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5),
                           .force = {10.0, 11.0, 12.0},
                           .torque = {13.0, 14.0, 15.0},
                           .contact_force = {16.0, 17.0, 18.0},
                           .contact_torque = {19.0, 20.0, 21.0},
                           .lubrication_force = {22.0, 23.0, 24.0},
                           .lubrication_torque = {25.0, 26.0, 27.0}};
    EXPECT_EQ(written_row(particle_columns<3>(),
                          [&sphere](CsvHistory& history) {
                              append_particle_rows<3>(history, 0.5, std::span(&sphere, 1));
                          }),
              (Row{{"time", 0.5},
                   {"id", 7.0},
                   {"x", 1.0},
                   {"y", 2.0},
                   {"z", 3.0},
                   {"u", 4.0},
                   {"v", 5.0},
                   {"w", 6.0},
                   {"omega_x", 7.0},
                   {"omega_y", 8.0},
                   {"omega_z", 9.0},
                   {"q_w", 0.5},
                   {"q_x", 0.5},
                   {"q_y", -0.5},
                   {"q_z", 0.5},
                   {"fx", 10.0},
                   {"fy", 11.0},
                   {"fz", 12.0},
                   {"torque_x", 13.0},
                   {"torque_y", 14.0},
                   {"torque_z", 15.0},
                   {"contact_fx", 16.0},
                   {"contact_fy", 17.0},
                   {"contact_fz", 18.0},
                   {"contact_torque_x", 19.0},
                   {"contact_torque_y", 20.0},
                   {"contact_torque_z", 21.0},
                   {"lubrication_fx", 22.0},
                   {"lubrication_fy", 23.0},
                   {"lubrication_fz", 24.0},
                   {"lubrication_torque_x", 25.0},
                   {"lubrication_torque_y", 26.0},
                   {"lubrication_torque_z", 27.0}}));
}

TEST(OutputColumns, EachSolverValueLandsInItsColumn)
{
    StepReport report;
    report.outer_iterations = 3;
    report.is_converged = true;
    report.mass_residual = 1e-5;
    report.momentum_residual = 2e-5;
    report.courant = 0.25;
    report.rate_of_change = 0.125;
    report.retries = 4;
    const Clock clock{.time = 0.5, .step = 5, .dt = 0.1};
    EXPECT_EQ(written_row(
                  solver_columns(),
                  [&](CsvHistory& history) { append_solver_row(history, clock, report, 12, 2.0); }),
              (Row{{"step", 5.0},
                   {"time", 0.5},
                   {"dt", 0.1},
                   {"outer_iterations", 3.0},
                   {"total_outer_iterations", 12.0},
                   {"is_converged", 1.0},
                   {"mass_residual", 1e-5},
                   {"momentum_residual", 2e-5},
                   {"courant", 0.25},
                   {"rate_of_change", 0.125},
                   {"retries", 4.0},
                   {"wall_seconds", 2.0}}));
}

} // namespace
} // namespace fddem
