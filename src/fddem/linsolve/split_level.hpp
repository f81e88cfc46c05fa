// SPDX-License-Identifier: MIT
#pragma once
/// One coarse level of the momentum multigrid on a grid split over MPI ranks (issue 15): each
/// rank owns a box of the level's unknowns and stores it with one ghost layer around it, and
/// the ghosts are filled from their owners (fill) or sent back and added there (accumulate).
///
/// Ownership follows the fine level: coarse unknown c merges the fine unknowns 2c … 2c + 1
/// (aggregation_multigrid.hpp), and it belongs to the rank that owns fine unknown 2c. So a
/// rank owning the fine unknowns [lo, hi) along an axis owns the coarse [⌈lo/2⌉, ⌈hi/2⌉), and
/// these boxes tile the coarse level as the fine ones tile the fine level. A rank whose fine
/// block starts at an odd index also holds a member of the block below it, owned by the
/// neighbour: its share of that block's sums lands in its low ghost layer and is accumulated.
///
/// Written here rather than with grid/halo_exchange.hpp: that one exchanges the MAC grid's
/// arrays over the grid's own blocks, and these levels have their own (smaller) boxes.

#include "fddem/core/index.hpp"
#include "fddem/grid/communicator.hpp"
#include "fddem/linsolve/aggregation_multigrid.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace fddem {

/// The coarse box a rank owns when it owns the fine unknowns `fine` (whole-level indices):
/// [⌈lo/2⌉, ⌈hi/2⌉) along every axis.
template <int Dim>
[[nodiscard]] constexpr Box<Dim> coarse_owned_box(const Box<Dim>& fine) noexcept
{
    Box<Dim> box;
    for (std::size_t d = 0; d < box.lo.size(); ++d) {
        box.lo[d] = (fine.lo[d] + 1) / 2;
        box.hi[d] = (fine.hi[d] + 1) / 2;
    }
    return box;
}

/// Where a split level's ghost entries come from, as offsets into the rank's stored arrays.
struct SplitLevelRoutes {
    struct Route {
        int rank = 0;
        std::vector<std::size_t> entries; ///< in the order both ranks list them
    };
    /// One exchange: what this rank sends, what it receives, and its own periodic images.
    struct Set {
        std::vector<Route> sends;    ///< owned entries that other ranks hold as ghosts, rank order
        std::vector<Route> receives; ///< ghost entries owned by other ranks, rank order
        /// (owned, ghost): ghosts that are periodic images of this rank's own entries.
        std::vector<std::pair<std::size_t, std::size_t>> images;
    };
    Set all; ///< every ghost that some rank owns: faces, edges, corners, periodic images
    /// The face ghosts (outside the owned box along one axis only) whose owner's whole-level
    /// index sum has the parity of the colour (0 even, 1 odd): after one colour of a
    /// (2·Dim + 1)-point red–black sweep these are the only ghosts it reads that have changed.
    std::array<Set, 2> colour_faces;
};

/// A rank's part of one coarse level.
template <int Dim>
struct SplitLevel {
    Index<Dim> whole_n{};             ///< the whole level's extent
    std::array<bool, Dim> periodic{}; ///< as the fine level's
    Box<Dim> owned;                   ///< this rank's unknowns (whole-level indices)
    Box<Dim> stored;                  ///< owned.grown(1): the ghost layer around them
    /// The arrays over `stored`, x fastest (local.n its extent; local.periodic unused).
    CoarseLevel<Dim> local;
    /// Shared: they depend only on the boxes, and a later build of the same part reuses them
    /// (split_multigrid.hpp, SplitHierarchy::layout).
    std::shared_ptr<const SplitLevelRoutes> routes;

    /// The place of whole-level index `i` (inside `stored`) in the local arrays.
    [[nodiscard]] std::size_t offset(const Index<Dim>& i) const noexcept
    {
        return local.offset(i - stored.lo);
    }
    /// The owned unknowns as a fine level for aggregate_part (their part: {owned.lo, whole_n}).
    [[nodiscard]] StencilView<Dim> owned_view() const noexcept;
    [[nodiscard]] LevelPart<Dim> part() const noexcept { return {owned.lo, whole_n}; }
};

/// Every rank's `mine`, in rank order (one gather of 2·Dim integers a rank).
template <int Dim>
[[nodiscard]] std::vector<Box<Dim>> gather_owned_boxes(const Communicator& ranks,
                                                       const Box<Dim>& mine);

/// A split level whose ranks own `owned_boxes` (every rank's, in rank order; this rank is
/// `me`): this rank's box, its ghost layer, its routes, and zero arrays.
template <int Dim>
[[nodiscard]] SplitLevel<Dim> make_split_level(std::span<const Box<Dim>> owned_boxes, int me,
                                               const Index<Dim>& whole_n,
                                               const std::array<bool, Dim>& periodic);

/// Sets every ghost entry of `values` (a split level's stored array) that some rank owns, a
/// periodic image included, to the owner's value. Ghosts beyond a bounded side are left.
template <int Dim>
void fill_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                 std::vector<double>& values);

/// Sets the face ghosts of colour `colour` (SplitLevelRoutes::colour_faces) to their owners'
/// values; the other ghosts are left.
template <int Dim>
void fill_face_ghosts_of_colour(const Communicator& ranks, const SplitLevel<Dim>& level,
                                std::vector<double>& values, int colour);

/// Adds every ghost entry of `values` to the entry its owner holds, in rank order (the
/// reverse of fill_ghosts). The ghosts keep their values.
template <int Dim>
void accumulate_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                       std::vector<double>& values);

} // namespace fddem
