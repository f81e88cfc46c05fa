// SPDX-License-Identifier: MIT
#include "fddem/coupling/marker_routes.hpp"

#include "fddem/core/errors.hpp"

#include <initializer_list>
#include <map>

namespace fddem {
namespace {

// Message tags of the marker routes, apart from every other exchange's on the grid's
// communicator (the gather's 41 and 42, the halo exchange's).
constexpr int tag_to_owners = 71;
constexpr int tag_to_holders = 72;
constexpr int tag_hand_over = 73;

/// Makes some values of every body the owner's on every rank: each rank writes, for the bodies
/// it owns, `size(body)` values by `pack`, in store order; one gather over the ranks
/// (Communicator::all_gather) hands every rank every owner's values, bit for bit, read back by
/// `unpack` in the owners' rank order. Each rank receives the values once (a sum with zeros
/// from the non-owners received them once from every rank: the ranks' number times over).
template <int Dim, class Size, class Pack, class Unpack>
void share_from_owners(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid, Size size,
                       Pack pack, Unpack unpack)
{
    const Communicator& ranks = grid.communicator();
    if (ranks.size() == 1) {
        return;
    }
    const auto n_ranks = static_cast<std::size_t>(ranks.size());
    // Every rank knows every body's owner: the bodies of each rank, in store order.
    std::vector<std::vector<std::size_t>> owned(n_ranks);
    std::vector<int> counts(n_ranks, 0);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const auto owner = static_cast<std::size_t>(owner_rank(grid, bodies[b]));
        owned[owner].push_back(b);
        counts[owner] += static_cast<int>(size(bodies[b]));
    }
    const auto me = static_cast<std::size_t>(ranks.rank());
    std::vector<double> mine(static_cast<std::size_t>(counts[me]));
    std::size_t at = 0;
    for (const std::size_t b : owned[me]) {
        const std::size_t n = size(bodies[b]);
        pack(b, std::span<double>(mine).subspan(at, n));
        at += n;
    }
    std::size_t total = 0;
    for (const int c : counts) {
        total += static_cast<std::size_t>(c);
    }
    std::vector<double> all(total);
    ranks.all_gather(mine, counts, all);
    at = 0;
    for (const std::vector<std::size_t>& list : owned) {
        for (const std::size_t b : list) {
            const std::size_t n = size(bodies[b]);
            unpack(b, std::span<const double>(all).subspan(at, n));
            at += n;
        }
    }
}

template <class Values>
void put(std::span<double> out, std::size_t& at, const Values& v, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i) {
        out[at++] = v[static_cast<Eigen::Index>(i)];
    }
}

template <class Values>
void take(std::span<const double> in, std::size_t& at, Values& v, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i) {
        v[static_cast<Eigen::Index>(i)] = in[at++];
    }
}

/// The marker arrays a message carries, in this order for each marker.
template <int Dim>
using MarkerArrays = std::initializer_list<std::vector<Vec<Dim>> MarkerCoupling<Dim>::*>;

/// `arrays` at the markers of `sends` to their ranks, and at those of `receives` from theirs,
/// into the bodies' records: one message each way per rank. Both sides list the same markers in
/// the same order.
template <int Dim>
void send_marker_values(std::span<Particle<Dim>> bodies, const Communicator& ranks,
                        std::span<const MarkerLink> sends, std::span<const MarkerLink> receives,
                        MarkerArrays<Dim> arrays, int tag)
{
    std::vector<std::vector<double>> out(sends.size());
    std::vector<Communicator::Outgoing> messages;
    for (std::size_t k = 0; k < sends.size(); ++k) {
        for (const auto& [b, l] : sends[k].markers) {
            for (const auto array : arrays) {
                const Vec<Dim>& v = (bodies[b].coupling.*array)[l];
                out[k].insert(out[k].end(), v.data(), v.data() + Dim);
            }
        }
        messages.push_back({sends[k].rank, out[k]});
    }
    std::vector<std::vector<double>> in(receives.size());
    std::vector<Communicator::Incoming> slots;
    for (std::size_t k = 0; k < receives.size(); ++k) {
        in[k].resize(receives[k].markers.size() * arrays.size() * Dim);
        slots.push_back({receives[k].rank, in[k]});
    }
    ranks.send_and_receive(messages, slots, tag);
    for (std::size_t k = 0; k < receives.size(); ++k) {
        std::size_t at = 0;
        for (const auto& [b, l] : receives[k].markers) {
            for (const auto array : arrays) {
                take(in[k], at, (bodies[b].coupling.*array)[l], Dim);
            }
        }
    }
}

template <int Dim>
constexpr std::size_t angular_size = Dim == 2 ? 1 : 3;

template <int Dim>
double& angular_entry(AngularVec<Dim>& w, std::size_t i)
{
    if constexpr (Dim == 2) {
        (void)i;
        return w;
    } else {
        return w[static_cast<Eigen::Index>(i)];
    }
}

/// A body's vector and angular quantity (U and ω, or force and torque) into `out` from `at`.
template <int Dim>
void put_rigid(std::span<double> out, std::size_t& at, const Vec<Dim>& v, AngularVec<Dim> w)
{
    put(out, at, v, Dim);
    for (std::size_t i = 0; i < angular_size<Dim>; ++i) {
        out[at++] = angular_entry<Dim>(w, i);
    }
}

/// The reverse of put_rigid.
template <int Dim>
void take_rigid(std::span<const double> in, std::size_t& at, Vec<Dim>& v, AngularVec<Dim>& w)
{
    take(in, at, v, Dim);
    for (std::size_t i = 0; i < angular_size<Dim>; ++i) {
        angular_entry<Dim>(w, i) = in[at++];
    }
}

} // namespace

template <int Dim>
MarkerRoutes<Dim>::MarkerRoutes(std::span<const Particle<Dim>> bodies, const MacGrid<Dim>& grid)
    : is_owned_(bodies.size(), 0), ranks_(&grid.communicator())
{
    const int me = ranks_->rank();
    std::map<int, MarkerLink> to_owners;
    std::map<int, MarkerLink> from_holders;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const int owner = owner_rank(grid, bodies[b]);
        is_owned_[b] = owner == me ? 1 : 0;
        if (owner != me && !holds_markers_of(grid, bodies[b])) {
            continue; // no marker in this rank's cells
        }
        const std::vector<Vec<Dim>>& positions = bodies[b].coupling.positions;
        for (std::size_t l = 0; l < positions.size(); ++l) {
            const int holder = grid.rank_of_point(positions[l]);
            if ((holder == me) != grid.owns_point(positions[l])) {
                throw InternalError("MarkerRoutes: rank_of_point and owns_point disagree");
            }
            const auto entry =
                std::pair{static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(l)};
            if (owner == me && holder != me) {
                MarkerLink& link = from_holders[holder];
                link.rank = holder;
                link.markers.push_back(entry);
            } else if (owner != me && holder == me) {
                MarkerLink& link = to_owners[owner];
                link.rank = owner;
                link.markers.push_back(entry);
            }
        }
    }
    for (auto& [rank, link] : to_owners) {
        to_owners_.push_back(std::move(link));
    }
    for (auto& [rank, link] : from_holders) {
        from_holders_.push_back(std::move(link));
    }
}

template <int Dim>
std::vector<int> MarkerRoutes<Dim>::peers() const
{
    std::map<int, int> seen;
    for (const MarkerLink& link : to_owners_) {
        seen[link.rank] = 1;
    }
    for (const MarkerLink& link : from_holders_) {
        seen[link.rank] = 1;
    }
    std::vector<int> out;
    for (const auto& [rank, flag] : seen) {
        out.push_back(rank);
    }
    return out;
}

template <int Dim>
void MarkerRoutes<Dim>::gather_at_owners(std::span<Particle<Dim>> bodies) const
{
    send_marker_values<Dim>(bodies, *ranks_, to_owners_, from_holders_,
                            {&MarkerCoupling<Dim>::fluid}, tag_to_owners);
}

template <int Dim>
void MarkerRoutes<Dim>::return_to_holders(std::span<Particle<Dim>> bodies) const
{
    send_marker_values<Dim>(bodies, *ranks_, from_holders_, to_owners_,
                            {&MarkerCoupling<Dim>::lambda, &MarkerCoupling<Dim>::lambda_star},
                            tag_to_holders);
}

template <int Dim>
void hand_over(std::span<Particle<Dim>> bodies, std::span<const int> previous_owners,
               const MacGrid<Dim>& grid)
{
    const Communicator& ranks = grid.communicator();
    if (ranks.size() == 1) {
        return;
    }
    const int me = ranks.rank();
    std::map<int, MarkerLink> sends;
    std::map<int, MarkerLink> receives;
    const auto add = [](std::map<int, MarkerLink>& links, int rank, std::size_t b, std::size_t l) {
        MarkerLink& link = links[rank];
        link.rank = rank;
        link.markers.emplace_back(static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(l));
    };
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const int from = previous_owners[b];
        if (from != me && !holds_markers_of(grid, bodies[b])) {
            continue; // neither sends (not the old owner) nor receives (no marker here now)
        }
        const int owner = owner_rank(grid, bodies[b]);
        const std::vector<Vec<Dim>>& positions = bodies[b].coupling.positions;
        for (std::size_t l = 0; l < positions.size(); ++l) {
            // The new owner needs every marker; a holder those in its cells.
            const int holder = grid.rank_of_point(positions[l]);
            for (const int to : {owner, holder == owner ? from : holder}) {
                if (to == from) {
                    continue; // it has them
                }
                if (from == me) {
                    add(sends, to, b, l);
                } else if (to == me) {
                    add(receives, from, b, l);
                }
            }
        }
    }
    std::vector<MarkerLink> out;
    std::vector<MarkerLink> in;
    for (auto& [rank, link] : sends) {
        out.push_back(std::move(link));
    }
    for (auto& [rank, link] : receives) {
        in.push_back(std::move(link));
    }
    send_marker_values<Dim>(bodies, ranks, out, in,
                            {&MarkerCoupling<Dim>::lambda, &MarkerCoupling<Dim>::lambda_star},
                            tag_hand_over);
}

template <int Dim>
void share_motion(std::span<Particle<Dim>> bodies, std::span<RigidVelocity<Dim>> motions,
                  const MacGrid<Dim>& grid)
{
    constexpr std::size_t n = Dim + angular_size<Dim> + 1;
    share_from_owners<Dim>(
        bodies, grid, [](const Particle<Dim>&) { return n; },
        [&](std::size_t b, std::span<double> out) {
            std::size_t at = 0;
            put_rigid<Dim>(out, at, motions[b].velocity, motions[b].omega);
            out[at] = bodies[b].coupling.forcing_change;
        },
        [&](std::size_t b, std::span<const double> in) {
            std::size_t at = 0;
            take_rigid<Dim>(in, at, motions[b].velocity, motions[b].omega);
            bodies[b].coupling.forcing_change = in[at];
        });
}

template <int Dim>
void share_loads(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid)
{
    constexpr std::size_t n = Dim + angular_size<Dim>;
    share_from_owners<Dim>(
        bodies, grid, [](const Particle<Dim>&) { return n; },
        [&](std::size_t b, std::span<double> out) {
            std::size_t at = 0;
            put_rigid<Dim>(out, at, bodies[b].force, bodies[b].torque);
        },
        [&](std::size_t b, std::span<const double> in) {
            std::size_t at = 0;
            take_rigid<Dim>(in, at, bodies[b].force, bodies[b].torque);
        });
}

template <int Dim>
void share_markers(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid)
{
    share_from_owners<Dim>(
        bodies, grid,
        [](const Particle<Dim>& body) { return 3 * Dim * body.coupling.markers.size(); },
        [&](std::size_t b, std::span<double> out) {
            MarkerCoupling<Dim>& c = bodies[b].coupling;
            const std::size_t n = c.markers.size() * Dim;
            std::size_t at = 0;
            for (auto* values : {&c.fluid, &c.lambda, &c.lambda_star}) {
                const std::span<double> v = flat_values<Dim>(*values);
                std::copy(v.begin(), v.end(), out.begin() + static_cast<std::ptrdiff_t>(at));
                at += n;
            }
        },
        [&](std::size_t b, std::span<const double> in) {
            MarkerCoupling<Dim>& c = bodies[b].coupling;
            const std::size_t n = c.markers.size() * Dim;
            std::size_t at = 0;
            for (auto* values : {&c.fluid, &c.lambda, &c.lambda_star}) {
                const std::span<double> v = flat_values<Dim>(*values);
                std::copy_n(in.begin() + static_cast<std::ptrdiff_t>(at), n, v.begin());
                at += n;
            }
        });
}

template class MarkerRoutes<2>;
template class MarkerRoutes<3>;
template void hand_over<2>(std::span<Particle<2>>, std::span<const int>, const MacGrid<2>&);
template void hand_over<3>(std::span<Particle<3>>, std::span<const int>, const MacGrid<3>&);
template void share_motion<2>(std::span<Particle<2>>, std::span<RigidVelocity<2>>,
                              const MacGrid<2>&);
template void share_motion<3>(std::span<Particle<3>>, std::span<RigidVelocity<3>>,
                              const MacGrid<3>&);
template void share_loads<2>(std::span<Particle<2>>, const MacGrid<2>&);
template void share_loads<3>(std::span<Particle<3>>, const MacGrid<3>&);
template void share_markers<2>(std::span<Particle<2>>, const MacGrid<2>&);
template void share_markers<3>(std::span<Particle<3>>, const MacGrid<3>&);

} // namespace fddem
