// SPDX-License-Identifier: MIT
#pragma once
/// Verlet neighbour list for the DEM sub-steps (Verlet 1967; Allen & Tildesley 1987, §5.3):
/// the candidate pairs and wall contacts of a time step's sub-steps, found once by the cell
/// list with a reach `skin` beyond the contact range and kept until some body has moved more
/// than skin/2 since. A pair missing from the list was farther apart than contact + margin +
/// skin when it was built, and two bodies that each moved less than skin/2 have closed that
/// gap by less than skin: no contact and no near miss (DemSettings::margin) is ever missed
/// that the cell list itself would find. Distances are between nearest images on the cell
/// list's periodic axes, so pairs across a periodic boundary are kept like any other.
///
/// Why: the DEM takes thousands of sub-steps per fluid step (2299 in the paper's cases with
/// k = 1e7), and rebuilding the cell list at every one of them was most of the contact time.

#include "fddem/contact/cell_list.hpp"
#include "fddem/core/vec.hpp"

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace fddem {

/// A body that may touch a box wall: the wall at `side` (0 low, 1 high) of `axis`.
struct WallCandidate {
    int body;
    int axis;
    int side;
};

template <int Dim>
class NeighbourList {
public:
    /// `margin`: the near-miss distance that counts as contact (DemSettings::margin) [m]. The
    /// skin is what the cell list reaches beyond the largest contact-plus-margin distance of two
    /// bodies (2 r_max + margin), so a cell list of range 2 r_max + margin + s gives skin s, and
    /// one of range 2 r_max + margin gives none: the list is then rebuilt at every refresh.
    NeighbourList(double margin, double largest_radius, const CellList<Dim>& cells);

    /// Box walls on the non-periodic axes of [origin, origin + length].
    void set_walls(const Vec<Dim>& origin, const Vec<Dim>& length,
                   const std::array<bool, Dim>& has_walls);

    /// Makes the candidates valid for `centres` (radii as given): rebuilt if never built, if
    /// the number of bodies changed, or if a body moved more than skin/2 since the last
    /// build. Returns whether it rebuilt.
    bool refresh(std::span<const Vec<Dim>> centres, std::span<const double> radii,
                 CellList<Dim>& cells);

    /// Candidate pairs (i < j), sorted; a superset of the pairs closer than contact + margin.
    [[nodiscard]] const std::vector<std::pair<int, int>>& pairs() const noexcept { return pairs_; }
    /// Candidate wall contacts, ordered by body, axis, side.
    [[nodiscard]] const std::vector<WallCandidate>& walls() const noexcept { return walls_; }
    [[nodiscard]] double skin() const noexcept { return skin_; }
    [[nodiscard]] long builds() const noexcept { return builds_; }

private:
    void build(std::span<const Vec<Dim>> centres, std::span<const double> radii,
               CellList<Dim>& cells);

    double margin_;
    double skin_;
    PeriodicDomain<Dim> domain_; ///< the cell list's: nearest images on its periodic axes
    Vec<Dim> origin_ = Vec<Dim>::Zero();
    Vec<Dim> length_ = Vec<Dim>::Zero();
    std::array<bool, Dim> has_walls_{};
    std::vector<Vec<Dim>> anchors_; ///< the centres at the last build
    std::vector<std::pair<int, int>> pairs_;
    std::vector<std::pair<int, int>> found_;
    std::vector<WallCandidate> walls_;
    long builds_ = 0;
};

} // namespace fddem
