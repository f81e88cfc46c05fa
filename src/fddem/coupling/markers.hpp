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

/// Markers for a ball with `n_rings` rings (2D) or shells (3D); n_rings ≥ 1: the paper's
/// layout above.
template <int Dim>
[[nodiscard]] MarkerSet<Dim> make_ball_markers(const Ball<Dim>& ball, int n_rings);

/// Markers for a ball whose outermost ring (shell) lies `retraction` inside the surface
/// (issue 13; `coupling.marker_retraction`): ring i at radius i h_L, h_L = (R − retraction)/N_a,
/// ring i < N_a owning the annulus ((i − ½) h_L, (i + ½) h_L) and ring N_a the rest of the ball
/// out to R, so that Σ ΔV_l is still the ball's volume. The paper's layout puts the last ring
/// h_L/2 inside (retraction ≈ 0.7 h at h_L = 1.4 h), where the diffuse forcing makes the body
/// hydrodynamically smaller than it is (docs/method.md §4); a surface layer of markers retracted
/// by a fraction of h is the immersed-boundary practice (Breugem 2012, J. Comput. Phys. 231).
/// 0 ≤ retraction < R.
template <int Dim>
[[nodiscard]] MarkerSet<Dim> make_retracted_ball_markers(const Ball<Dim>& ball, int n_rings,
                                                         double retraction);

/// Markers on one ring (shell) `retraction` inside the surface and none inside it
/// (`coupling.markers = "surface"`, issue 13): the outermost ring of the retracted layout
/// alone, its markers about `spacing` apart, each owning an equal share of a shell of thickness
/// `thickness` (the grid spacing h: the surface markers of Uhlmann 2005, J. Comput. Phys. 209,
/// whose ΔV_l = h × the marker's share of the surface makes one λ update of eq. (15) remove
/// most of the slip). Σ ΔV_l is the shell's volume, not the body's: the layout fits a body whose
/// velocity is given (fixed or prescribed), not eqs. (13)–(14) of a free one, whose fluid
/// momentum Σ ΔV_l u_l it would miss. 0 ≤ retraction < R, spacing and thickness > 0.
template <int Dim>
[[nodiscard]] MarkerSet<Dim> make_surface_ball_markers(const Ball<Dim>& ball, double retraction,
                                                       double spacing, double thickness);

/// N_a for a target marker spacing h_L ≈ ratio · h: round(R / (ratio h) − ½), at least 1.
[[nodiscard]] int rings_for_spacing(double radius, double grid_spacing, double ratio);

/// N_a for the retracted layout: round((R − retraction) / (ratio h)), at least 1.
[[nodiscard]] int retracted_rings_for_spacing(double radius, double retraction, double grid_spacing,
                                              double ratio);

} // namespace fddem
