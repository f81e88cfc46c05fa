// SPDX-License-Identifier: MIT
#include "fddem/contact/neighbour_list.hpp"

#include <algorithm>

namespace fddem {

template <int Dim>
NeighbourList<Dim>::NeighbourList(double margin, double largest_radius, const CellList<Dim>& cells)
    : margin_(margin), skin_(std::max(0.0, cells.range() - 2.0 * largest_radius - margin)),
      domain_(cells.domain())
{
}

template <int Dim>
void NeighbourList<Dim>::set_walls(const Vec<Dim>& origin, const Vec<Dim>& length,
                                   const std::array<bool, Dim>& has_walls)
{
    origin_ = origin;
    length_ = length;
    has_walls_ = has_walls;
    anchors_.clear(); // rebuild at the next refresh
}

template <int Dim>
bool NeighbourList<Dim>::refresh(std::span<const Vec<Dim>> centres, std::span<const double> radii,
                                 CellList<Dim>& cells)
{
    bool is_stale = anchors_.size() != centres.size() || anchors_.empty() || skin_ <= 0.0;
    const double limit_squared = 0.25 * skin_ * skin_;
    for (std::size_t b = 0; !is_stale && b < centres.size(); ++b) {
        is_stale = domain_.minimum_image(centres[b] - anchors_[b]).squaredNorm() > limit_squared;
    }
    if (is_stale) {
        build(centres, radii, cells);
    }
    return is_stale;
}

template <int Dim>
void NeighbourList<Dim>::build(std::span<const Vec<Dim>> centres, std::span<const double> radii,
                               CellList<Dim>& cells)
{
    ++builds_;
    anchors_.assign(centres.begin(), centres.end());
    const double reach = margin_ + skin_; // beyond touching
    cells.find_pairs(centres, found_);
    pairs_.clear();
    for (const auto& [i, j] : found_) {
        const auto a = static_cast<std::size_t>(i);
        const auto b = static_cast<std::size_t>(j);
        const double gap =
            domain_.minimum_image(centres[a] - centres[b]).norm() - radii[a] - radii[b];
        if (gap < reach) {
            pairs_.emplace_back(i, j);
        }
    }
    walls_.clear();
    for (std::size_t b = 0; b < centres.size(); ++b) {
        for (int d = 0; d < Dim; ++d) {
            if (!has_walls_[static_cast<std::size_t>(d)]) {
                continue;
            }
            const double low_gap = centres[b][d] - origin_[d] - radii[b];
            const double high_gap = origin_[d] + length_[d] - centres[b][d] - radii[b];
            if (low_gap < reach) {
                walls_.push_back({static_cast<int>(b), d, 0});
            }
            if (high_gap < reach) {
                walls_.push_back({static_cast<int>(b), d, 1});
            }
        }
    }
}

template class NeighbourList<2>;
template class NeighbourList<3>;

} // namespace fddem
