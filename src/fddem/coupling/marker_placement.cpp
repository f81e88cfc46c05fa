// SPDX-License-Identifier: MIT
#include "fddem/coupling/marker_placement.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/coupling/forcing_gain.hpp"
#include "fddem/coupling/marker_routes.hpp"
#include "fddem/coupling/transfer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace fddem {
namespace {

/// Numbered from 1 in messages, as in `--set bodies.N.key=value`.
template <int Dim>
std::string name_of(const Particle<Dim>& body)
{
    return "body " + std::to_string(body.id + 1);
}

/// Whether the body's orientation and spin are finite (those its markers' offsets follow).
template <int Dim>
bool is_turn_finite(const Particle<Dim>& body)
{
    if constexpr (Dim == 2) {
        return std::isfinite(body.orientation) && std::isfinite(body.omega);
    } else {
        return body.orientation.coeffs().allFinite() && body.omega.allFinite();
    }
}

/// Throws NumericalError if the body's motion is not finite (every rank alike: a rank that does
/// not place the body must not pass a state that makes another's placement throw).
template <int Dim>
void check_finite(const Particle<Dim>& body, long step, double time)
{
    if (!body.centre.allFinite() || !body.velocity.allFinite() || !is_turn_finite(body)) {
        throw NumericalError(step, time, name_of(body),
                             "the body's motion is not finite: the coupling has blown up");
    }
}

/// Whether a marker of `body` may come within two cells of a bounded side of the domain (its
/// centre and marker reach against the sides), the only place where place() can find a kernel
/// support beyond the ghost layers: a point two cells inside the domain has the support of the
/// widest kernel (half width 2 h) within the box and its n_ghost = 2 ghost layers.
template <int Dim>
bool may_near_bounded_side(const MacGrid<Dim>& grid, const Particle<Dim>& body)
{
    for (int d = 0; d < Dim; ++d) {
        if (grid.is_periodic(d)) {
            continue; // markers are wrapped into the box
        }
        const double margin = 2.0 * grid.spacing(d) + body.coupling.reach;
        if (body.centre[d] - margin < grid.origin()[d] ||
            body.centre[d] + margin > grid.origin()[d] + grid.length()[d]) {
            return true;
        }
    }
    return false;
}

/// Places the markers of `body` (`is_stored`) or only checks where they would be: each marker's
/// world offset and position, and the check that its kernel support stays within the grid's
/// storage.
template <int Dim, class Kernel>
void place(Particle<Dim>& body, const MacGrid<Dim>& grid, long step, double time,
           bool is_stored = true)
{
    check_finite(body, step, time);
    MarkerCoupling<Dim>& c = body.coupling;
    if (is_stored) {
        c.fluid_second_moment = inertia_in_world<Dim>(body.orientation, c.body_second_moment);
    }
    const PeriodicDomain<Dim> domain = grid.domain();
    // Checked against the one-process storage, so that every rank of a split grid gives the
    // same verdict (the bodies are the same on every rank): a marker that fits there fits in
    // the storage of the rank that owns it, the only one that interpolates and spreads it.
    const Box<Dim> storage = grid.whole_storage_box();
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        const Vec<Dim> offset = to_world<Dim>(body.orientation, c.markers.offsets[l]);
        // Each marker on its own image in the box: a body across a periodic side has markers
        // on both sides, and every marker's kernel support stays within the ghost layers.
        const Vec<Dim> position = domain.wrap(body.centre + offset);
        if (!fits_in_box<Dim, Kernel>(grid, storage, position)) {
            throw NumericalError(step, time, name_of(body),
                                 fmt::format("a marker of the body left the box (its kernel "
                                             "support reaches past the ghost layers): centre "
                                             "({:.6g}), velocity ({:.6g})",
                                             fmt::join(body.centre, ", "),
                                             fmt::join(body.velocity, ", ")));
        }
        if (is_stored) {
            c.offsets[l] = offset;
            c.positions[l] = position;
        }
    }
}

} // namespace

template <int Dim>
void place_markers(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                   const AnyKernel& kernel, long step, double time, bool is_forcing_normalised,
                   bool is_owner_split, std::span<const char> also_place)
{
    std::visit(
        [&](auto k) {
            for (std::size_t b = 0; b < bodies.size(); ++b) {
                Particle<Dim>& body = bodies[b];
                // With the owner split a rank places only what it reads; where the check of
                // the kernel support could fail every rank makes it for every body alike, so
                // that no rank throws while another waits (the verdict is then every rank's).
                const bool is_placed = !is_owner_split || holds_markers_of(grid, body) ||
                                       (b < also_place.size() && also_place[b] != 0);
                if (is_placed) {
                    body.coupling.allocate_arrays(); // a body this rank did not hold before
                    place<Dim, decltype(k)>(body, grid, step, time);
                    continue;
                }
                body.coupling.release_arrays(); // not read here until it is placed again
                if (may_near_bounded_side(grid, body)) {
                    place<Dim, decltype(k)>(body, grid, step, time, false); // the check alone
                } else {
                    check_finite(body, step, time);
                }
            }
        },
        kernel);
    if (!is_forcing_normalised) {
        return;
    }
    if (!is_owner_split) {
        set_forcing_gains<Dim>(bodies, grid, kernel);
        return;
    }
    for (Particle<Dim>& body : bodies) {
        if (holds_markers_of(grid, body)) {
            set_forcing_gains<Dim>(std::span<Particle<Dim>>(&body, 1), grid, kernel);
        }
    }
}

template <int Dim>
void set_forcing_gains(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                       const AnyKernel& kernel)
{
    for (Particle<Dim>& body : bodies) {
        MarkerCoupling<Dim>& c = body.coupling;
        // Unwrapped: the patch of faces follows the body across a periodic side.
        std::vector<Vec<Dim>> unwrapped(c.offsets.size());
        for (std::size_t l = 0; l < c.offsets.size(); ++l) {
            unwrapped[l] = body.centre + c.offsets[l];
        }
        c.gains = forcing_row_sums<Dim>(kernel, unwrapped, c.markers.volumes, grid.origin(),
                                        grid.spacing());
        for (Vec<Dim>& g : c.gains) {
            g = g.cwiseMax(1.0);
        }
    }
}

template void place_markers<2>(std::span<Particle<2>>, const MacGrid<2>&, const AnyKernel&, long,
                               double, bool, bool, std::span<const char>);
template void place_markers<3>(std::span<Particle<3>>, const MacGrid<3>&, const AnyKernel&, long,
                               double, bool, bool, std::span<const char>);
template void set_forcing_gains<2>(std::span<Particle<2>>, const MacGrid<2>&, const AnyKernel&);
template void set_forcing_gains<3>(std::span<Particle<3>>, const MacGrid<3>&, const AnyKernel&);

} // namespace fddem
