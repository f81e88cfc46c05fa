// SPDX-License-Identifier: MIT
#pragma once
/// A split grid's arrays brought together whole on one rank, and whole arrays handed back out
/// to the blocks (issue 15): what lets the outputs and the checkpoints of a run on several
/// ranks be written by rank 0 in exactly the form a one-process run writes them.
///
/// Every rank contributes the storage entries it is the authority for: its owned cells (and
/// the faces of the same indices), widened to the edge of the storage on the sides where its
/// block reaches a side of the domain (the ghosts beyond it, and the boundary face n). These
/// boxes tile the whole storage box, so the gathered array is entry for entry the array a
/// one-process run holds (its ghosts filled the same way at the same points of the step).

#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

namespace fddem {

/// The storage entries this rank contributes to a gathered array (see the file comment).
template <int Dim>
[[nodiscard]] Box<Dim> contributed_box(const MacGrid<Dim>& grid) noexcept;

/// Gathers `part`, an array of the split grid `grid`, onto the grid's rank 0 as `whole`, an
/// array of the same grid on one process (only rank 0's `whole` is written). Collective over
/// the grid's ranks. On one process, a copy.
template <int Dim>
void gather_to_root(const MacGrid<Dim>& grid, const GridArray<Dim>& part, GridArray<Dim>& whole);

/// Sets every storage entry of `part` (an array of `grid`) from `whole`, the whole array
/// (of the same grid on one process) held by this rank: the reverse of gather_to_root, ghosts
/// included (a ghost inside the domain takes its owner's value).
template <int Dim>
void take_block(const MacGrid<Dim>& grid, const GridArray<Dim>& whole, GridArray<Dim>& part);

} // namespace fddem
