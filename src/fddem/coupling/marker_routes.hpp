// SPDX-License-Identifier: MIT
#pragma once
/// Who computes what of a body on a grid split over MPI ranks (issue 15, docs/parallel.md,
/// "Bodies"), for the simultaneous sweep over the bodies (coupling.body_sweep).
///
/// - The owner of a body is the rank that owns the cell of its centre (MacGrid::rank_of_point).
///   It alone evaluates eqs. (13)–(15) for the body, from the I(u) of all its markers.
/// - A marker is interpolated and spread by the rank that owns its cell (its holder), as
///   before. A holder that is not the owner sends its markers' I(u) to the owner
///   (gather_at_owners), and gets back their λ and λ* (return_to_holders): one message between
///   each pair of ranks that share a body, in each direction, per outer iteration, holding the
///   markers of all the bodies they share. Ranks that share no body exchange nothing.
/// - Every rank still holds every body's record. What the owners computed is made every rank's
///   by one gather of the owners' values (Communicator::all_gather: exactly the owner's
///   values, each received once): the bodies' motion (share_motion, every outer iteration), their
///   hydrodynamic loads (share_loads, every step) and, for a checkpoint or the outputs, the marker
///   arrays (share_markers). The first two are a few numbers per body; the last is sent only when
///   asked for.
///
/// The marker lists the owner assembles are, value for value, those of one process, so the
/// split run computes what one process computes, bit for bit.

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/rigid_coupling.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace fddem {

/// The rank that owns `body`: the one owning the cell of its centre, wrapped into the domain.
template <int Dim>
[[nodiscard]] int owner_rank(const MacGrid<Dim>& grid, const Particle<Dim>& body) noexcept
{
    return grid.rank_of_point(grid.domain().wrap(body.centre));
}

/// Whether this rank may hold some of the markers of `body` (in its cells) or owns it: the
/// bodies a rank's marker loops visit (interpolation, spreading, the routes). Decided from the
/// body's centre and marker reach against the rank's block (MacGrid::may_own_near), so it costs
/// a few operations per body, not a pass over the markers; it errs on the side of yes, and a
/// body it says no to has no marker in this rank's cells. Always yes on one process.
template <int Dim>
[[nodiscard]] bool holds_markers_of(const MacGrid<Dim>& grid, const Particle<Dim>& body) noexcept
{
    if (grid.communicator().size() == 1) {
        return true;
    }
    const Vec<Dim> centre = grid.domain().wrap(body.centre);
    return grid.may_own_near(centre, body.coupling.reach) ||
           grid.rank_of_point(centre) == grid.communicator().rank();
}

/// Markers (body, marker), in store and marker order, going to or coming from one rank.
struct MarkerLink {
    int rank = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> markers;
};

template <int Dim>
class MarkerRoutes {
public:
    /// The routes of the markers as placed now (every rank holds every body, in the same order,
    /// with the same marker positions, so every rank finds the same routes without asking). Only
    /// the markers of the bodies this rank owns or holds markers of are visited
    /// (holds_markers_of): the others have none in its cells.
    MarkerRoutes(std::span<const Particle<Dim>> bodies, const MacGrid<Dim>& grid);

    /// Whether this rank owns body number `b` (its position in the store).
    [[nodiscard]] bool owns(std::size_t b) const noexcept { return is_owned_[b] != 0; }
    /// The ranks this rank exchanges markers with (each once), for tests and the traffic table.
    [[nodiscard]] std::vector<int> peers() const;

    /// coupling.fluid of every owned body made whole: the other holders' values received.
    void gather_at_owners(std::span<Particle<Dim>> bodies) const;
    /// coupling.lambda and lambda_star of the markers this rank holds of other ranks' bodies,
    /// received from the owners.
    void return_to_holders(std::span<Particle<Dim>> bodies) const;

private:
    std::vector<MarkerLink> to_owners_;    ///< markers this rank holds of bodies other ranks own
    std::vector<MarkerLink> from_holders_; ///< markers of this rank's bodies other ranks hold
    std::vector<char> is_owned_;
    const Communicator* ranks_;
};

/// After the bodies moved and their markers were placed again: λ and λ* sent from each body's
/// `previous_owners[b]` (which holds them whole) to its owner now, if another, and to every
/// other rank that now holds some of its markers (so that the next steps' spreading and eqs.
/// (13)–(15) read the values one process would). A holder that held the same markers before
/// gets them again: sending only what changed hands is left to do.
template <int Dim>
void hand_over(std::span<Particle<Dim>> bodies, std::span<const int> previous_owners,
               const MacGrid<Dim>& grid);

/// U, ω and coupling.forcing_change of every body set to the owner's `motions[b]` (and
/// forcing_change) on every rank.
template <int Dim>
void share_motion(std::span<Particle<Dim>> bodies, std::span<RigidVelocity<Dim>> motions,
                  const MacGrid<Dim>& grid);
/// force and torque of every body set to the owner's on every rank.
template <int Dim>
void share_loads(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid);
/// coupling.fluid, lambda and lambda_star of every body set to the owner's on every rank.
template <int Dim>
void share_markers(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid);

} // namespace fddem
