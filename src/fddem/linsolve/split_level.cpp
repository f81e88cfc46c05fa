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

    // Both ranks of a route list its entries alike: for each image (for_each_image's order),
    // the receiver's ghosts that fall in the owner's box, in VTK order.
    for (std::size_t q = 0; q < owned_boxes.size(); ++q) {
        const bool is_me = static_cast<int>(q) == me;
        SplitLevelRoutes::Route in{static_cast<int>(q), {}};
        SplitLevelRoutes::Route out{static_cast<int>(q), {}};
        for_each_image<Dim>(whole_n, periodic, [&](const Index<Dim>& shift) {
            const bool is_unshifted = shift == Index<Dim>{};
            if (is_me && is_unshifted) {
                return; // the owned entries themselves
            }
            // q's entries seen as this rank's ghosts.
            const Box<Dim> received =
                intersection(level.stored, shifted<Dim>(owned_boxes[q], shift));
            for_each_cell_in_vtk_order<Dim>(received, [&](const Index<Dim>& i) {
                if (is_me) {
                    level.routes.images.emplace_back(level.offset(i - shift), level.offset(i));
                } else {
                    in.entries.push_back(level.offset(i));
                }
            });
            if (is_me) {
                return;
            }
            // This rank's entries seen as q's ghosts.
            const Box<Dim> sent =
                intersection(owned_boxes[q].grown(1), shifted<Dim>(level.owned, shift));
            for_each_cell_in_vtk_order<Dim>(
                sent, [&](const Index<Dim>& i) { out.entries.push_back(level.offset(i - shift)); });
        });
        if (!in.entries.empty()) {
            level.routes.receives.push_back(std::move(in));
        }
        if (!out.entries.empty()) {
            level.routes.sends.push_back(std::move(out));
        }
    }
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

} // namespace

template <int Dim>
void fill_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                 std::vector<double>& values)
{
    const auto& routes = level.routes;
    const auto received = swap_entries(ranks, routes.sends, routes.receives, values, fill_tag);
    for (std::size_t r = 0; r < routes.receives.size(); ++r) {
        const auto& entries = routes.receives[r].entries;
        for (std::size_t k = 0; k < entries.size(); ++k) {
            values[entries[k]] = received[r][k];
        }
    }
    for (const auto& [owned, ghost] : routes.images) {
        values[ghost] = values[owned];
    }
}

template <int Dim>
void accumulate_ghosts(const Communicator& ranks, const SplitLevel<Dim>& level,
                       std::vector<double>& values)
{
    const auto& routes = level.routes;
    const auto received =
        swap_entries(ranks, routes.receives, routes.sends, values, accumulate_tag);
    for (std::size_t r = 0; r < routes.sends.size(); ++r) {
        const auto& entries = routes.sends[r].entries;
        for (std::size_t k = 0; k < entries.size(); ++k) {
            values[entries[k]] += received[r][k];
        }
    }
    for (const auto& [owned, ghost] : routes.images) {
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
template void accumulate_ghosts<2>(const Communicator&, const SplitLevel<2>&, std::vector<double>&);
template void accumulate_ghosts<3>(const Communicator&, const SplitLevel<3>&, std::vector<double>&);

} // namespace fddem
