// SPDX-License-Identifier: MIT
#pragma once
/// Frames for ParaView: fields/fields_NNNNNN.vtr listed in fields.pvd and, with bodies,
/// particles/particles_NNNNNN.vtp listed in particles.pvd (docs/output-files.md).

#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <filesystem>

namespace fddem {

/// Writes the frame of the current time into `directory`, numbered by the frames `fields`
/// already lists, and adds it to both collections.
template <int Dim>
void write_frame(const Simulation<Dim>& sim, const std::filesystem::path& directory,
                 PvdCollection& fields, PvdCollection& particles);

} // namespace fddem
