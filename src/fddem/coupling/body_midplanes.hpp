// SPDX-License-Identifier: MIT
#pragma once
/// The planes midway between the surfaces of two bodies close to each other, for
/// coupling.markers_off_between_bodies (fddem's, not the paper's; docs/method.md §5, "The row
/// of cells between two bodies left free").
///
/// Why a midplane. Two equal bodies driven toward each other at equal speeds meet a symmetry
/// plane midway between their surfaces: the fluid's normal velocity is zero there, so each body
/// sees the other as a wall at the midplane. Beside a real wall, markers that read the row of
/// cells next to it hold the fluid that drains the film to the body's motion, and the resolved
/// force below half a cell then grows as Δt shrinks (coupling.markers_off_at_walls and its
/// reach, the kernel's support + h/2: docs/method.md §5, "The wall's row of cells left free").
/// Between two bodies the same cells carry the drained fluid, and both bodies' markers read
/// them, each holding them to its own motion: the constraints conflict outright. The rule here
/// is the wall's, with the midplane as the wall: a marker is off when it lies closer to the
/// plane midway between its body's surface and the other's than the reach. For unequal bodies
/// or speeds the midplane is not a symmetry plane; it is still where the film is thinnest on
/// either side, and the rule is the same.
///
/// Balls only (the one shape fddem has): the gap and the normal come from the two centres.

#include "fddem/bodies/particle.hpp"
#include "fddem/core/periodic_domain.hpp"

#include <span>
#include <vector>

namespace fddem {

/// The plane between a body and one neighbour: the points r (relative to the body's centre,
/// nearest images across periodic sides) with normal · r = distance. `normal` is the unit vector
/// from the body's centre toward the neighbour's, `distance` = the body's radius + half the gap
/// between the surfaces.
template <int Dim>
struct Midplane {
    Vec<Dim> normal = Vec<Dim>::Zero();
    double distance = 0.0;
};

/// For each body, the midplanes to every other body whose surface gap is below `gap_limit` [m]
/// (a marker can be within reach r of a midplane only if the gap is below 2 r), in the order of
/// the neighbours' indices. Found with a cell list: linear in the number of bodies at a bounded
/// density. Overlapping bodies (a negative gap) get a plane inside them, which switches off the
/// markers beyond it as well.
template <int Dim>
[[nodiscard]] std::vector<std::vector<Midplane<Dim>>>
body_midplanes(std::span<const Particle<Dim>> bodies, const PeriodicDomain<Dim>& domain,
               double gap_limit);

/// Whether a marker at `offset` from its body's centre lies closer than `reach` [m] to one of
/// the body's midplanes (or beyond one).
template <int Dim>
[[nodiscard]] bool reaches_midplane(const Vec<Dim>& offset, std::span<const Midplane<Dim>> planes,
                                    double reach) noexcept
{
    for (const Midplane<Dim>& plane : planes) {
        if (plane.distance - plane.normal.dot(offset) < reach) {
            return true;
        }
    }
    return false;
}

} // namespace fddem
