// SPDX-License-Identifier: MIT
#pragma once
/// Frames for ParaView: fields/fields_NNNNNN.vtr listed in fields.pvd and, with bodies,
/// particles/particles_NNNNNN.vtp listed in particles.pvd (docs/output-files.md).
///
/// On a grid split across MPI ranks (issue 15) a frame is written in pieces, one per rank, in a
/// folder of its own, and rank 0 lists them in a parallel master file, which the .pvd lists:
/// fields/fields_NNNNNN.pvtr with fields/fields_NNNNNN/fields_NNNNNN_RRRR.vtr (the cells rank
/// RRRR owns), particles/particles_NNNNNN.pvtp with particles/particles_NNNNNN/
/// particles_NNNNNN_RRRR.vtp (the bodies whose centre lies in rank RRRR's block). No rank holds
/// more of the grid than its block for them.

#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// Writes the frame of the current time into `directory`, numbered after the last frame
/// `fields` lists (next_frame_number), and adds it to both collections. On a split grid:
/// collective, every rank writes its pieces, and only rank 0's collections are used.
template <int Dim>
void write_frame(const Simulation<Dim>& sim, const std::filesystem::path& directory,
                 PvdCollection& fields, PvdCollection& particles);

/// The file of rank `rank`'s piece of the frame `stem` (fields_000007), relative to the folder
/// of the frame's master file: fields_000007/fields_000007_0003.vtr.
[[nodiscard]] std::string piece_file(const std::string& stem, int rank,
                                     const std::string& extension);

/// One after the number of the last frame `fields` lists (fields/fields_000007.vtr: 8), 0 when it
/// lists none. Not the count of its frames: a restart leaves deleted frames out.
[[nodiscard]] std::size_t next_frame_number(const PvdCollection& fields);

/// Removes from `frames` (.pvd entries, relative to `directory`) those whose files are missing
/// (deleted by the user) and returns their names: a .pvd must list only files that exist.
std::vector<std::string> drop_missing_frames(const std::filesystem::path& directory,
                                             std::vector<std::pair<double, std::string>>& frames);

} // namespace fddem
