// SPDX-License-Identifier: MIT
#pragma once
/// Additive-correction multigrid (Hutchinson & Raithby 1986, Numer. Heat Transfer 9) for the
/// (2·Dim + 1)-point systems of the momentum equations, a_P u_P − Σ a_nb u_nb = r.
///
/// Gauss–Seidel alone damps the rough part of the error quickly but the smooth part at about
/// 1 − a_time/a_P per sweep, which is 0.8 at the paper's h = 1/64 and 0.98 at h = 1/160: the
/// SIMPLE outer iterations then spend themselves on an unconverged momentum solve (and the
/// colour order breaks the left–right symmetry of a symmetric flow). A coarse level is made by
/// merging blocks of 2^Dim unknowns: the prolongation is piecewise constant and the restriction
/// sums, so the coarse operator R A P is again a (2·Dim + 1)-point stencil whose coefficients are
/// sums of fine ones (that is what keeps the upwinded convection's M-matrix signs). Written here
/// rather than taken from hypre: hypre needs its set-up every outer iteration (the coefficients
/// change with the iterate) and MPI, whose start-up alone costs more than this whole solve.
///
/// The finest level is the caller's grid arrays (a StencilView); the coarse levels are dense,
/// x fastest, and smoothed by red-black Gauss–Seidel (rows in parallel on the larger ones).

#include "fddem/core/index.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace fddem {

/// A (2·Dim + 1)-point system stored in arrays with strides: unknown i sits at
/// origin + Σ_d i_d stride_d. Its matrix is diag(diagonal · diagonal_scale) − Σ_k a_nb[k], where
/// a_nb[2d] links to the low neighbour along d and a_nb[2d + 1] to the high one. A neighbour
/// outside [0, n) is a known value (dropped from the correction equation) unless the axis is
/// periodic, where it wraps around.
template <int Dim>
struct StencilView {
    Index<Dim> n{};
    std::array<bool, Dim> periodic{};
    std::array<std::ptrdiff_t, Dim> stride{};
    std::ptrdiff_t origin = 0;
    const double* diagonal = nullptr;
    double diagonal_scale = 1.0;
    std::array<const double*, 2 * Dim> a_nb{};

    [[nodiscard]] std::ptrdiff_t at(const Index<Dim>& i) const noexcept
    {
        std::ptrdiff_t o = origin;
        for (std::size_t d = 0; d < i.size(); ++d) {
            o += i[d] * stride[d];
        }
        return o;
    }
};

/// One coarse level: its operator, right-hand side and solution, dense and x fastest.
template <int Dim>
struct CoarseLevel {
    Index<Dim> n{};
    std::array<bool, Dim> periodic{};
    std::vector<double> diagonal;
    std::array<std::vector<double>, 2 * Dim> a_nb;
    std::vector<double> rhs;
    std::vector<double> x;

    [[nodiscard]] std::size_t size() const noexcept { return diagonal.size(); }
    [[nodiscard]] std::size_t offset(const Index<Dim>& i) const noexcept
    {
        std::size_t flat = 0;
        for (int d = Dim - 1; d >= 0; --d) {
            const auto sd = static_cast<std::size_t>(d);
            flat = flat * static_cast<std::size_t>(n[sd]) + static_cast<std::size_t>(i[sd]);
        }
        return flat;
    }
    [[nodiscard]] StencilView<Dim> view() const noexcept;
    /// The flat distance between neighbours along each axis (x fastest).
    [[nodiscard]] std::array<std::size_t, Dim> strides() const noexcept;
    /// Sizes every array for `extent` unknowns (n = extent), all zero.
    void assign_zero(const Index<Dim>& extent, const std::array<bool, Dim>& is_periodic);
};

/// The index of the coarse unknown that fine unknown `i` merges into.
template <int Dim>
[[nodiscard]] constexpr Index<Dim> coarse_index(Index<Dim> i) noexcept
{
    for (int& c : i) {
        c /= 2;
    }
    return i;
}

/// The coarse extent of a fine extent (an odd last block has one fine unknown along that axis).
template <int Dim>
[[nodiscard]] constexpr Index<Dim> coarse_extent(Index<Dim> n) noexcept
{
    for (int& c : n) {
        c = (c + 1) / 2;
    }
    return n;
}

/// The size of a level small enough to be the coarsest (swept to convergence).
inline constexpr std::size_t coarsest_level_size = 64;

/// Builds `levels` below `fine`: each the Galerkin aggregation of the one above, until a level
/// has at most `coarsest_size` unknowns or cannot shrink. Reuses the levels' storage.
template <int Dim>
void build_coarse_levels(const StencilView<Dim>& fine, std::vector<CoarseLevel<Dim>>& levels,
                         std::size_t coarsest_size = coarsest_level_size);

/// Where one process's part of a fine level split over several processes sits: its unknowns
/// are the whole level's [offset, offset + n) (StencilView::n is the part's extent), and the
/// whole level's extent is whole_n. Blocks are merged by whole-level index, so a block may
/// straddle two processes' parts.
template <int Dim>
struct LevelPart {
    Index<Dim> offset{};
    Index<Dim> whole_n{};
};

/// The unknowns of the first coarse level that the members of a part of `part_n` unknowns at
/// `part` merge into: the only ones aggregate_part (and the multigrid's restriction of a part's
/// residual) write for it.
template <int Dim>
[[nodiscard]] constexpr Box<Dim> coarse_part_box(const LevelPart<Dim>& part,
                                                 const Index<Dim>& part_n) noexcept
{
    Box<Dim> box;
    for (std::size_t d = 0; d < box.lo.size(); ++d) {
        box.lo[d] = part.offset[d] / 2;
        box.hi[d] = (part.offset[d] + part_n[d] - 1) / 2 + 1;
    }
    return box;
}

/// Adds to `coarse` the terms of R A P that this part's unknowns give: the coarse level below
/// the level `fine` is a part of, written at the blocks the part meets (coarse_part_box) and
/// nowhere else. `coarse`'s arrays hold the coarse unknowns from `origin` on (coarse.n their
/// extent; the whole coarse extent is coarse_extent(part.whole_n)), and must hold those blocks.
/// Summed over the parts (in any fixed order), these shares are build_coarse_levels' level
/// below the whole level, up to the order of the additions.
template <int Dim>
void aggregate_part(const StencilView<Dim>& fine, const LevelPart<Dim>& part,
                    const Index<Dim>& origin, CoarseLevel<Dim>& coarse);

/// Builds levels[1], levels[2], … below levels[0], which the caller has built, as
/// build_coarse_levels does below its fine level. `levels` must not be empty.
template <int Dim>
void extend_coarse_levels(std::vector<CoarseLevel<Dim>>& levels,
                          std::size_t coarsest_size = coarsest_level_size);

/// One V-cycle on levels[k], levels[k+1], …: approximately solves levels[k]'s system for
/// levels[k].x from levels[k].rhs, starting from x = 0; `sweeps` Gauss–Seidel sweeps before
/// and after each coarse correction, and sweeps until converged (at most 50) on the coarsest.
/// (solve_momentum does the finest level's part itself, on the grid arrays: a row-wise
/// restriction there is cheaper than restrict_sum's per-unknown calls.)
template <int Dim>
void coarse_v_cycle(std::vector<CoarseLevel<Dim>>& levels, std::size_t k, int sweeps);

/// Sets coarse.rhs to the sum over each block of `residual(i)` at the fine unknowns i of
/// `fine_n`, and coarse.x to 0. Blocks run in parallel; `residual` must be safe for that.
template <int Dim, class Residual>
void restrict_sum(const Index<Dim>& fine_n, Residual&& residual, CoarseLevel<Dim>& coarse);

} // namespace fddem

#include "fddem/linsolve/aggregation_multigrid_impl.hpp"
