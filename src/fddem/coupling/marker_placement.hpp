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
/// coupling.gains (set_forcing_gains).
///
/// With `is_owner_split` (the simultaneous sweep on a split grid: a body's markers are read
/// only by its owner and the ranks holding some of them, coupling/marker_routes.hpp) a rank
/// places only the bodies it owns or may hold markers of (holds_markers_of) and those
/// `also_place` marks (indexed as `bodies`: the ones it held before a move, whose markers it
/// may hand over from their new places); only the first get gains. For every other body whose
/// markers may come near a bounded side of the domain it makes the check above without storing
/// anything (there the check can fail, and it must fail on every rank alike). The others'
/// per-marker arrays are released
/// (MarkerCoupling::release_arrays): no rank reads them there, and a rank's memory for markers
/// then follows the bodies it holds, not all of them (Simulation::share_marker_state sizes and
/// places every body before a checkpoint writes them). A body placed again gets its arrays
/// back, I(u), λ and λ* zero until its owner hands them over (hand_over). The motion of every
/// body is checked on every rank.
template <int Dim>
void place_markers(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                   const AnyKernel& kernel, long step, double time,
                   bool is_forcing_normalised = false, bool is_owner_split = false,
                   std::span<const char> also_place = {});

/// Sets each body's coupling.gains, max(1, r_m) per marker and component, from its markers'
/// offsets as they are (coupling/forcing_gain.hpp).
template <int Dim>
void set_forcing_gains(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                       const AnyKernel& kernel);

} // namespace fddem
