// SPDX-License-Identifier: MIT
#include "fddem/linsolve/split_level.hpp"

#include "fddem/grid/loops.hpp"
#include "fddem/grid/storage_pieces.hpp"

namespace fddem {

namespace {

/// Message tags of the two exchanges (each completes before the next starts).
constexpr int fill_tag = 31;
constexpr int accumulate_tag = 32;

/// Calls f(shift) for every periodic image of a level, shift the offset of the image in
/// whole-level indices (0 along bounded axes; −n, 0 or n along periodic ones), in a fixed order
/// that every rank follows.
template <int Dim, class F>
void for_each_image(const Index<Dim>& whole_n, const std::array<bool, Dim>& periodic, F&& f)
{
    int count = 1;
    for (int d = 0; d < Dim; ++d) {
        count *= 3;
    }
    for (int k = 0; k < count; ++k) {
        Index<Dim> shift{};
        bool is_image = true;
        int digits = k;
        for (std::size_t d = 0; d < shift.size(); ++d) {
            const int s = digits % 3 - 1;
            digits /= 3;
            is_image = is_image && (s == 0 || periodic[d]);
            shift[d] = s * whole_n[d];
        }
        if (is_image) {
            f(shift);
        }
    }
}

template <int Dim>
Box<Dim> shifted(Box<Dim> box, const Index<Dim>& shift) noexcept
{
    box.lo = box.lo + shift;
    box.hi = box.hi + shift;
    return box;
}

} // namespace

template <int Dim>
StencilView<Dim> SplitLevel<Dim>::owned_view() const noexcept
{
    StencilView<Dim> v = local.view();
    for (int d = 0; d < Dim; ++d) {
        v.n[static_cast<std::size_t>(d)] = owned.extent(d);
    }
    v.periodic = periodic;
    v.origin = static_cast<std::ptrdiff_t>(offset(owned.lo));
    return v;
}

template <int Dim>
std::vector<Box<Dim>> gather_owned_boxes(const Communicator& ranks, const Box<Dim>& mine)
{
    std::vector<int> bounds(mine.lo.begin(), mine.lo.end());
    bounds.insert(bounds.end(), mine.hi.begin(), mine.hi.end());
    const std::vector<int> all = ranks.all_gather(bounds);
    std::vector<Box<Dim>> boxes(static_cast<std::size_t>(ranks.size()));
    for (std::size_t r = 0; r < boxes.size(); ++r) {
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
            boxes[r].lo[d] = all[r * 2 * Dim + d];
            boxes[r].hi[d] = all[r * 2 * Dim + Dim + d];
        }
    }
    return boxes;
}

namespace {

/// Along how many axes `i` lies outside `box`: 1 for a face ghost of the box.
template <int Dim>
int axes_outside(const Box<Dim>& box, const Index<Dim>& i) noexcept
{
    int count = 0;
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        count += i[sd] < box.lo[sd] || i[sd] >= box.hi[sd] ? 1 : 0;
    }
    return count;
}

/// The red–black colour of whole-level index `i` (inside the level: no negative entries).
template <int Dim>
std::size_t colour_of(const Index<Dim>& i) noexcept
{
    int sum = 0;
    for (const int c : i) {
        sum += c;
    }
    return static_cast<std::size_t>(sum % 2);
}

/// The route sets a ghost entry joins: every set's `all`, and the colour's face set if the
/// ghost `ghost` (in the receiver's frame, whose owned box is `receiver`) is a face ghost;
/// `owner_index` is the index its owner stores it at. f(set) is called for each.
template <int Dim, class F>
void for_each_set_of(SplitLevelRoutes& routes, const Box<Dim>& receiver, const Index<Dim>& ghost,
                     const Index<Dim>& owner_index, F&& f)
{
    f(routes.all);
    if (axes_outside<Dim>(receiver, ghost) == 1) {
        f(routes.colour_faces[colour_of<Dim>(owner_index)]);
    }
}

} // namespace

template <int Dim>
SplitLevel<Dim> make_split_level(std::span<const Box<Dim>> owned_boxes, int me,
                                 const Index<Dim>& whole_n, const std::array<bool, Dim>& periodic)
{
    SplitLevel<Dim> level;
    level.whole_n = whole_n;
    level.periodic = periodic;
    level.owned = owned_boxes[static_cast<std::size_t>(me)];
    level.stored = level.owned.grown(1);
    // (local.periodic stays false: the wrap goes through the ghosts.)
    level.local.assign_zero(level.stored.hi - level.stored.lo, {});
    auto routes = std::make_shared<SplitLevelRoutes>();

    // Both ranks of a route list its entries alike: for each image (for_each_image's order),
    // the receiver's ghosts that fall in the owner's box, in VTK order; a ghost joins the same
    // sets on both sides (for_each_set_of, from the receiver's box and the owner's index).
    using Set = SplitLevelRoutes::Set;
    for (std::size_t q = 0; q < owned_boxes.size(); ++q) {
        const bool is_me = static_cast<int>(q) == me;
        std::vector<std::pair<Set*, SplitLevelRoutes::Route>> in;
        std::vector<std::pair<Set*, SplitLevelRoutes::Route>> out;
        const auto route_in = [&](auto& routes_of, Set* set) -> SplitLevelRoutes::Route& {
            for (auto& [s, route] : routes_of) {
                if (s == set) {
                    return route;
                }
            }
            return routes_of.emplace_back(set, SplitLevelRoutes::Route{static_cast<int>(q), {}})
                .second;
        };
        for_each_image<Dim>(whole_n, periodic, [&](const Index<Dim>& shift) {
            const bool is_unshifted = shift == Index<Dim>{};
            if (is_me && is_unshifted) {
                return; // the owned entries themselves
            }
            // q's entries seen as this rank's ghosts.
            const Box<Dim> received =
                intersection(level.stored, shifted<Dim>(owned_boxes[q], shift));
            for_each_cell_in_vtk_order<Dim>(received, [&](const Index<Dim>& i) {
                for_each_set_of<Dim>(*routes, level.owned, i, i - shift, [&](Set& set) {
                    if (is_me) {
                        set.images.emplace_back(level.offset(i - shift), level.offset(i));
                    } else {
                        route_in(in, &set).entries.push_back(level.offset(i));
                    }
                });
            });
            if (is_me) {
                return;
            }
            // This rank's entries seen as q's ghosts.
            const Box<Dim> sent =
                intersection(owned_boxes[q].grown(1), shifted<Dim>(level.owned, shift));
            for_each_cell_in_vtk_order<Dim>(sent, [&](const Index<Dim>& i) {
                for_each_set_of<Dim>(*routes, owned_boxes[q], i, i - shift, [&](Set& set) {
                    route_in(out, &set).entries.push_back(level.offset(i - shift));
                });
            });
        });
        for (auto& [set, route] : in) {
            set->receives.push_back(std::move(route));
        }
        for (auto& [set, route] : out) {
            set->sends.push_back(std::move(route));
        }
    }
    level.routes = std::move(routes);
    return level;
}

namespace {

/// Sends, for every route of `from`, `values` at its entries, and receives for every route of
/// `to` as many values: the buffers received, in the order of `to`.
std::vector<std::vector<double>> swap_entries(const Communicator& ranks,
                                              const std::vector<SplitLevelRoutes::Route>& from,
                                              const std::vector<SplitLevelRoutes::Route>& to,
                                              const std::vector<double>& values, int tag)
{
    std::vector<std::vector<double>> packed;
    packed.reserve(from.size());
    std::vector<Communicator::Outgoing> sends;
    for (const auto& route : from) {
        std::vector<double>& buffer = packed.emplace_back();
        buffer.reserve(route.entries.size());
        for (const std::size_t e : route.entries) {
            buffer.push_back(values[e]);
        }
        sends.push_back({route.rank, buffer});
    }
    std::vector<std::vector<double>> received;
    received.reserve(to.size());
    std::vector<Communicator::Incoming> receives;
    for (const auto& route : to) {
        receives.push_back({route.rank, received.emplace_back(route.entries.size())});
    }
    if (!sends.empty() || !receives.empty()) {
        ranks.send_and_receive(sends, receives, tag);
    }
    return received;
}

/// fill_ghosts over the routes of `set`.
void fill_over(const Communicator& ranks, const SplitLevelRoutes::Set& set,
               std::vector<double>& values)
{
    const auto received = swap_entries(ranks, set.sends, set.receives, values, fill_tag);
    for (std::size_t r = 0; r < set.receives.size(); ++r) {
        const auto& entries = set.receives[r].entries;
        for (std::size_t k = 0; k < entries.size(); ++k) {
            values[entries[k]] = received[r][k];
        }
    }
    for (const auto& [owned, ghost] : set.images) {
        values[ghost] = values[owned];
    }
}

} // namespace

template <int Dim>
void fill_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                 std::vector<double>& values)
{
    fill_over(ranks, level.routes->all, values);
}

template <int Dim>
void fill_face_ghosts_of_colour(const Communicator& ranks, const SplitLevel<Dim>& level,
                                std::vector<double>& values, int colour)
{
    fill_over(ranks, level.routes->colour_faces[static_cast<std::size_t>(colour)], values);
}

template <int Dim>
void accumulate_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                       std::vector<double>& values)
{
    const SplitLevelRoutes::Set& set = level.routes->all;
    const auto received = swap_entries(ranks, set.receives, set.sends, values, accumulate_tag);
    for (std::size_t r = 0; r < set.sends.size(); ++r) {
        const auto& entries = set.sends[r].entries;
        for (std::size_t k = 0; k < entries.size(); ++k) {
            values[entries[k]] += received[r][k];
        }
    }
    for (const auto& [owned, ghost] : set.images) {
        values[owned] += values[ghost];
    }
}

template struct SplitLevel<2>;
template struct SplitLevel<3>;
template std::vector<Box<2>> gather_owned_boxes<2>(const Communicator&, const Box<2>&);
template std::vector<Box<3>> gather_owned_boxes<3>(const Communicator&, const Box<3>&);
template SplitLevel<2> make_split_level<2>(std::span<const Box<2>>, int, const Index<2>&,
                                           const std::array<bool, 2>&);
template SplitLevel<3> make_split_level<3>(std::span<const Box<3>>, int, const Index<3>&,
                                           const std::array<bool, 3>&);
template void fill_ghosts<2>(const Communicator&, const SplitLevel<2>&, std::vector<double>&);
template void fill_ghosts<3>(const Communicator&, const SplitLevel<3>&, std::vector<double>&);
template void fill_face_ghosts_of_colour<2>(const Communicator&, const SplitLevel<2>&,
                                            std::vector<double>&, int);
template void fill_face_ghosts_of_colour<3>(const Communicator&, const SplitLevel<3>&,
                                            std::vector<double>&, int);
template void accumulate_ghosts<2>(const Communicator&, const SplitLevel<2>&, std::vector<double>&);
template void accumulate_ghosts<3>(const Communicator&, const SplitLevel<3>&, std::vector<double>&);

} // namespace fddem
