// SPDX-License-Identifier: MIT
#include "fddem/coupling/body_midplanes.hpp"

#include "fddem/contact/cell_list.hpp"

#include <algorithm>
#include <utility>

namespace fddem {

template <int Dim>
std::vector<std::vector<Midplane<Dim>>> body_midplanes(std::span<const Particle<Dim>> bodies,
                                                       const PeriodicDomain<Dim>& domain,
                                                       const Vec<Dim>& spacing, double reach_cells)
{
    std::vector<std::vector<Midplane<Dim>>> planes(bodies.size());
    // Markers lie inside their body, so one is within reach r of the plane only if half the gap
    // is below r; r is at most reach_cells Σ_d h_d (reach_along).
    const double gap_limit = 2.0 * reach_cells * spacing.sum();
    if (bodies.size() < 2 || !(gap_limit > 0.0)) {
        return planes;
    }
    std::vector<Vec<Dim>> centres;
    double largest_radius = 0.0;
    centres.reserve(bodies.size());
    for (const Particle<Dim>& body : bodies) {
        centres.push_back(body.centre);
        largest_radius = std::max(largest_radius, body.radius());
    }
    // Every pair with a gap below the limit has its centres closer than this.
    CellList<Dim> cells(domain, 2.0 * largest_radius + gap_limit);
    std::vector<std::pair<int, int>> pairs;
    cells.find_pairs(centres, pairs); // sorted, i < j
    for (const auto& [i, j] : pairs) {
        const Particle<Dim>& a = bodies[static_cast<std::size_t>(i)];
        const Particle<Dim>& b = bodies[static_cast<std::size_t>(j)];
        const Vec<Dim> apart = domain.minimum_image(b.centre - a.centre);
        const double distance = apart.norm();
        const double gap = distance - a.radius() - b.radius();
        if (!(gap < gap_limit) || !(distance > 0.0)) {
            continue; // too far, or coincident centres (no direction)
        }
        const Vec<Dim> normal = apart / distance;
        const double reach = reach_along<Dim>(normal, spacing, reach_cells);
        if (!(0.5 * gap < reach)) {
            continue; // no marker of either comes within reach
        }
        planes[static_cast<std::size_t>(i)].push_back({normal, a.radius() + 0.5 * gap, reach});
        planes[static_cast<std::size_t>(j)].push_back({-normal, b.radius() + 0.5 * gap, reach});
    }
    return planes;
}

template std::vector<std::vector<Midplane<2>>>
body_midplanes<2>(std::span<const Particle<2>>, const PeriodicDomain<2>&, const Vec<2>&, double);
template std::vector<std::vector<Midplane<3>>>
body_midplanes<3>(std::span<const Particle<3>>, const PeriodicDomain<3>&, const Vec<3>&, double);

} // namespace fddem
