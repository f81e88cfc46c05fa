// SPDX-License-Identifier: MIT
#include "fddem/coupling/force_spreading.hpp"

#include "fddem/coupling/marker_routes.hpp"
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/halo_exchange.hpp"

namespace fddem {

template <int Dim>
void spread_marker_forces(std::span<const Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                          const AnyKernel& kernel, double fluid_density,
                          const Vec<Dim>& uniform_force, FaceField<Dim>& body_force,
                          const BoundaryConditions<Dim>* adjoint_walls)
{
    for (int a = 0; a < Dim; ++a) {
        body_force[a].fill(uniform_force[a]);
    }
    // What markers by a periodic side (or by a rank face of a split grid) spread into the ghosts
    // beyond it belongs to the faces there on the other side: collected in zeroed ghosts, then
    // added to their owners.
    const HaloExchange<Dim> halo(grid);
    halo.zero_ghosts(body_force);
    if (adjoint_walls != nullptr) {
        zero_wall_ghosts(grid, *adjoint_walls, body_force);
    }
    std::visit(
        [&](auto k) {
            for (const Particle<Dim>& body : bodies) {
                if (!holds_markers_of(grid, body)) {
                    continue; // none of its markers in this rank's cells (a split grid)
                }
                const MarkerCoupling<Dim>& c = body.coupling;
                for (std::size_t l = 0; l < c.markers.size(); ++l) {
                    if (!grid.owns_point(c.positions[l])) {
                        continue; // another rank's (a split grid): it spreads this one
                    }
                    spread_vector<Dim, decltype(k)>(grid, body_force, c.positions[l],
                                                    fluid_density * c.lambda[l],
                                                    c.markers.volumes[l]);
                }
            }
        },
        kernel);
    if (adjoint_walls != nullptr) {
        fold_wall_ghosts(grid, *adjoint_walls, body_force);
    }
    halo.accumulate(body_force);
    halo.fill(body_force);
}

template void spread_marker_forces<2>(std::span<const Particle<2>>, const MacGrid<2>&,
                                      const AnyKernel&, double, const Vec<2>&, FaceField<2>&,
                                      const BoundaryConditions<2>*);
template void spread_marker_forces<3>(std::span<const Particle<3>>, const MacGrid<3>&,
                                      const AnyKernel&, double, const Vec<3>&, FaceField<3>&,
                                      const BoundaryConditions<3>*);

} // namespace fddem
