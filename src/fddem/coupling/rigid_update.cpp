// SPDX-License-Identifier: MIT
#include "fddem/coupling/rigid_update.hpp"

#include "fddem/core/time_scheme.hpp"
#include "fddem/coupling/body_midplanes.hpp"
#include "fddem/coupling/inner_fluid.hpp"
#include "fddem/coupling/lubrication_coupling.hpp"
#include "fddem/coupling/marker_routes.hpp"
#include "fddem/coupling/rigid_coupling.hpp"
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/halo_exchange.hpp"

#include <algorithm>
#include <vector>

namespace fddem {
namespace {

/// Eqs. (13)–(14)'s level-n motion and parameters of a free body.
template <int Dim>
RigidUpdateInput<Dim> input_of(const Particle<Dim>& body, const RigidUpdateSettings<Dim>& s)
{
    // Ũ^n, ω̃^n: U^n, ω^n themselves with Euler (w = 0).
    const TimeLevels levels{s.dt, s.history_weight};
    RigidUpdateInput<Dim> in{levels.history(body.velocity_n, body.velocity_nm1),
                             levels.history(body.omega_n, body.omega_nm1),
                             body.density,
                             body.volume(),
                             body.inertia_tensor(),
                             s.fluid_density,
                             body.coupling.fluid_second_moment,
                             s.gravity,
                             s.dt,
                             body.contact.mean_force,
                             body.contact.mean_torque};
    if (s.is_inner_fluid_volume) {
        in.inner_fluid = &body.coupling.inner_fluid; // take_inner_fluid has just set it
        in.inner_fluid_n = &body.coupling.inner_fluid_n;
    }
    return in;
}

/// coupling.inner_fluid = "volume": ∫_P u dx and ∫_P r × u dx of those of `members` that
/// eqs. (13)–(14) move, into coupling.inner_fluid, from the current `u` (one sum over the
/// ranks; every rank calls it with the same members). Nothing without the option.
template <int Dim>
void take_inner_fluid(std::span<Particle<Dim>> bodies, std::span<const std::size_t> members,
                      const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                      const RigidUpdateSettings<Dim>& s)
{
    if (!s.is_inner_fluid_volume) {
        return;
    }
    std::vector<std::size_t> moved;
    for (const std::size_t b : members) {
        if (is_moved_by_fluid(bodies[b], s.is_paper_contact)) {
            moved.push_back(b);
        }
    }
    const std::vector<InnerFluid<Dim>> values =
        inner_fluid_of<Dim>(std::span<const Particle<Dim>>(bodies), moved, grid, u);
    for (std::size_t m = 0; m < moved.size(); ++m) {
        bodies[moved[m]].coupling.inner_fluid = values[m];
    }
}

/// U^{n+1}, ω^{n+1} of one body: eqs. (13)–(14) for a free body, the DEM's end state for a free
/// body in contact under the paper's coupling, the given motion for a fixed or prescribed one.
template <int Dim>
RigidVelocity<Dim> new_motion(const Particle<Dim>& body, const RigidUpdateSettings<Dim>& s)
{
    const MarkerCoupling<Dim>& c = body.coupling;
    if (!body.is_free()) {
        return {body.velocity, body.omega};
    }
    if (!is_moved_by_fluid(body, s.is_paper_contact)) {
        // §2.3: "When the collision happens, the DEM is used in place of (13) and (14)": the
        // body moves as the sub-steps say; the fluid is made to follow.
        return {body.contact.velocity, body.contact.omega};
    }
    return rigid_velocity<Dim>(input_of(body, s), c.offsets, c.markers.volumes, c.fluid,
                               c.lambda_star); // eqs. (13)–(14)
}

/// I(u) at the markers of one body that sit in cells this rank owns (their kernel support is
/// then within the rank's storage, whose halo is filled); zero at the others.
template <int Dim, class Kernel>
void interpolate_owned(const MacGrid<Dim>& grid, const FaceField<Dim>& u, MarkerCoupling<Dim>& c)
{
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        c.fluid[l] = grid.owns_point(c.positions[l])
                         ? interpolate_velocity<Dim, Kernel>(grid, u, c.positions[l])
                         : Vec<Dim>::Zero();
    }
}

/// I(u) at every marker of the body, the same on every rank of a split grid (issue 15): each
/// marker is interpolated by the rank that owns the cell it sits in, and one gather over the
/// ranks (Communicator::all_gather) hands every rank every marker's value as its holder computed
/// it, so U and ω of eqs. (13)–(14) come out the same on every rank and as on one process. One
/// collective per body and outer iteration with the sequential sweep (the simultaneous one sends
/// the markers to their bodies' owners instead: coupling/marker_routes.hpp; docs/parallel.md).
template <int Dim, class Kernel>
void interpolate_at_markers(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                            MarkerCoupling<Dim>& c)
{
    const Communicator& ranks = grid.communicator();
    if (ranks.size() == 1) {
        interpolate_owned<Dim, Kernel>(grid, u, c);
        return;
    }
    const auto n_ranks = static_cast<std::size_t>(ranks.size());
    const auto me = ranks.rank();
    std::vector<int> holders(c.markers.size());
    std::vector<int> counts(n_ranks, 0);
    std::vector<double> mine;
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        holders[l] = grid.rank_of_point(c.positions[l]);
        counts[static_cast<std::size_t>(holders[l])] += Dim;
        if (holders[l] == me) {
            const Vec<Dim> v = interpolate_velocity<Dim, Kernel>(grid, u, c.positions[l]);
            mine.insert(mine.end(), v.data(), v.data() + Dim);
        }
    }
    std::vector<double> all(Dim * c.markers.size());
    ranks.all_gather(mine, counts, all);
    std::vector<std::size_t> at(n_ranks, 0); // where each rank's values start in `all`
    for (std::size_t q = 1; q < n_ranks; ++q) {
        at[q] = at[q - 1] + static_cast<std::size_t>(counts[q - 1]);
    }
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        std::size_t& k = at[static_cast<std::size_t>(holders[l])];
        for (int d = 0; d < Dim; ++d) {
            c.fluid[l][d] = all[k++];
        }
    }
}

/// Whether a marker at `x` is closer than `reach` cells to a non-periodic side. With the
/// default reach (the kernel's support radius + 1/2) that is every marker whose kernel reads the
/// row of cells beside the wall: the wall's ghosts, odd images of the fluid beside it
/// (fluid/boundary_conditions.cpp), which turn eq. (15)'s correction around (docs/method.md §5,
/// "The stall in contact, diagnosed"), and the tangential velocity h/2 from the wall, which
/// drains the fluid squeezed out between a body and the wall: with markers holding it to the
/// body's motion the resolved force below half a cell grows as Δt shrinks, measured (§5, "The
/// retracted ring beside a wall" and "The wall's row of cells left free").
template <int Dim>
bool reaches_wall(const MacGrid<Dim>& grid, const Vec<Dim>& x, double reach_cells)
{
    const PeriodicDomain<Dim> domain = grid.domain();
    for (int d = 0; d < Dim; ++d) {
        if (domain.periodic(d)) {
            continue;
        }
        const double reach = reach_cells * grid.spacing()[d];
        if (x[d] - domain.origin[d] < reach || domain.origin[d] + domain.length[d] - x[d] < reach) {
            return true;
        }
    }
    return false;
}

/// The reach of coupling.markers_off_at_walls and coupling.markers_off_between_bodies [cells].
template <class Kernel>
double marker_off_reach(double wall_marker_reach) noexcept
{
    return wall_marker_reach > 0.0 ? wall_marker_reach
                                   : default_wall_marker_reach(Kernel::support_radius);
}

/// Each body's midplanes (coupling/body_midplanes.hpp), in the order of the bodies.
template <int Dim>
using BodyMidplanes = std::vector<std::vector<Midplane<Dim>>>;

/// The midplanes of coupling.markers_off_between_bodies for every body (none without it), from
/// the centres where the step's markers were placed: the same on every rank.
template <int Dim, class Kernel>
BodyMidplanes<Dim> midplanes_of(std::span<const Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                                const RigidUpdateSettings<Dim>& s)
{
    if (!s.is_body_marker_off) {
        return BodyMidplanes<Dim>(bodies.size());
    }
    return body_midplanes<Dim>(bodies, grid.domain(), grid.spacing(),
                               marker_off_reach<Kernel>(s.wall_marker_reach));
}

/// The markers of one body close to a wall (reaches_wall), with coupling.markers_off_at_walls
/// (Kempe & Fröhlich 2012b, as Biegert et al. 2017 report), or close to a midplane toward a
/// neighbour (`planes`, coupling.markers_off_between_bodies): no force; their fluid moves with
/// the body in eqs. (13)–(14). Decided from the positions alone, so alike on every rank of a
/// split grid. Sets their I(u) and λ*; returns the flags (empty without either option).
template <int Dim, class Kernel>
std::vector<char> silence_markers(Particle<Dim>& body, std::span<const Midplane<Dim>> planes,
                                  const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s)
{
    MarkerCoupling<Dim>& c = body.coupling;
    const bool is_any_off = s.is_wall_marker_off || (s.is_body_marker_off && !planes.empty());
    std::vector<char> is_off(is_any_off ? c.markers.size() : 0, 0);
    const double reach = marker_off_reach<Kernel>(s.wall_marker_reach);
    for (std::size_t l = 0; l < is_off.size(); ++l) {
        if ((s.is_wall_marker_off && reaches_wall<Dim>(grid, c.positions[l], reach)) ||
            reaches_midplane<Dim>(c.offsets[l], planes)) {
            is_off[l] = 1;
            c.fluid[l] = body.velocity + cross(body.omega, c.offsets[l]);
            c.lambda_star[l] = Vec<Dim>::Zero();
        }
    }
    return is_off;
}

/// Eq. (15) of one body at its new `motion`, the silenced markers' λ zeroed, and
/// coupling.forcing_change. Returns the rigid-motion defect.
template <int Dim>
double new_forcing(Particle<Dim>& body, const RigidVelocity<Dim>& motion,
                   const std::vector<char>& is_off, const RigidUpdateSettings<Dim>& s)
{
    MarkerCoupling<Dim>& c = body.coupling;
    const double defect = update_marker_force<Dim>(motion, c.offsets, c.fluid, c.lambda_star, s.dt,
                                                   c.lambda, c.gains); // eq. (15)
    for (std::size_t l = 0; l < is_off.size(); ++l) {
        if (is_off[l] != 0) {
            c.lambda[l] = Vec<Dim>::Zero();
        }
    }
    c.forcing_change = forcing_change<Dim>(c.offsets, c.markers.volumes, c.lambda, c.lambda_star,
                                           s.dt, body.volume(), body.radius());
    return defect;
}

/// Eqs. (13)–(15) of one body from its markers' I(u) (c.fluid): the markers off at walls and
/// midplanes (`planes`), the new motion and λ, and coupling.forcing_change. Arithmetic on the
/// body's own record only, the same on every rank. Returns the rigid-motion defect; `motion`
/// receives U^{n+1}, ω^{n+1}.
template <int Dim, class Kernel>
double correct_forcing(Particle<Dim>& body, std::span<const Midplane<Dim>> planes,
                       const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s,
                       RigidVelocity<Dim>& motion)
{
    const std::vector<char> is_off = silence_markers<Dim, Kernel>(body, planes, grid, s);
    motion = new_motion<Dim>(body, s);
    return new_forcing<Dim>(body, motion, is_off, s);
}

/// Eqs. (13)–(15) of the bodies `members` that lubrication links join (lubrication.coupling =
/// "implicit"; coupling/lubrication_coupling.hpp), from their markers' I(u): eq. (13) of all of
/// them solved together with the links' damping, then each one's eq. (14) with its links'
/// turning resistance at the new velocities, then eq. (15). Each member's velocity is set to
/// its new one (`motions`, in the order of `members`). Returns the largest defect.
template <int Dim, class Kernel>
double correct_linked_forcing(std::span<Particle<Dim>> bodies, std::span<const std::size_t> members,
                              const BodyMidplanes<Dim>& planes, const MacGrid<Dim>& grid,
                              const RigidUpdateSettings<Dim>& s,
                              std::span<RigidVelocity<Dim>> motions)
{
    std::vector<std::vector<char>> is_off;
    std::vector<RigidBalance<Dim>> balances;
    for (const std::size_t b : members) {
        Particle<Dim>& body = bodies[b];
        is_off.push_back(silence_markers<Dim, Kernel>(body, planes[b], grid, s));
        const MarkerCoupling<Dim>& c = body.coupling;
        balances.push_back(rigid_balance<Dim>(input_of(body, s), c.offsets, c.markers.volumes,
                                              c.fluid, c.lambda_star));
    }
    const std::vector<Vec<Dim>> velocities =
        coupled_velocities<Dim>(bodies, members, balances); // eq. (13) with the film
    for (std::size_t m = 0; m < members.size(); ++m) {
        bodies[members[m]].velocity = velocities[m];
    }
    double defect = 0.0;
    for (std::size_t m = 0; m < members.size(); ++m) {
        Particle<Dim>& body = bodies[members[m]];
        const LinkedDamping<Dim> film =
            linked_damping<Dim>(body.contact.lubrication_links, velocities[m], body.omega, bodies);
        const AngularVec<Dim> omega =
            solve<Dim>(Inertia<Dim>(balances[m].inertia_rate + film.moment_rate),
                       AngularVec<Dim>(balances[m].moment_rate + film.moment_target)); // eq. (14)
        motions[m] = {velocities[m], omega};
        defect = std::max(defect, new_forcing<Dim>(body, motions[m], is_off[m], s));
    }
    return defect;
}

/// Eq. (16)'s D(λ − λ*) of one body into `u`, owned markers only: on a split grid each marker is
/// spread by the rank that owns its cell, into its block and halo. The caller zeroes the ghosts
/// before and accumulates them after.
template <int Dim, class Kernel>
void spread_correction(const Particle<Dim>& body, const MacGrid<Dim>& grid,
                       const RigidUpdateSettings<Dim>& s, FaceField<Dim>& u)
{
    if (!holds_markers_of(grid, body)) {
        return; // none of its markers in this rank's cells
    }
    const MarkerCoupling<Dim>& c = body.coupling;
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        if (!grid.owns_point(c.positions[l])) {
            continue;
        }
        spread_vector<Dim, Kernel>(grid, u, c.positions[l], s.dt * (c.lambda[l] - c.lambda_star[l]),
                                   c.markers.volumes[l]);
    }
}

/// Before eq. (16)'s spreading into `u`: the ghosts zeroed, so that they collect only what is
/// spread (periodic and rank ghosts; with coupling.adjoint_at_walls the walls' too).
template <int Dim>
void begin_spreading(const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s, FaceField<Dim>& u,
                     const Box<Dim>* window = nullptr)
{
    HaloExchange<Dim>(grid).zero_ghosts(u);
    if (s.adjoint_walls != nullptr) {
        zero_wall_ghosts(grid, *s.adjoint_walls, u, window);
    }
}

/// After eq. (16)'s spreading into `u`: the ghosts' share handed to the faces they are images
/// of (walls' first with coupling.adjoint_at_walls, the transpose of the fill running in the
/// reverse order), then the ghosts filled again, so that the next I(u) reads the correction.
template <int Dim>
void end_spreading(const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s, FaceField<Dim>& u,
                   const Box<Dim>* window = nullptr)
{
    const HaloExchange<Dim> halo(grid);
    if (s.adjoint_walls == nullptr) {
        halo.accumulate(u);
        halo.fill(u);
        return;
    }
    fold_wall_ghosts(grid, *s.adjoint_walls, u, window);
    halo.accumulate(u);
    fill_velocity_ghosts(grid, *s.adjoint_walls, u, window);
}

/// The end of a body's update: λ* ← λ, and U, ω take their new values.
template <int Dim>
void finish_update(Particle<Dim>& body, const RigidVelocity<Dim>& motion)
{
    body.coupling.lambda_star = body.coupling.lambda;
    body.velocity = motion.velocity;
    body.omega = motion.omega;
}

/// coupling.body_sweep = "sequential": one body after the other, each reading the fluid as the
/// bodies before it left it (a Gauss–Seidel sweep over the bodies). Per body: one sum over the
/// ranks and one reverse halo sum and fill.
template <int Dim, class Kernel>
double update_one(Particle<Dim>& body, std::span<const Midplane<Dim>> planes,
                  const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s, FaceField<Dim>& u)
{
    interpolate_at_markers<Dim, Kernel>(grid, u, body.coupling); // I(u)
    const std::size_t self = 0;
    take_inner_fluid<Dim>(std::span<Particle<Dim>>(&body, 1),
                          std::span<const std::size_t>(&self, 1), grid, u, s);
    RigidVelocity<Dim> motion;
    const double defect = correct_forcing<Dim, Kernel>(body, planes, grid, s, motion);
    // eq. (16): u ← u + Δt D(λ − λ*). Across a periodic side the ghosts collect what belongs
    // to the faces on the other side (zeroed first, then accumulated onto their owners) and are
    // filled again, so that the next body's I(u) reads this body's correction there as well.
    // On a split grid the accumulation adds the halo's share to the neighbours' faces.
    // With coupling.adjoint_at_walls, only the sides the body's spreading comes near, and of
    // those only the part beside its markers, are zeroed, folded and filled (support_window):
    // the rest keeps the values a whole fill gives, bit for bit, without a pass over every side
    // for each body (measured: 8.5 times the step of the 200-sphere soak, docs/method.md §4).
    const Box<Dim> window = support_window<Dim, Kernel>(grid, body.coupling.positions);
    begin_spreading(grid, s, u, &window);
    spread_correction<Dim, Kernel>(body, grid, s, u);
    end_spreading(grid, s, u, &window);
    finish_update(body, motion);
    return defect;
}

/// The groups the lubrication links join (lubrication.coupling = "implicit"), else none.
template <int Dim>
LinkedGroups groups_of(std::span<const Particle<Dim>> bodies, const RigidUpdateSettings<Dim>& s)
{
    return s.is_lubrication_implicit ? linked_groups<Dim>(bodies, s.is_paper_contact)
                                     : LinkedGroups(bodies.size());
}

/// The sequential sweep's step for a group of bodies that lubrication links join: all of them
/// read the fluid as the bodies before the group left it, their eqs. (13)–(15) are solved
/// together (correct_linked_forcing), then each one's correction is spread as update_one does.
template <int Dim, class Kernel>
double update_group(std::span<Particle<Dim>> bodies, std::span<const std::size_t> members,
                    const BodyMidplanes<Dim>& planes, const MacGrid<Dim>& grid,
                    const RigidUpdateSettings<Dim>& s, FaceField<Dim>& u)
{
    for (const std::size_t b : members) {
        interpolate_at_markers<Dim, Kernel>(grid, u, bodies[b].coupling); // I(u)
    }
    take_inner_fluid<Dim>(bodies, members, grid, u, s);
    std::vector<RigidVelocity<Dim>> motions(members.size());
    const double defect =
        correct_linked_forcing<Dim, Kernel>(bodies, members, planes, grid, s, motions);
    for (std::size_t m = 0; m < members.size(); ++m) {
        Particle<Dim>& body = bodies[members[m]];
        const Box<Dim> window = support_window<Dim, Kernel>(grid, body.coupling.positions);
        begin_spreading(grid, s, u, &window);
        spread_correction<Dim, Kernel>(body, grid, s, u); // eq. (16)
        end_spreading(grid, s, u, &window);
        finish_update(body, motions[m]);
    }
    return defect;
}

/// coupling.body_sweep = "simultaneous": every body reads the same u, and the corrections of all
/// of them are added together (a Jacobi sweep over the bodies; eq. (16) with D over every
/// marker at once, as the paper writes it). On a split grid, one message between each pair of
/// ranks that share bodies each way, one sum of a few numbers per body over the ranks, and one
/// reverse halo sum and fill, whatever the number of bodies. Bodies whose kernel
/// supports do not meet get exactly what the sequential sweep gives them; where they meet, the
/// two sweeps reach the same converged λ by different paths.
template <int Dim, class Kernel>
double update_all_at_once(std::span<Particle<Dim>> bodies, const BodyMidplanes<Dim>& planes,
                          const MacGrid<Dim>& grid, const RigidUpdateSettings<Dim>& s,
                          FaceField<Dim>& u)
{
    for (Particle<Dim>& body : bodies) {
        // I(u), all from the same u. On a split grid a body none of whose markers is in this
        // rank's cells is skipped: its I(u) here is not read (its owner gathers the values of
        // the ranks that hold its markers, marker_routes.hpp).
        if (holds_markers_of(grid, body)) {
            interpolate_owned<Dim, Kernel>(grid, u, body.coupling);
        }
    }
    if (s.is_inner_fluid_volume) {
        std::vector<std::size_t> all(bodies.size());
        for (std::size_t b = 0; b < all.size(); ++b) {
            all[b] = b;
        }
        take_inner_fluid<Dim>(bodies, all, grid, u, s); // from the same u, like I(u)
    }
    double defect = 0.0;
    std::vector<RigidVelocity<Dim>> motions(bodies.size());
    if (grid.communicator().size() == 1) {
        const LinkedGroups groups = groups_of<Dim>(bodies, s);
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            const std::vector<std::size_t>* group = groups.group_starting_at(b);
            if (group != nullptr) {
                std::vector<RigidVelocity<Dim>> linked(group->size());
                defect = std::max(defect, correct_linked_forcing<Dim, Kernel>(
                                              bodies, *group, planes, grid, s, linked));
                for (std::size_t m = 0; m < group->size(); ++m) {
                    motions[(*group)[m]] = linked[m];
                }
            } else if (!groups.is_linked(b)) {
                defect = std::max(defect, correct_forcing<Dim, Kernel>(bodies[b], planes[b], grid,
                                                                       s, motions[b]));
            }
        }
    } else {
        // (lubrication.coupling = "implicit" is refused here: OuterIterations' constructor)
        // Split grid (marker_routes.hpp): the owner of each body gathers its markers' I(u),
        // evaluates eqs. (13)–(15), and hands λ back to the ranks that spread them; the motion
        // is then every rank's.
        const MarkerRoutes<Dim> routes(bodies, grid);
        routes.gather_at_owners(bodies);
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            if (routes.owns(b)) {
                defect = std::max(defect, correct_forcing<Dim, Kernel>(bodies[b], planes[b], grid,
                                                                       s, motions[b]));
            }
        }
        routes.return_to_holders(bodies);
        share_motion<Dim>(bodies, motions, grid);
        defect = grid.communicator().max(defect);
    }
    begin_spreading(grid, s, u);
    for (const Particle<Dim>& body : bodies) {
        spread_correction<Dim, Kernel>(body, grid, s, u); // eq. (16), all markers
    }
    end_spreading(grid, s, u);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        finish_update(bodies[b], motions[b]);
    }
    return defect;
}

} // namespace

template <int Dim>
double update_rigid_bodies(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                           const AnyKernel& kernel, const RigidUpdateSettings<Dim>& settings,
                           FaceField<Dim>& u)
{
    double defect = 0.0;
    std::visit(
        [&](auto k) {
            // The midplanes of coupling.markers_off_between_bodies, once per outer iteration
            // (the markers stay where the step placed them).
            const BodyMidplanes<Dim> planes = midplanes_of<Dim, decltype(k)>(
                std::span<const Particle<Dim>>(bodies.data(), bodies.size()), grid, settings);
            if (settings.is_simultaneous) {
                defect = update_all_at_once<Dim, decltype(k)>(bodies, planes, grid, settings, u);
                return;
            }
            // With the implicit lubrication, the bodies its links join are updated together,
            // where the first of them comes in the sweep.
            const LinkedGroups groups = groups_of<Dim>(bodies, settings);
            for (std::size_t b = 0; b < bodies.size(); ++b) {
                const std::vector<std::size_t>* group = groups.group_starting_at(b);
                if (group != nullptr) {
                    defect = std::max(defect, update_group<Dim, decltype(k)>(bodies, *group, planes,
                                                                             grid, settings, u));
                } else if (!groups.is_linked(b)) {
                    defect = std::max(defect, update_one<Dim, decltype(k)>(bodies[b], planes[b],
                                                                           grid, settings, u));
                }
            }
        },
        kernel);
    return defect;
}

template double update_rigid_bodies<2>(std::span<Particle<2>>, const MacGrid<2>&, const AnyKernel&,
                                       const RigidUpdateSettings<2>&, FaceField<2>&);
template double update_rigid_bodies<3>(std::span<Particle<3>>, const MacGrid<3>&, const AnyKernel&,
                                       const RigidUpdateSettings<3>&, FaceField<3>&);

} // namespace fddem
