// SPDX-License-Identifier: MIT
#pragma once
/// samples/<name>.csv: the fields along each [[output.lines]] segment, written at the end of a
/// run (docs/output-files.md).

#include "fddem/simulation/simulation.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fddem {

/// x,y[,z],u,v[,w],p
template <int Dim>
[[nodiscard]] std::vector<std::string> sample_columns();

/// One file per line of the case, each written atomically by the grid's rank 0. Collective on a
/// split grid: each rank samples the points in its cells, and rank 0 gathers the rows (a few
/// values per point, never the grid).
template <int Dim>
void write_line_samples(const Simulation<Dim>& sim, const std::vector<LineSample>& lines,
                        const std::filesystem::path& directory);

} // namespace fddem
