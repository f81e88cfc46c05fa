// SPDX-License-Identifier: MIT
#pragma once
/// The pressure-correction step of SIMPLE, eqs. (9)–(12).

#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

namespace fddem {

/// ∇·u per cell [1/s] into `divergence`; returns max |∇·u| over the owned cells.
template <int Dim>
double compute_divergence(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                          CellField<Dim>& divergence);

/// eqs. (9)–(12): sets the outflow faces from u* (set_outflow_velocity), solves
/// ∇²p′ = (ρf/Δt) ∇·u* and corrects u = u* − (Δt/ρf) ∇p′ on every unknown face,
/// p = p* + α_p p′. Returns max |∇·u*| before the correction [1/s].
///
/// Paper deviation: eqs. (11)–(12) use SIMPLE's d_ij = ΔV/a_ij; here d = Δt/ρf for every face,
/// the consistent (SIMPLEC) coefficient of the transient term. The converged answer of the
/// outer iterations does not depend on d, and a constant d keeps eq. (9) a constant-coefficient
/// Poisson equation that FFTW solves directly (DESIGN.md §3).
template <int Dim>
double correct_pressure_and_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                     const FluidProperties& fluid, double dt,
                                     double pressure_relaxation, PoissonSolver<Dim>& poisson,
                                     FluidState<Dim>& state);

} // namespace fddem
