// SPDX-License-Identifier: MIT
#pragma once
/// The halo seam (DESIGN.md §6): the two exchanges between the entries a process owns and the
/// ghosts that are images of entries owned elsewhere.
///
///   fill:        every such ghost takes the value of its owner (before a stencil or the
///                interpolation I reads across the seam);
///   accumulate:  every such ghost's value is added to its owner and the ghost is zeroed
///                (after the spreading D wrote into ghosts: the reverse halo sum).
///
/// accumulate is the adjoint of fill: ⟨fill x, y⟩ = ⟨x, accumulate y⟩ over all entries, ghosts
/// included; that is what makes D stay the adjoint of I across a seam. The sum over all entries
/// is kept by accumulate, so momentum spread into ghosts is not lost.
///
/// Spreading protocol: zero_ghosts(a); spread into a (owned entries and ghosts); accumulate(a);
/// then fill(a) if the ghosts are read again. The ghosts must hold only what was spread into
/// them, hence the zero_ghosts first.
///
/// Along an axis that is not split across ranks, the only such ghosts are those across a
/// periodic side, whose owner is the entry one period away (index i mod n along the axis,
/// MacGrid's table), copied in place. Ghosts across the other sides belong to the boundary
/// conditions (fluid/boundary_conditions) and are left untouched.
///
/// Along an axis split across MPI ranks (grid/grid_partition.hpp), the ghosts of a block side
/// that faces another block (or, across a periodic side, the block at the other end) are
/// owned by that neighbour: fill receives them from it and accumulate sends them to it, which
/// adds them in a fixed order (halo_exchange.cpp lays out the layers). The messages go through
/// the grid's Communicator. Blocks are at least min_block_cells thick, so every ghost comes
/// from the nearest block.
///
/// Axes are exchanged one after the other over the whole storage extent of the others (fill in
/// axis order, accumulate in reverse), so edge and corner ghosts of a doubly periodic box, and
/// the corner four ranks share, are right as well (fill_faces, for the sweeps, leaves the edges,
/// corners and deeper layers). fill, fill_faces, accumulate and zero_ghosts are collective over
/// the grid's ranks: every rank calls them in the same order.

#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

namespace fddem {

template <int Dim>
class HaloExchange {
public:
    /// For the arrays of `grid` (which must outlive this object).
    explicit HaloExchange(const MacGrid<Dim>& grid) noexcept : grid_(&grid) {}

    /// Ghosts that are images of owned entries ← their owners' values.
    void fill(GridArray<Dim>& a) const;
    void fill(FaceField<Dim>& u) const;

    /// fill restricted to one slice across the outermost axis (index `plane` along Dim − 1):
    /// the images across the periodic sides of the other axes, in the same axis order. Needs
    /// keeps_slices_apart(). With fill_axis(a, Dim − 1), it is fill over every slice; a wavefront
    /// that has updated one slice refreshes its ghosts with it.
    void fill_plane(GridArray<Dim>& a, int plane) const;

    /// fill along one axis only (the images across its periodic sides, or the halo from the
    /// neighbouring blocks if it is split), over the whole storage extent of the others.
    void fill_axis(GridArray<Dim>& a, int axis) const;

    /// fill restricted to what a (2·Dim + 1)-point stencil on the momentum unknowns reads: the
    /// one ghost layer across each face of the owned cells' box, over the owned cells' extent
    /// along the other axes (no edge or corner ghost, no deeper layer; a face array's boundary
    /// face n of a bounded axis, never an unknown, gets no such neighbours). A red–black sweep
    /// refreshes its neighbours' values with it between colours; the deeper layers and the edges
    /// stay as they were until the next fill.
    void fill_faces(GridArray<Dim>& a) const;

    /// fill_faces along one axis only.
    void fill_faces_axis(GridArray<Dim>& a, int axis) const;

    /// Whether no axis but the outermost (Dim − 1) is split over ranks: then the images within a
    /// slice across Dim − 1 are copies within the process (fill_plane).
    [[nodiscard]] bool keeps_slices_apart() const;

    /// Owners += the values of their image ghosts, in a fixed order; those ghosts ← 0.
    void accumulate(GridArray<Dim>& a) const;
    void accumulate(FaceField<Dim>& u) const;

    /// Those ghosts ← 0: before spreading into an array whose ghosts hold other values.
    void zero_ghosts(GridArray<Dim>& a) const;
    void zero_ghosts(FaceField<Dim>& u) const;

private:
    const MacGrid<Dim>* grid_;
};

} // namespace fddem
