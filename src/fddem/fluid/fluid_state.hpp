// SPDX-License-Identifier: MIT
#pragma once
/// The fluid unknowns of one time step and the settings of the momentum discretisation.

#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

namespace fddem {

struct FluidProperties {
    double density;   ///< ρf [kg/m³]
    double viscosity; ///< μ [Pa·s]
};

/// Convection: implicit first-order upwind plus a deferred correction to central differences,
/// evaluated with the latest outer iterate. At SIMPLE convergence the answer is the central
/// (second-order) one; upwinding only keeps the momentum matrix diagonally dominant.
enum class ConvectionScheme { central, upwind };

template <int Dim>
struct FluidState {
    explicit FluidState(const MacGrid<Dim>& grid)
        : u(grid), u_n(grid), u_nm1(grid), p(grid), p_corr(grid), body_force(grid), divergence(grid)
    {
    }
    FaceField<Dim> u;          ///< latest outer iterate of the velocity [m/s]
    FaceField<Dim> u_n;        ///< velocity at time level n [m/s]
    FaceField<Dim> u_nm1;      ///< velocity at time level n−1 [m/s] (BDF2; a reused assembly)
    CellField<Dim> p;          ///< pressure p* / p [Pa]
    CellField<Dim> p_corr;     ///< pressure correction p′ [Pa]
    FaceField<Dim> body_force; ///< force on the fluid per unit volume, incl. ρf λ* [N/m³]
    CellField<Dim> divergence; ///< work array: ∇·u* [1/s], then the Poisson right-hand side
};

} // namespace fddem
