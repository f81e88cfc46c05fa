// SPDX-License-Identifier: MIT
#pragma once
/// The gain of eqs. (15)–(16) at each marker: the row sums of the forcing operator M = I·D over
/// one body's markers (docs/method.md §4, "The forcing operator"). A marker's slip e is
/// corrected as e ← (1 − M) e in each outer iteration, a Richardson iteration that overshoots
/// every mode whose eigenvalue exceeds 2. M's entries are non-negative (the kernels are), so its
/// largest eigenvalue is at most its largest row sum r_m = Σ_l M_ml, and dividing each marker's
/// correction by g_m = max(1, r_m) leaves an operator G⁻¹M whose eigenvalues are real (it is
/// similar to the symmetric (G⁻¹V)^½ K (G⁻¹V)^½, with M = K V, K symmetric, V the marker
/// volumes) and at most 1: no mode overshoots. The converged λ (no slip) is the same. The idea is
/// Pinelli et al.'s (2010, J. Comput. Phys. 229, 9073) marker weights, which they solve for
/// (K ε = 1); this is a one-step row-sum approximation of it, not their solve.
///
/// Computed on a small patch of faces around the body, from the markers' unwrapped positions
/// (centre + offset), so that it needs neither the grid's storage nor a message between ranks:
/// the same numbers on every rank. Walls are not folded in. With the hat kernel the retracted
/// markers do not reach a wall's ghost images (docs/method.md §4) and the bound above holds;
/// the wider kernels' do, and the fold (odd images) can make entries of M negative, so beside
/// a wall only eigenvalues up to 2 are guaranteed there. The gains count the body's own
/// markers only: the bound is per body (the sequential body sweep).
#include "fddem/core/vec.hpp"
#include "fddem/coupling/delta_kernel.hpp"

#include <span>
#include <vector>

namespace fddem {

/// r_m for every marker and velocity component: Σ_l M_ml with M_ml = ΔV_l Σ_f δ_h(x_f − X_l)
/// δ_h(X_m − x_f) h^Dim over the faces f of that component (faces along an axis lie on the grid
/// lines origin + k h, across it at the cell centres). `positions` unwrapped, `volumes` ΔV_l.
template <int Dim, DeltaKernel Kernel>
[[nodiscard]] std::vector<Vec<Dim>>
forcing_row_sums(std::span<const Vec<Dim>> positions, std::span<const double> volumes,
                 const Vec<Dim>& origin, const Vec<Dim>& spacing);

/// The same for the kernel the case chose.
template <int Dim>
[[nodiscard]] std::vector<Vec<Dim>>
forcing_row_sums(const AnyKernel& kernel, std::span<const Vec<Dim>> positions,
                 std::span<const double> volumes, const Vec<Dim>& origin, const Vec<Dim>& spacing);

} // namespace fddem
