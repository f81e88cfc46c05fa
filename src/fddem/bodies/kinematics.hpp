// SPDX-License-Identifier: MIT
#pragma once
/// The position update of eq. (17): X^{n+1} = X^n + Δt (U^n + U^{n+1})/2, and likewise the
/// orientation with ω (θ in 2D, the quaternion in 3D: bodies/orientation.hpp).

#include "fddem/bodies/particle.hpp"
#include "fddem/core/periodic_domain.hpp"

#include <span>

namespace fddem {

/// Moves every free or prescribed body over a step of `dt` [s] by eq. (17), from its level-n
/// and new velocities. With `is_paper_contact` (contact.coupling = "paper"), a free body that
/// was in contact takes the DEM's end position instead (§2.3: "DEM is used to update the
/// position"). Fixed bodies stay.
template <int Dim>
void move_bodies(std::span<Particle<Dim>> bodies, double dt, bool is_paper_contact);

/// A body whose centre crossed a periodic side of `domain` re-enters on the other: its centre
/// moves by whole periods into the box (unchanged bit for bit if it is inside).
template <int Dim>
void wrap_centres(std::span<Particle<Dim>> bodies, const PeriodicDomain<Dim>& domain);

} // namespace fddem
