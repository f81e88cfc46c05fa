// SPDX-License-Identifier: MIT
#include "fddem/run/particle_history.hpp"

#include "fddem/run/csv_columns.hpp"

namespace fddem {
namespace {

/// The one list of particles.csv's columns, for 2D and 3D (csv_columns.hpp). The orientation is
/// θ in 2D and the unit quaternion q_w, q_x, q_y, q_z (body frame → world frame) in 3D.
template <int Dim>
auto particle_row(double time, const BodySnapshot<Dim>& body)
{
    return [time, &body](auto& visit) {
        visit(ColumnName{"time"}, time);
        visit(ColumnName{"id"}, static_cast<double>(body.id));
        visit_components<Dim>(visit, "", axis_names, body.centre);
        visit_components<Dim>(visit, "", velocity_names, body.velocity);
        visit_angular<Dim>(visit, "omega", body.omega);
        if constexpr (Dim == 2) {
            visit(ColumnName{"theta"}, body.orientation);
        } else {
            visit(ColumnName{"q_w"}, body.orientation.w());
            visit(ColumnName{"q_x"}, body.orientation.x());
            visit(ColumnName{"q_y"}, body.orientation.y());
            visit(ColumnName{"q_z"}, body.orientation.z());
        }
        visit_components<Dim>(visit, "f", axis_names, body.force);
        visit_angular<Dim>(visit, "torque", body.torque);
        visit_components<Dim>(visit, "contact_f", axis_names, body.contact_force);
        visit_angular<Dim>(visit, "contact_torque", body.contact_torque);
        visit_components<Dim>(visit, "lubrication_f", axis_names, body.lubrication_force);
        visit_angular<Dim>(visit, "lubrication_torque", body.lubrication_torque);
    };
}

} // namespace

template <int Dim>
std::vector<std::string> particle_columns()
{
    const BodySnapshot<Dim> any;
    return column_names(particle_row<Dim>(0.0, any));
}

template <int Dim>
void append_particle_rows(CsvHistory& history, double time,
                          std::span<const BodySnapshot<Dim>> bodies)
{
    std::vector<double> values;
    for (const BodySnapshot<Dim>& body : bodies) {
        row_values(particle_row<Dim>(time, body), values);
        history.append(values);
    }
}

template std::vector<std::string> particle_columns<2>();
template std::vector<std::string> particle_columns<3>();
template void append_particle_rows(CsvHistory&, double, std::span<const BodySnapshot<2>>);
template void append_particle_rows(CsvHistory&, double, std::span<const BodySnapshot<3>>);

} // namespace fddem
