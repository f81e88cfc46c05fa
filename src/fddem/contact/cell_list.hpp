// SPDX-License-Identifier: MIT
#pragma once
/// Broad phase of contact detection: a uniform cell list (Allen & Tildesley 1987, §5.3).
/// Bodies are binned by centre into cells at least as wide as the interaction range, so each
/// body is tested only against bodies in its own and the neighbouring cells: cost linear in
/// the number of bodies for a bounded density. On a periodic axis the first and last cells are
/// neighbours and distances are taken between nearest images (PeriodicDomain::minimum_image),
/// so pairs across a periodic boundary are found; a pair closer than the range through two
/// images at once (a box narrower than twice the range) is found once, through the nearer.

#include "fddem/core/periodic_domain.hpp"
#include "fddem/core/vec.hpp"

#include <span>
#include <utility>
#include <vector>

namespace fddem {

template <int Dim>
class CellList {
public:
    /// A box [origin, origin + length) and the interaction range `range` [m]: every pair whose
    /// centres are closer than `range` is found.
    CellList(const Vec<Dim>& origin, const Vec<Dim>& length, double range);
    /// The same for a box with periodic axes.
    CellList(const PeriodicDomain<Dim>& domain, double range);

    /// All pairs (i < j) with |x_i − x_j| < range (nearest images on periodic axes), sorted.
    /// Centres outside the box are wrapped on periodic axes and clamped into the edge cells on
    /// the others (they are still found).
    void find_pairs(std::span<const Vec<Dim>> centres, std::vector<std::pair<int, int>>& pairs);

    /// The interaction range [m].
    [[nodiscard]] double range() const noexcept { return range_; }
    /// The box and its periodic axes.
    [[nodiscard]] const PeriodicDomain<Dim>& domain() const noexcept { return domain_; }

    [[nodiscard]] int n_cells(int axis) const noexcept
    {
        return n_[static_cast<std::size_t>(axis)];
    }

private:
    [[nodiscard]] int cell_of(const Vec<Dim>& x) const noexcept;

    PeriodicDomain<Dim> domain_;
    Vec<Dim> cell_size_;
    std::array<int, Dim> n_{};
    double range_;
    std::vector<int> head_; ///< first body in each cell, −1 if empty
    std::vector<int> next_; ///< next body in the same cell
};

/// Reference: all pairs closer than `range` (nearest images on the periodic axes of
/// `domain`) by testing every pair (O(N²)), sorted.
template <int Dim>
[[nodiscard]] std::vector<std::pair<int, int>>
brute_force_pairs(std::span<const Vec<Dim>> centres, double range,
                  const PeriodicDomain<Dim>& domain = {});

} // namespace fddem
