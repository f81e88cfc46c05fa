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
/// or speeds the midplane is not a symmetry plane; it still bisects the gap on the line of
/// centres, and the same rule is used (not measured on such a pair).
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
/// between the surfaces (the plane bisects the gap on the line of centres). A marker closer to
/// it than `reach` [m] is off.
template <int Dim>
struct Midplane {
    Vec<Dim> normal = Vec<Dim>::Zero();
    double distance = 0.0;
    double reach = 0.0;
};

/// The reach from a plane of normal `normal` of `reach_cells` grid spacings: reach_cells ·
/// Σ_d |n_d| h_d. The kernels are products of 1-D kernels, so a marker's support is a box, which
/// reaches Σ_d |n_d| s h_d along n (s its half width in cells): √2 (2D) or √3 (3D) times s h on
/// a diagonal. Scaled so, the rule keeps the kernel off the cells next to the plane whatever the
/// pair's direction, as the wall's rule does for its axis-aligned walls (where this is
/// reach_cells · h of the wall's axis, the same).
template <int Dim>
[[nodiscard]] double reach_along(const Vec<Dim>& normal, const Vec<Dim>& spacing,
                                 double reach_cells) noexcept
{
    return reach_cells * normal.cwiseAbs().dot(spacing);
}

/// For each body, the midplanes to every other body close enough for a marker to come within
/// reach of the plane between them (`reach_cells` grid spacings of `spacing`, along the plane's
/// normal: reach_along), in the order of the neighbours' indices. Found with a cell list: linear
/// in the number of bodies at a bounded density. Overlapping bodies (a negative gap) get a plane
/// inside them, which switches off the markers beyond it as well; bodies whose centres coincide
/// get none (no direction). Each pair is found once, through its nearest images: a pair close
/// through two images at once (a box narrower than twice the range) gets one plane, and no
/// body gets one to its own periodic image.
template <int Dim>
[[nodiscard]] std::vector<std::vector<Midplane<Dim>>>
body_midplanes(std::span<const Particle<Dim>> bodies, const PeriodicDomain<Dim>& domain,
               const Vec<Dim>& spacing, double reach_cells);

/// Whether a marker at `offset` from its body's centre lies within the reach of one of the
/// body's midplanes (or beyond one).
template <int Dim>
[[nodiscard]] bool reaches_midplane(const Vec<Dim>& offset,
                                    std::span<const Midplane<Dim>> planes) noexcept
{
    for (const Midplane<Dim>& plane : planes) {
        if (plane.distance - plane.normal.dot(offset) < plane.reach) {
            return true;
        }
    }
    return false;
}

} // namespace fddem
