// SPDX-License-Identifier: MIT
#pragma once
/// A split grid's arrays in pieces, one per rank, that tile the one-process storage (issue 15):
/// what lets every rank write its own part of a checkpoint, and a run on any number of ranks
/// read back the parts its block needs, without any rank holding the whole grid.
///
/// Every rank's piece is the storage entries it is the authority for: its owned cells (and
/// the faces of the same indices), widened to the edge of the storage on the sides where its
/// block reaches a side of the domain (the ghosts beyond it, and the boundary face n). These
/// boxes tile the whole storage box, so the pieces together are entry for entry the array a
/// one-process run holds (its ghosts filled the same way at the same points of the step), and
/// any block's storage, ghosts included, is covered by the pieces it overlaps.

#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <cstddef>
#include <span>

namespace fddem {

/// The storage entries this rank contributes as its piece (see the file comment).
template <int Dim>
[[nodiscard]] Box<Dim> contributed_box(const MacGrid<Dim>& grid) noexcept;

/// The boxes' common entries (an empty box, size() 0, when they share none).
template <int Dim>
[[nodiscard]] Box<Dim> intersection(const Box<Dim>& a, const Box<Dim>& b) noexcept;

/// Sets the entries of `part` (an array of `grid`, over its storage box) that lie in `piece`
/// from `values`, the piece's entries over that box, x fastest (as pack gives them); leaves the
/// others. Returns how many it set. `values` must hold piece.size() entries.
template <int Dim>
std::size_t take_overlap(const MacGrid<Dim>& grid, const Box<Dim>& piece,
                         std::span<const double> values, GridArray<Dim>& part);

} // namespace fddem
