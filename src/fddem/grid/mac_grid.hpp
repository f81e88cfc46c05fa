// SPDX-License-Identifier: MIT
#pragma once
/// The uniform staggered (MAC) grid of paper §2.2.
///
/// Staggering convention: the face `(axis, i)` is the *low* face of cell i along `axis`,
/// at x_{i−1/2}. This is the paper's convention: in eq. (7) u_ij is driven by p_ij − p_{i−1,j}.
///
///          +-----v(i,j+1)-----+
///          |                  |
///       u(i,j)    p(i,j)   u(i+1,j)        cell (i,j): centre ((i+½)h_x, (j+½)h_y)
///          |                  |            u(i,j) at x = i·h_x, v(i,j) at y = j·h_y
///          +-----v(i,j)-------+
///
/// Every array of the grid (cell or face) shares one memory layout: n + 1 entries per axis
/// plus `n_ghost` layers on each side, so a cell and the faces of the same index have the
/// same flat offset, and a neighbour along `axis` is always ±stride(axis) away.
///
/// Owned entries and ghosts (DESIGN.md §6). The process owns the cells of owned_cells() and the
/// faces of owned_faces(axis); every loop that updates values runs over them, and every other
/// entry of an array is a ghost, written only by a halo fill (grid/halo_exchange.hpp) or a
/// boundary condition (fluid/boundary_conditions.hpp). What a process owns along one axis:
///
///                  cells          faces normal to the axis      faces of other axes
///   bounded axis   [0, n)         [0, n]: both boundary faces     [0, n)
///   periodic axis  [0, n)         [0, n): face n is the image      [0, n)
///                                 of face 0 (the same face)
///
/// (A bounded axis has walls, inflows or outflows at its sides.)
///
/// A periodic axis has no boundary: index i and i + n are the same cell or face, and every
/// index outside [0, n) is the image of one inside. On one process, the owner of a periodic
/// ghost is the entry it is an image of.
///
/// Split across MPI ranks (grid/grid_partition.hpp), a process holds one Cartesian block:
/// owned_cells() is the block, [lo, hi) along each axis, indices stay global, and the arrays
/// are allocated over the block's storage, [lo, hi + 1) grown by n_ghost. In the table above
/// [0, n) becomes [lo, hi); the faces normal to an axis at the block's high side are owned by
/// the next block, except the boundary face n of a bounded axis, owned by the last block. A
/// ghost inside the domain (or across a periodic side) is then owned by the neighbouring
/// rank. cells(), cell_box() and face_box() stay the whole domain's.

#include "fddem/core/index.hpp"
#include "fddem/core/periodic_domain.hpp"
#include "fddem/core/vec.hpp"
#include "fddem/grid/communicator.hpp"
#include "fddem/grid/grid_partition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace fddem {

template <int Dim>
class MacGrid {
public:
    /// Ghost layers on every side: 2 covers the widest delta kernel (Peskin 4-point).
    static constexpr int n_ghost = 2;

    /// `cells` per axis (each ≥ 1), box `origin` and `length` [m] (each > 0), and which axes
    /// are periodic (none by default), all on this process.
    MacGrid(const Index<Dim>& cells, const Vec<Dim>& origin, const Vec<Dim>& length,
            const std::array<bool, Dim>& is_periodic = {});
    /// The same grid, of which this process holds the block of `partition` (partition_grid
    /// with the same cells and periodic axes).
    MacGrid(const Index<Dim>& cells, const Vec<Dim>& origin, const Vec<Dim>& length,
            const std::array<bool, Dim>& is_periodic, GridPartition<Dim> partition);

    [[nodiscard]] const Index<Dim>& cells() const noexcept { return cells_; }
    [[nodiscard]] int cells(int axis) const noexcept { return cells_[ax(axis)]; }
    [[nodiscard]] const Vec<Dim>& origin() const noexcept { return origin_; }
    [[nodiscard]] const Vec<Dim>& length() const noexcept { return length_; }
    /// Whether `axis` is periodic.
    [[nodiscard]] bool is_periodic(int axis) const noexcept { return is_periodic_[ax(axis)]; }
    [[nodiscard]] const std::array<bool, Dim>& periodic_axes() const noexcept
    {
        return is_periodic_;
    }
    /// The box with its periodic axes: wrapping points into it, nearest images.
    [[nodiscard]] PeriodicDomain<Dim> domain() const noexcept
    {
        return {origin_, length_, is_periodic_};
    }
    /// The processes sharing this grid; every reduction over it goes through this.
    [[nodiscard]] const Communicator& communicator() const noexcept
    {
        return partition_.communicator;
    }
    /// This process's block, its place among the ranks and its neighbours.
    [[nodiscard]] const GridPartition<Dim>& partition() const noexcept { return partition_; }
    /// Whether `axis` is split across several ranks.
    [[nodiscard]] bool is_split(int axis) const noexcept { return partition_.ranks[ax(axis)] > 1; }
    /// Cell size along `axis` [m].
    [[nodiscard]] double spacing(int axis) const noexcept { return spacing_[axis]; }
    [[nodiscard]] const Vec<Dim>& spacing() const noexcept { return spacing_; }
    /// Cell volume [m³] (area [m²] in 2D: quantities in 2D are per unit depth).
    [[nodiscard]] double cell_volume() const noexcept { return cell_volume_; }
    [[nodiscard]] std::size_t n_cells() const noexcept { return cell_box().size(); }

    /// All cells of the domain, [0, n).
    [[nodiscard]] Box<Dim> cell_box() const noexcept { return {Index<Dim>{}, cells_}; }
    /// The cells this process owns: its block (the whole domain on one process).
    [[nodiscard]] const Box<Dim>& owned_cells() const noexcept { return partition_.block; }
    /// The faces normal to `axis` this process owns: those of the owned cells (each cell owns
    /// its low face) and, on a bounded axis, the boundary face n as well if the block reaches
    /// it; on a periodic axis face n is the image of face 0 and a ghost (see the table at the
    /// top).
    [[nodiscard]] Box<Dim> owned_faces(int axis) const noexcept
    {
        Box<Dim> box = owned_cells();
        if (!is_periodic(axis) && box.hi[ax(axis)] == cells_[ax(axis)]) {
            box.hi[ax(axis)] += 1;
        }
        return box;
    }
    /// Whether this process's block reaches side `side` (0 low, 1 high) of `axis`: the ranks
    /// that apply that side's boundary condition (every rank along an axis not split).
    [[nodiscard]] bool touches_side(int axis, int side) const noexcept
    {
        return side == 0 ? partition_.block.lo[ax(axis)] == 0
                         : partition_.block.hi[ax(axis)] == cells_[ax(axis)];
    }
    /// Whether this process owns the cell holding the point x (x inside the domain, wrapped
    /// along periodic axes): the rank that interpolates and spreads a marker there.
    [[nodiscard]] bool owns_point(const Vec<Dim>& x) const noexcept
    {
        for (int d = 0; d < Dim; ++d) {
            const int i = static_cast<int>(std::floor((x[d] - origin_[d]) / spacing_[d]));
            const int clamped = i < 0 ? 0 : (i >= cells_[ax(d)] ? cells_[ax(d)] - 1 : i);
            if (clamped < partition_.block.lo[ax(d)] || clamped >= partition_.block.hi[ax(d)]) {
                return false;
            }
        }
        return true;
    }
    /// Whether some point within `reach` [m] of `centre` along every axis (wrapped along periodic
    /// axes and clamped into the domain along bounded ones, as owns_point does) may lie in a cell
    /// this process owns. Errs on the side of yes: one cell more on each side against round-off,
    /// and yes for a centre that is not finite. A body whose markers are all within `reach` of
    /// its centre has none in this process's cells when this is false (issue 15: a rank's marker
    /// loops skip the bodies it does not hold).
    [[nodiscard]] bool may_own_near(const Vec<Dim>& centre, double reach) const noexcept
    {
        for (int d = 0; d < Dim; ++d) {
            const double n = cells_[ax(d)];
            const double lo = partition_.block.lo[ax(d)];
            const double hi = partition_.block.hi[ax(d)];
            if (lo == 0.0 && hi == n) {
                continue; // the whole axis
            }
            double first = std::floor((centre[d] - reach - origin_[d]) / spacing_[d]) - 1.0;
            double last = std::floor((centre[d] + reach - origin_[d]) / spacing_[d]) + 1.0;
            if (!std::isfinite(first) || !std::isfinite(last)) {
                return true;
            }
            if (!is_periodic_[ax(d)]) {
                first = std::clamp(first, 0.0, n - 1.0);
                last = std::clamp(last, 0.0, n - 1.0);
                if (last < lo || first >= hi) {
                    return false;
                }
                continue;
            }
            if (last - first + 1.0 >= n) {
                continue; // the images cover the whole axis
            }
            const double shift = std::floor(first / n) * n; // first into [0, n)
            first -= shift;
            last -= shift; // < first + n < 2n
            const bool meets = (first < hi && std::min(last, n - 1.0) >= lo) ||
                               (last >= n && last - n >= lo); // the part past n wraps to 0
            if (!meets) {
                return false;
            }
        }
        return true;
    }
    /// The rank that owns the cell holding the point x (the cell clamped into the domain, as in
    /// owns_point): the one that interpolates and spreads a marker there.
    [[nodiscard]] int rank_of_point(const Vec<Dim>& x) const noexcept
    {
        std::size_t block = 0;
        std::size_t stride = 1;
        for (int d = 0; d < Dim; ++d) {
            const int i = static_cast<int>(std::floor((x[d] - origin_[d]) / spacing_[d]));
            const int clamped = i < 0 ? 0 : (i >= cells_[ax(d)] ? cells_[ax(d)] - 1 : i);
            const int parts = partition_.ranks[ax(d)];
            block +=
                stride * static_cast<std::size_t>(block_of_cell(cells_[ax(d)], parts, clamped));
            stride *= static_cast<std::size_t>(parts);
        }
        return partition_.rank_of_block[block];
    }
    /// All faces normal to `axis` from 0 to n (on a periodic axis face n is a ghost:
    /// owned_faces is the box to update).
    [[nodiscard]] Box<Dim> face_box(int axis) const noexcept
    {
        return {Index<Dim>{}, cells_ + unit<Dim>(axis)};
    }
    /// The box every array is allocated over: the owned cells' [lo, hi + 1) per axis, plus
    /// ghosts ([−n_ghost, n + 1 + n_ghost) on one process).
    [[nodiscard]] Box<Dim> storage_box() const noexcept
    {
        Box<Dim> b = owned_cells();
        for (int d = 0; d < Dim; ++d) {
            b.hi[ax(d)] += 1;
        }
        return b.grown(n_ghost);
    }

    /// The storage box of the same grid on one process, [−n_ghost, n + 1 + n_ghost): the
    /// same on every rank. A point whose kernel support fits in it fits in the storage of the
    /// rank that owns it (owns_point), whose block's storage reaches n_ghost beyond the block.
    [[nodiscard]] Box<Dim> whole_storage_box() const noexcept
    {
        Box<Dim> b = cell_box();
        for (int d = 0; d < Dim; ++d) {
            b.hi[ax(d)] += 1;
        }
        return b.grown(n_ghost);
    }

    [[nodiscard]] Vec<Dim> cell_centre(const Index<Dim>& cell) const noexcept;
    /// Centre of the low face of `cell` along `axis`.
    [[nodiscard]] Vec<Dim> face_centre(int axis, const Index<Dim>& cell) const noexcept;

    /// Flat offset of an index into any array of this grid.
    [[nodiscard]] std::ptrdiff_t offset(const Index<Dim>& i) const noexcept
    {
        std::ptrdiff_t off = 0;
        for (int d = 0; d < Dim; ++d) {
            off += static_cast<std::ptrdiff_t>(i[ax(d)] - storage_lo_[ax(d)]) * stride_[ax(d)];
        }
        return off;
    }
    /// The lowest index of the storage box along each axis.
    [[nodiscard]] const Index<Dim>& storage_lo() const noexcept { return storage_lo_; }
    [[nodiscard]] std::ptrdiff_t stride(int axis) const noexcept { return stride_[ax(axis)]; }
    [[nodiscard]] std::size_t storage_size() const noexcept { return storage_size_; }

private:
    static constexpr std::size_t ax(int axis) noexcept { return static_cast<std::size_t>(axis); }

    Index<Dim> cells_;
    Vec<Dim> origin_;
    Vec<Dim> length_;
    std::array<bool, Dim> is_periodic_;
    GridPartition<Dim> partition_;
    Vec<Dim> spacing_;
    double cell_volume_;
    std::array<std::ptrdiff_t, Dim> stride_{};
    Index<Dim> storage_lo_{};
    std::size_t storage_size_;
};

} // namespace fddem
