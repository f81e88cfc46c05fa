// SPDX-License-Identifier: MIT
#pragma once
/// Where the markers are (paper §2.2, Fig. 1): each body's markers, laid out in its own frame,
/// turned by its orientation and carried to its centre; across a periodic side of the box, to
/// the image inside it (PeriodicDomain::wrap), marker by marker.

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <span>

namespace fddem {

/// Sets every body's world-frame offsets r_l and positions X_l = centre + r_l, wrapped into the
/// box along periodic axes (unchanged bit for bit where no wrap is needed). Throws
/// NumericalError (of time step `step`, ending at `time` [s]) if a body's motion is not finite or
/// a marker's kernel support leaves the grid's storage.
/// With `is_forcing_normalised` (coupling.normalised_forcing) also sets each body's
/// coupling.gains (set_forcing_gains); with `is_owner_split` as well (the simultaneous sweep on
/// a split grid, where a body's owner alone evaluates eq. (15)) only those of the bodies this
/// rank holds markers of (holds_markers_of, coupling/marker_routes.hpp), the others' left as
/// they were.
template <int Dim>
void place_markers(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                   const AnyKernel& kernel, long step, double time,
                   bool is_forcing_normalised = false, bool is_owner_split = false);

/// Sets each body's coupling.gains, max(1, r_m) per marker and component, from its markers'
/// offsets as they are (coupling/forcing_gain.hpp).
template <int Dim>
void set_forcing_gains(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                       const AnyKernel& kernel);

} // namespace fddem
