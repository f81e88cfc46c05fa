// SPDX-License-Identifier: MIT
#pragma once
/// Values of the staggered fields at arbitrary points, and cell-centred derived fields:
/// (multi-)linear interpolation from each quantity's own positions (faces of its axis for a
/// velocity component, cell centres for p), using ghost values near walls (fill them first).

#include "fddem/grid/fields.hpp"

#include <vector>

namespace fddem {

/// Velocity at point x [m] (inside the box, boundary included).
template <int Dim>
[[nodiscard]] Vec<Dim> sample_velocity(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                                       const Vec<Dim>& x);

/// A cell-centred field at point x [m].
template <int Dim>
[[nodiscard]] double sample_cell_field(const MacGrid<Dim>& grid, const CellField<Dim>& phi,
                                       const Vec<Dim>& x);

/// Rows (k, x, y[, z], u, v[, w], p) at those of n_points equally spaced points from `from` to
/// `to` (k = 0 … n_points − 1) whose cell this process owns (MacGrid::owns_point;
/// on a split grid each point has one owner, whose storage holds the interpolation's stencil),
/// each row preceded by the point's number k (0 … n_points − 1). The ghosts of u and p next to
/// the block must be filled.
template <int Dim>
[[nodiscard]] std::vector<std::vector<double>>
sample_line_owned(const MacGrid<Dim>& grid, const FaceField<Dim>& u, const CellField<Dim>& p,
                  const Vec<Dim>& from, const Vec<Dim>& to, int n_points);

/// Velocity component `axis` at cell centres: the mean of the cell's two faces, on the cells
/// this process owns (the ghosts of u read across a rank face must be filled).
template <int Dim>
void cell_centred_velocity(const MacGrid<Dim>& grid, const FaceField<Dim>& u, int axis,
                           CellField<Dim>& out);

/// Vorticity component ω_c = ∂u_b/∂x_a − ∂u_a/∂x_b at cell centres, (a, b, c) cyclic
/// (in 2D only c = z: a = 0, b = 1): the mean of the four cell edges it is defined on, on the
/// cells this process owns (reads the ghosts of u next to them, edges and corners included).
template <int Dim>
void cell_centred_vorticity(const MacGrid<Dim>& grid, const FaceField<Dim>& u, int a, int b,
                            CellField<Dim>& out);

} // namespace fddem
