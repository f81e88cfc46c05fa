// SPDX-License-Identifier: MIT
#pragma once
/// Frames for ParaView: fields/fields_NNNNNN.vtr listed in fields.pvd and, with bodies,
/// particles/particles_NNNNNN.vtp listed in particles.pvd (docs/output-files.md).

#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// Writes the frame of the current time into `directory`, numbered after the last frame
/// `fields` lists (next_frame_number), and adds it to both collections.
template <int Dim>
void write_frame(const Simulation<Dim>& sim, const std::filesystem::path& directory,
                 PvdCollection& fields, PvdCollection& particles);

/// One after the number of the last frame `fields` lists (fields/fields_000007.vtr: 8), 0 when it
/// lists none. Not the count of its frames: a restart leaves deleted frames out.
[[nodiscard]] std::size_t next_frame_number(const PvdCollection& fields);

/// Removes from `frames` (.pvd entries, relative to `directory`) those whose files are missing
/// (deleted by the user) and returns their names: a .pvd must list only files that exist.
std::vector<std::string> drop_missing_frames(const std::filesystem::path& directory,
                                             std::vector<std::pair<double, std::string>>& frames);

} // namespace fddem
