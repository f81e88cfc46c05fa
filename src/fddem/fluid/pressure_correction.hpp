// SPDX-License-Identifier: MIT
#pragma once
/// The pressure-correction step of SIMPLE, eqs. (9)–(12).

#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

namespace fddem {

/// How eq. (10) updates the pressure from the correction p′.
enum class PressureUpdate {
    standard,  ///< p = p* + α_p p′ (the paper's eq. (10))
    rotational ///< p = p* + α_p (p′ − μ ∇·u*): see correct_pressure_and_velocity
};

/// ∇·u per cell [1/s] into `divergence`; returns max |∇·u| over the owned cells.
template <int Dim>
double compute_divergence(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                          CellField<Dim>& divergence);

/// eqs. (9)–(12): sets the outflow faces from u* (set_outflow_velocity), solves
/// ∇²p′ = (ρf/Δt) ∇·u* and corrects u = u* − (Δt/ρf) ∇p′ on every unknown face,
/// p = p* + α_p p′. Returns max |∇·u*| before the correction [1/s]. `dt` is the Δt_e of
/// core/time_scheme.hpp: the step over the time term's coefficient in a_P, Δt for implicit
/// Euler, 2Δt/3 for BDF2 at a constant step.
///
/// With PressureUpdate::rotational the pressure also takes −α_p μ ∇·u* (the rotational form
/// of the pressure-correction update; Timmermans, Minev & van de Vosse, Int. J. Numer. Meth.
/// Fluids 22 (1996) 673; Guermond & Shen, Math. Comp. 73 (2004) 1719). Why: the momentum
/// equations answer a pressure change δp with δu = −(ρf/Δt − μ∇²)⁻¹ ∇δp, while d = Δt/ρf
/// assumes δu = −(Δt/ρf) ∇δp. For a pressure error of wavenumber k the plain update then leaves
/// the fraction μk²/(ρf/Δt + μk²) of it per outer iteration: 0.95 for the shortest waves of the
/// paper's cases (μ = 0.1, h = 1/64, Δt = 0.005), which the λ updates of eq. (16) excite at
/// every marker. Where the momentum operator commutes with the gradient (uniform grid away from
/// walls, no convection), p′ − μ∇·u* is the exact pressure change: the same velocity
/// correction, the whole pressure error removed in one iteration. It only changes how the outer
/// iterations approach their answer, not the answer: at convergence p′ and ∇·u* both vanish.
///
/// Paper deviation: eqs. (11)–(12) use SIMPLE's d_ij = ΔV/a_ij; here d = Δt/ρf for every face,
/// the consistent (SIMPLEC) coefficient of the transient term. The converged answer of the
/// outer iterations does not depend on d, and a constant d keeps eq. (9) a constant-coefficient
/// Poisson equation that FFTW solves directly (DESIGN.md §3).
template <int Dim>
double correct_pressure_and_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                     const FluidProperties& fluid, double dt,
                                     double pressure_relaxation, PressureUpdate update,
                                     PoissonSolver<Dim>& poisson, FluidState<Dim>& state);

} // namespace fddem
