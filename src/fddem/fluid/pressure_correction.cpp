// SPDX-License-Identifier: MIT
#include "fddem/fluid/pressure_correction.hpp"

#include "fddem/grid/loops.hpp"

#include <cmath>

namespace fddem {

template <int Dim>
double compute_divergence(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                          CellField<Dim>& divergence)
{
    return max_over(grid.communicator(), grid.owned_cells(), [&](const Index<Dim>& c) {
        const std::ptrdiff_t o = grid.offset(c);
        double div = 0.0;
        for (int d = 0; d < Dim; ++d) {
            div += (u[d][o + grid.stride(d)] - u[d][o]) / grid.spacing(d);
        }
        divergence[o] = div;
        return std::abs(div);
    });
}

template <int Dim>
double correct_pressure_and_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                     const FluidProperties& fluid, double dt,
                                     double pressure_relaxation, PressureUpdate update,
                                     PoissonSolver<Dim>& poisson, FluidState<Dim>& state)
{
    // Outflow faces from u* (zero gradient, corrected to the inflow's volume flux): they are
    // not corrected by p′ below, and they make the right-hand side sum to zero, as the
    // zero-normal-gradient Poisson problem requires.
    set_outflow_velocity(grid, bc, state.u);
    // eq. (9): the right-hand side b′ is the mass imbalance of u*.
    const double max_divergence = compute_divergence(grid, state.u, state.divergence);
    const double source_factor = fluid.density / dt;
    for_each_index(grid.owned_cells(),
                   [&](const Index<Dim>& c) { state.divergence(c) *= source_factor; });
    poisson.solve(state.divergence, state.p_corr);
    fill_cell_ghosts(grid, bc, state.p_corr);

    // eqs. (11)–(12): u = u* + d (p′_W − p′_P), d = Δt/ρf.
    const double d_coefficient = dt / fluid.density;
    for (int axis = 0; axis < Dim; ++axis) {
        GridArray<Dim>& ua = state.u[axis];
        const std::ptrdiff_t s = grid.stride(axis);
        const double factor = d_coefficient / grid.spacing(axis);
        for_each_index(unknown_faces(grid, bc, axis), [&](const Index<Dim>& c) {
            const std::ptrdiff_t o = grid.offset(c);
            ua[o] += factor * (state.p_corr[o - s] - state.p_corr[o]);
        });
    }
    // eq. (10): p = p* + α_p p′, or p* + α_p (p′ − μ ∇·u*) (rotational); `divergence` holds
    // (ρf/Δt) ∇·u*.
    // Paper deviation (the rotational update; see the header): μΔt/ρf [m²], 0 for eq. (10).
    const double rotational_factor =
        update == PressureUpdate::rotational ? fluid.viscosity / source_factor : 0.0;
    for_each_index(grid.owned_cells(), [&](const Index<Dim>& c) {
        state.p(c) +=
            pressure_relaxation * (state.p_corr(c) - rotational_factor * state.divergence(c));
    });
    fill_velocity_ghosts(grid, bc, state.u);
    fill_cell_ghosts(grid, bc, state.p);
    return max_divergence;
}

template double compute_divergence<2>(const MacGrid<2>&, const FaceField<2>&, CellField<2>&);
template double compute_divergence<3>(const MacGrid<3>&, const FaceField<3>&, CellField<3>&);
template double correct_pressure_and_velocity<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                                 const FluidProperties&, double, double,
                                                 PressureUpdate, PoissonSolver<2>&, FluidState<2>&);
template double correct_pressure_and_velocity<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                                 const FluidProperties&, double, double,
                                                 PressureUpdate, PoissonSolver<3>&, FluidState<3>&);

} // namespace fddem
