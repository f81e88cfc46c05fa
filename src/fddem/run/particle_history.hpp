// SPDX-License-Identifier: MIT
#pragma once
/// particles.csv: one row per body per output time (docs/output-files.md).

#include "fddem/io/csv_history.hpp"
#include "fddem/run/body_snapshot.hpp"

#include <span>
#include <string>
#include <vector>

namespace fddem {

/// 2D: time,id,x,y,u,v,omega,theta,fx,fy,torque,contact_fx,contact_fy,contact_torque;
/// 3D: time,id,x,y,z,u,v,w,omega_x,omega_y,omega_z,fx,fy,fz,torque_x,torque_y,torque_z,
/// contact_fx,contact_fy,contact_fz.
template <int Dim>
[[nodiscard]] std::vector<std::string> particle_columns();

/// One row per body at simulated time `time` [s].
template <int Dim>
void append_particle_rows(CsvHistory& history, double time,
                          std::span<const BodySnapshot<Dim>> bodies);

} // namespace fddem
