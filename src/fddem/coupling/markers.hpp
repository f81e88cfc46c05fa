// SPDX-License-Identifier: MIT
#pragma once
/// Lagrangian markers filling a body (paper §3.1, Fig. 1): one at the centre and 6i on ring i,
/// i = 1..N_a, for a disk; the same idea with spherical shells for a sphere.
///
/// Layout (a choice, the paper gives only the counts): ring i has radius i h_L with
/// h_L = R / (N_a + ½), so the rings sit at the middles of N_a annuli of equal width h_L
/// between h_L/2 and R. Each ring's markers share its annulus equally, and the centre marker
/// owns the disk of radius h_L/2: then Σ ΔV_l = π R² exactly, every ring marker has the same
/// volume π h_L²/3, and neighbours on a ring are π h_L/3 ≈ 1.05 h_L apart. A sphere's shells
/// hold 8 round(π i²/2) markers (spacing ≈ h_L), sharing the shell's volume equally: a
/// golden-angle spiral over one octant, reflected through the planes of the axes. Every layout
/// is mirror-symmetric in those planes, so its centroid is the centre.

#include "fddem/bodies/ball.hpp"
#include "fddem/bodies/marker_set.hpp"

#include <vector>

namespace fddem {

/// Markers for a ball with `n_rings` rings (2D) or shells (3D); n_rings ≥ 1.
template <int Dim>
[[nodiscard]] MarkerSet<Dim> make_ball_markers(const Ball<Dim>& ball, int n_rings);

/// N_a for a target marker spacing h_L ≈ ratio · h: round(R / (ratio h) − ½), at least 1.
[[nodiscard]] int rings_for_spacing(double radius, double grid_spacing, double ratio);

} // namespace fddem
