// SPDX-License-Identifier: MIT
#pragma once
/// What a Simulation is built from: the grid, boundary conditions, bodies and contact set-up a
/// checked case describes.

#include "fddem/bodies/particles.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/mac_grid.hpp"
#include "fddem/simulation/case_config.hpp"
#include "fddem/simulation/simulation.hpp"

#include <optional>

namespace fddem {

/// The ranks along each axis of a run on `n_ranks` processes: parallel.ranks (checked), or the
/// layout with the least interface area (grid/grid_partition.hpp). Throws InputError naming the
/// case file when there is none.
template <int Dim>
[[nodiscard]] Index<Dim> rank_layout(const CaseConfig& config, int n_ranks);

/// The case's grid, split over `ranks` (rank_layout) if they are more than one process. Throws
/// InputError if the case is not Dim-dimensional or if the blocks would be too thin.
template <int Dim>
[[nodiscard]] MacGrid<Dim> make_grid(const CaseConfig& config,
                                     const Communicator& ranks = Communicator::self());

template <int Dim>
[[nodiscard]] BoundaryConditions<Dim> make_boundary_conditions(const CaseConfig& config);

/// The first Dim entries of a case vector (missing ones 0).
template <int Dim>
[[nodiscard]] Vec<Dim> vector_of(const std::vector<double>& values);

/// A case's angular quantity (bodies.omega): ω_z in 2D, the three components in 3D (missing
/// ones 0).
template <int Dim>
[[nodiscard]] AngularVec<Dim> angular_of(const std::vector<double>& values);

/// The case's bodies, with ids 0, 1, … in the order of [[bodies]] and their markers in the body
/// frame (N_a from bodies.n_rings or coupling.marker_spacing_ratio).
template <int Dim>
[[nodiscard]] Particles<Dim> make_particles(const CaseConfig& config, const MacGrid<Dim>& grid);

/// The DEM's settings, broad phase and walls: none without a free body or a contact model.
template <int Dim>
[[nodiscard]] std::optional<ContactSetup<Dim>>
make_contact_setup(const CaseConfig& config, const MacGrid<Dim>& grid,
                   const BoundaryConditions<Dim>& bc, const Particles<Dim>& bodies);

} // namespace fddem
