// SPDX-License-Identifier: MIT
#pragma once
/// The split of the uniform grid into Cartesian blocks, one per MPI rank (DESIGN.md §6).
///
/// Rank r owns the cells of one block: along each axis the n cells are cut into `ranks[axis]`
/// runs as evenly as possible (the first n mod p runs one cell longer), and the ranks are laid
/// out by MPI_Cart_create in the communicator's order (x fastest is MPI's row-major order with
/// the last axis fastest; fddem keeps MPI's coordinates and only uses them through this
/// struct). A face belongs to the rank of the cell above it, so the high face of a block is
/// owned by the next block, and only the last block of a bounded axis owns its boundary face n
/// (grid/mac_grid.hpp's table).
///
/// Every block has at least `min_block_cells` cells along a split axis: the halo exchange
/// fills up to that many ghost layers from one neighbour (grid/halo_exchange.hpp), so a block
/// thinner than that would need its neighbour's neighbour.

#include "fddem/core/index.hpp"
#include "fddem/grid/communicator.hpp"

#include <array>
#include <utility>
#include <vector>

namespace fddem {

/// The fewest cells a block may have along an axis that is split across ranks: the widest
/// halo layer count (MacGrid::n_ghost + 1 on a block's high side, where storage holds n + 1
/// entries).
inline constexpr int min_block_cells = 3;

/// Cells [lo, hi) of block `part` of `parts` along an axis of `n` cells.
[[nodiscard]] std::pair<int, int> block_range(int n, int parts, int part);

/// The block (part) of `parts` along an axis of `n` cells that holds cell `i` (0 ≤ i < n): the
/// inverse of block_range.
[[nodiscard]] int block_of_cell(int n, int parts, int i) noexcept;

/// The number of ranks along each axis for `n_ranks` ranks on a grid of `cells`: of all the
/// ways to write n_ranks as a product with every block at least min_block_cells thick, the one
/// with the smallest total area of block interfaces (the halo traffic), ties to splitting later
/// axes. Throws InputError (key domain.cells) when there is none.
template <int Dim>
[[nodiscard]] Index<Dim> choose_rank_layout(const Index<Dim>& cells, int n_ranks);

/// Checks a layout asked for (parallel.ranks): its product is `n_ranks` and every block is at
/// least min_block_cells thick; throws InputError (key parallel.ranks) otherwise.
template <int Dim>
void check_rank_layout(const Index<Dim>& cells, const Index<Dim>& ranks, int n_ranks);

/// This rank's part of the grid.
template <int Dim>
struct GridPartition {
    /// The Cartesian communicator of all the grid's ranks (self() on one process).
    Communicator communicator;
    /// Ranks along each axis.
    Index<Dim> ranks{};
    /// This rank's coordinates in that layout.
    Index<Dim> coords{};
    /// The cells this rank owns.
    Box<Dim> block;
    /// The ranks below and above along each axis: Communicator::no_rank beyond a side of the
    /// domain that is not periodic; across a periodic side, the rank at the other end (this
    /// rank itself when the axis is not split).
    std::array<std::pair<int, int>, Dim> neighbours{};
    /// The rank of every block, by its coordinates with the first axis fastest (MPI_Cart_rank of
    /// each; {0} on one process): which rank owns a cell (MacGrid::rank_of_point).
    std::vector<int> rank_of_block{0};
};

/// The whole grid on this process alone.
template <int Dim>
[[nodiscard]] GridPartition<Dim> whole_grid(const Index<Dim>& cells,
                                            const std::array<bool, Dim>& is_periodic);

/// The grid of `cells` split over the ranks of `comm` with `ranks` per axis (each product
/// equal to comm.size(); check_rank_layout first). Collective over `comm`.
template <int Dim>
[[nodiscard]] GridPartition<Dim> partition_grid(const Communicator& comm, const Index<Dim>& cells,
                                                const std::array<bool, Dim>& is_periodic,
                                                const Index<Dim>& ranks);

} // namespace fddem
