// SPDX-License-Identifier: MIT
#pragma once
/// The pseudo body force of eq. (4a) on the faces: f = f_uniform + ρf D(λ), the momentum source
/// of the next outer iteration's eqs. (7)–(8).

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/fields.hpp"

#include <span>

namespace fddem {

/// Sets `body_force` [N/m³] to `uniform_force` plus ρf D(λ) of every body's markers, with
/// what was spread across a periodic side accumulated on the faces there (HaloExchange) and
/// the periodic ghosts filled. With `adjoint_walls` (coupling.adjoint_at_walls) what was spread
/// into a wall's ghosts is folded back through their fill (fold_wall_ghosts), the adjoint of
/// interpolating there; without, it is dropped.
template <int Dim>
void spread_marker_forces(std::span<const Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                          const AnyKernel& kernel, double fluid_density,
                          const Vec<Dim>& uniform_force, FaceField<Dim>& body_force,
                          const BoundaryConditions<Dim>* adjoint_walls = nullptr);

} // namespace fddem
