// SPDX-License-Identifier: MIT
#pragma once
/// The coarse levels of the momentum multigrid (aggregation_multigrid.hpp) on a grid split over
/// MPI ranks (issue 15): split levels while every rank still owns a block of the next one, then
/// one small level gathered onto one rank, which solves it and the levels below it.
///
/// Each split level is the one-process level, owned in blocks (split_level.hpp): its operator
/// R A P and each restricted residual are the sums of the ranks' shares (the shares of a block
/// that straddles two ranks added on its owner), its red–black Gauss–Seidel sweeps update one
/// colour on every rank and then fill the ghosts, and the prolongation reads the filled ghosts.
/// A colour's updates do not depend on each other, so the result is the one-process V-cycle up
/// to the order of additions. A level stays split only while its periodic extents are even
/// (an odd one makes two neighbours through the wrap the same colour, which the one-process
/// sweep then takes one after the other), it is larger than the coarsest size, and every rank
/// would own at least one unknown of the level below it.
///
/// Until the thirty-ninth session the whole first coarse level was gathered onto one rank
/// every V-cycle (1/2^Dim of the grid), and every rank allocated it whole. Now the gathered
/// level is the first one that fails the conditions above: with even periodic extents down to
/// the coarsest size, one or two unknowns per rank along each split axis (or 64 in all); but a
/// periodic extent of 2^k times an odd number stops the split at level k, which then reaches
/// the root whole (a 2D grid periodic along x with 30 cells: the first coarse level).

#include "fddem/grid/communicator.hpp"
#include "fddem/linsolve/aggregation_multigrid.hpp"
#include "fddem/linsolve/split_level.hpp"

#include <vector>

namespace fddem {

/// The levels' boxes and routes below one fine part, without their arrays: they depend only on
/// how the grid is split, so they are made once per part and reused by every later build.
template <int Dim>
struct SplitLayout {
    LevelPart<Dim> part{};               ///< the fine part they were made for
    Index<Dim> fine_n{};                 ///< its extent
    std::array<bool, Dim> periodic{};    ///< its periodic axes
    std::vector<SplitLevel<Dim>> levels; ///< local arrays empty
    std::vector<Box<Dim>> last_boxes;    ///< every rank's owned box of levels.back()

    [[nodiscard]] bool is_for(const StencilView<Dim>& fine, const LevelPart<Dim>& p) const noexcept
    {
        return !levels.empty() && part.offset == p.offset && part.whole_n == p.whole_n &&
               fine_n == fine.n && periodic == fine.periodic;
    }
};

template <int Dim>
struct SplitHierarchy {
    /// Made at the first build (one gather of every rank's box and a scan of every box) and
    /// reused after, while the fine part stays the same (build_split_levels).
    SplitLayout<Dim> layout;
    std::vector<SplitLevel<Dim>> levels; ///< levels[0] is the first coarse level
    std::vector<Box<Dim>> last_boxes;    ///< every rank's owned box of levels.back()
    /// On the root alone: levels.back() whole, then the one-process levels below it.
    std::vector<CoarseLevel<Dim>> root_levels;
};

/// The rank that solves the gathered level: the last, so that rank 0, which gathers the
/// outputs, does not also gather the coarse levels.
[[nodiscard]] inline int split_coarse_root(const Communicator& ranks) noexcept
{
    return ranks.size() - 1;
}

/// Builds the levels below `fine`, this rank's part of a level split over `ranks` (fine.n the
/// part's extent, `part` where it sits), with hierarchy.layout if it was made for this part,
/// else with a new one. The whole level must have an extent above 1. Collective, and the choice
/// is each rank's own: a hierarchy must be built under one split of the grid all along (as a
/// momentum system is, for its one velocity component), so that every rank reuses its layout
/// or makes a new one alike and none waits alone in the gather of the boxes.
template <int Dim>
void build_split_levels(const Communicator& ranks, const StencilView<Dim>& fine,
                        const LevelPart<Dim>& part, SplitHierarchy<Dim>& hierarchy);

/// One V-cycle on the split levels (what coarse_v_cycle does on one process): on entry
/// levels[0].local.rhs holds this rank's share of the restricted residual over its stored box
/// (ghosts included, zero where it has none); on return levels[0].local.x holds the
/// correction over the owned box and its ghosts. `sweeps` sweeps before and after each coarse
/// correction. Within the sweeps only the face ghosts of the colour just updated are filled
/// (what the next colour and the restriction read); at the end of a level's visit (after its
/// last post-smoothing sweep, or after the prolongation if `sweeps` is 0) all of them, which the
/// prolongation to the level above and, on the first level, the caller read.
template <int Dim>
void split_v_cycle(const Communicator& ranks, SplitHierarchy<Dim>& hierarchy, int sweeps);

} // namespace fddem
