// SPDX-License-Identifier: MIT
#include "fddem/run/wall_proximity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace fddem {

template <int Dim>
double gap_to_walls(const Vec<Dim>& centre, double radius, const PeriodicDomain<Dim>& domain,
                    const BoundaryConditions<Dim>& bc, const Vec<Dim>& spacing) noexcept
{
    double gap = std::numeric_limits<double>::infinity();
    for (int d = 0; d < Dim; ++d) {
        if (bc.periodic(d)) {
            continue;
        }
        const double low = centre[d] - radius - domain.origin[d];
        const double high = domain.origin[d] + domain.length[d] - centre[d] - radius;
        for (const auto& [side, distance] : {std::pair{0, low}, std::pair{1, high}}) {
            if (bc.side_kind(d, side) != BoundaryKind::outflow) {
                gap = std::min(gap, distance / spacing[d]);
            }
        }
    }
    return gap;
}

bool has_shallow_ring_at_walls(const CouplingConfig& coupling) noexcept
{
    const double full_reach = default_wall_marker_reach(support_radius(coupling.kernel));
    const bool is_mended = coupling.is_wall_marker_off &&
                           coupling.wall_marker_reach.value_or(full_reach) >= full_reach;
    return coupling.markers != MarkerLayout::paper &&
           coupling.marker_retraction < shallow_ring_depth && !is_mended;
}

template <int Dim>
std::optional<std::string>
wall_ring_warning(const Particles<Dim>& bodies, const PeriodicDomain<Dim>& domain,
                  const BoundaryConditions<Dim>& bc, const Vec<Dim>& spacing,
                  const CouplingConfig& coupling, double time)
{
    if (!has_shallow_ring_at_walls(coupling)) {
        return std::nullopt;
    }
    for (const Particle<Dim>& body : bodies) {
        const double gap = gap_to_walls<Dim>(body.centre, body.radius(), domain, bc, spacing);
        if (gap < near_wall_gap) {
            return fmt::format(
                "warning: t = {:g} s: body id {} is {:.2f} cells from a wall with its outermost "
                "markers {:g} cells inside its surface (coupling.marker_retraction): there the "
                "resolved force grows as Δt shrinks and is not a converged quantity "
                "(docs/method.md §5, \"The retracted ring beside a wall\"); "
                "coupling.markers_off_at_walls = true, at no less than its default "
                "coupling.markers_off_reach, keeps it bounded in Δt",
                time, body.id, gap, coupling.marker_retraction);
        }
    }
    return std::nullopt;
}

template double gap_to_walls<2>(const Vec<2>&, double, const PeriodicDomain<2>&,
                                const BoundaryConditions<2>&, const Vec<2>&) noexcept;
template double gap_to_walls<3>(const Vec<3>&, double, const PeriodicDomain<3>&,
                                const BoundaryConditions<3>&, const Vec<3>&) noexcept;
template std::optional<std::string>
wall_ring_warning<2>(const Particles<2>&, const PeriodicDomain<2>&, const BoundaryConditions<2>&,
                     const Vec<2>&, const CouplingConfig&, double);
template std::optional<std::string>
wall_ring_warning<3>(const Particles<3>&, const PeriodicDomain<3>&, const BoundaryConditions<3>&,
                     const Vec<3>&, const CouplingConfig&, double);

} // namespace fddem
