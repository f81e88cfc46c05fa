// SPDX-License-Identifier: MIT
#include "fddem/linsolve/split_multigrid.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"

#include <algorithm>
#include <limits>

namespace fddem {

namespace {

/// Whether `level` is smoothed split and has a split level below it whose ranks own
/// `next_boxes` (the conditions in split_multigrid.hpp).
template <int Dim>
bool stays_split(const SplitLevel<Dim>& level, const std::vector<Box<Dim>>& next_boxes)
{
    Box<Dim> whole;
    whole.hi = level.whole_n;
    if (whole.size() <= coarsest_level_size || coarse_extent<Dim>(level.whole_n) == level.whole_n) {
        return false;
    }
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        if (level.periodic[sd] && level.whole_n[sd] % 2 != 0) {
            return false;
        }
        for (const Box<Dim>& box : next_boxes) {
            if (box.extent(d) < 1) {
                return false; // some rank would own nothing
            }
        }
    }
    return true;
}

/// Adds the ranks' shares of the level's operator up on the owners.
template <int Dim>
void accumulate_operator(const Communicator& ranks, SplitLevel<Dim>& level)
{
    accumulate_ghosts(ranks, level, level.local.diagonal);
    for (auto& a : level.local.a_nb) {
        accumulate_ghosts(ranks, level, a);
    }
}

/// rhs − A x at stored offset `o` of an owned unknown (its neighbours' ghosts filled; the links
/// out of a bounded side are zero).
template <int Dim>
double residual(const CoarseLevel<Dim>& local, const std::array<std::size_t, Dim>& stride,
                std::size_t o) noexcept
{
    double product = local.diagonal[o] * local.x[o];
    for (std::size_t d = 0; d < stride.size(); ++d) {
        product -= local.a_nb[2 * d][o] * local.x[o - stride[d]];
        product -= local.a_nb[2 * d + 1][o] * local.x[o + stride[d]];
    }
    return local.rhs[o] - product;
}

/// A red–black Gauss–Seidel sweep over the owned unknowns, red (even index sum) first or black
/// first. After each colour the face ghosts of that colour are filled, which is all the next
/// colour and the residual read; after the second, every ghost if `is_all_filled_after`.
template <int Dim>
void relax(const Communicator& ranks, SplitLevel<Dim>& level, bool is_red_first,
           bool is_all_filled_after)
{
    const std::array<std::size_t, Dim> stride = level.local.strides();
    CoarseLevel<Dim>& local = level.local;
    for (int pass = 0; pass < 2; ++pass) {
        const int colour = is_red_first ? pass : 1 - pass;
        for_each_row(level.owned, [&](const Index<Dim>& row) {
            int parity = colour;
            for (const int c : row) {
                parity += c;
            }
            Index<Dim> i = row;
            i[0] += parity % 2; // the first unknown of the colour in the row
            for (; i[0] < level.owned.hi[0]; i[0] += 2) {
                const std::size_t o = level.offset(i);
                local.x[o] += interior_update<Dim>(local, stride, o); // every neighbour stored
            }
        });
        if (pass == 1 && is_all_filled_after) {
            fill_ghosts(ranks, level, local.x);
        } else {
            fill_face_ghosts_of_colour(ranks, level, local.x, colour);
        }
    }
}

/// next.rhs = the residual of `level` summed over each block (the ranks' shares added on the
/// owners), next.x = 0.
template <int Dim>
void restrict_to(const Communicator& ranks, const SplitLevel<Dim>& level, SplitLevel<Dim>& next)
{
    std::fill(next.local.rhs.begin(), next.local.rhs.end(), 0.0);
    std::fill(next.local.x.begin(), next.local.x.end(), 0.0);
    const std::array<std::size_t, Dim> stride = level.local.strides();
    // In VTK order a block's members come in the order restrict_sum adds them.
    for_each_cell_in_vtk_order<Dim>(level.owned, [&](const Index<Dim>& i) {
        next.local.rhs[next.offset(coarse_index<Dim>(i))] +=
            residual<Dim>(level.local, stride, level.offset(i));
    });
    accumulate_ghosts(ranks, next, next.local.rhs);
}

/// `count` as an MPI count, or an InternalError.
int gathered_count(std::size_t count)
{
    if (count > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        throw InternalError("split multigrid: a gathered part of more than 2^31 values");
    }
    return static_cast<int>(count);
}

/// The owned entries of `arrays` (stored arrays of the gathered level) of every rank into
/// `whole_arrays` (the root's whole level) on the root: one personalised all-to-all in which
/// the others receive nothing.
template <int Dim>
void gather_on_root(const Communicator& ranks, const SplitHierarchy<Dim>& hierarchy,
                    std::span<const std::vector<double>* const> arrays,
                    std::span<std::vector<double>* const> whole_arrays)
{
    const SplitLevel<Dim>& level = hierarchy.levels.back();
    const int root = split_coarse_root(ranks);
    const bool is_root = ranks.rank() == root;
    std::vector<double> mine;
    mine.reserve(level.owned.size() * arrays.size());
    for (const std::vector<double>* values : arrays) {
        for_each_cell_in_vtk_order<Dim>(
            level.owned, [&](const Index<Dim>& i) { mine.push_back((*values)[level.offset(i)]); });
    }
    // Every rank checks every part's count, so that all throw alike rather than some wait.
    std::vector<int> counts;
    std::size_t total = 0;
    for (const Box<Dim>& box : hierarchy.last_boxes) {
        counts.push_back(gathered_count(box.size() * arrays.size()));
        total += box.size() * arrays.size();
    }
    std::vector<int> send_counts(counts.size(), 0);
    send_counts[static_cast<std::size_t>(root)] = counts[static_cast<std::size_t>(ranks.rank())];
    const std::vector<int> receive_counts = is_root ? counts : std::vector<int>(counts.size(), 0);
    if (!is_root) {
        total = 0;
    }
    std::vector<double> all(total);
    ranks.all_to_all(mine, send_counts, all, receive_counts);
    if (!is_root) {
        return;
    }
    const CoarseLevel<Dim>& whole = hierarchy.root_levels.front();
    std::size_t at = 0;
    for (const Box<Dim>& box : hierarchy.last_boxes) {
        for (std::vector<double>* values : whole_arrays) {
            for_each_cell_in_vtk_order<Dim>(
                box, [&](const Index<Dim>& c) { (*values)[whole.offset(c)] = all[at++]; });
        }
    }
}

/// The gathered level's rhs onto the root, which solves it and the levels below it; then each
/// rank's owned part of the solution back to it, and its ghosts filled.
template <int Dim>
void solve_gathered(const Communicator& ranks, SplitHierarchy<Dim>& hierarchy, int sweeps)
{
    SplitLevel<Dim>& level = hierarchy.levels.back();
    const int root = split_coarse_root(ranks);
    const bool is_root = ranks.rank() == root;
    std::vector<double>* whole_rhs = nullptr;
    if (is_root) {
        whole_rhs = &hierarchy.root_levels.front().rhs;
    }
    const std::vector<double>* const local_rhs[] = {&level.local.rhs};
    gather_on_root<Dim>(ranks, hierarchy, local_rhs, std::span(&whole_rhs, is_root ? 1 : 0));
    std::vector<int> send_counts(hierarchy.last_boxes.size(), 0);
    std::vector<double> parts;
    if (is_root) {
        CoarseLevel<Dim>& whole = hierarchy.root_levels.front();
        std::fill(whole.x.begin(), whole.x.end(), 0.0);
        coarse_v_cycle(hierarchy.root_levels, 0, sweeps);
        for (std::size_t r = 0; r < send_counts.size(); ++r) {
            send_counts[r] = gathered_count(hierarchy.last_boxes[r].size());
            for_each_cell_in_vtk_order<Dim>(hierarchy.last_boxes[r], [&](const Index<Dim>& c) {
                parts.push_back(whole.x[whole.offset(c)]);
            });
        }
    }
    std::vector<int> receive_counts(hierarchy.last_boxes.size(), 0);
    receive_counts[static_cast<std::size_t>(root)] = gathered_count(level.owned.size());
    std::vector<double> part(level.owned.size());
    ranks.all_to_all(parts, send_counts, part, receive_counts);
    std::size_t at = 0;
    for_each_cell_in_vtk_order<Dim>(
        level.owned, [&](const Index<Dim>& i) { level.local.x[level.offset(i)] = part[at++]; });
    fill_ghosts(ranks, level, level.local.x);
}

template <int Dim>
void v_cycle_from(const Communicator& ranks, SplitHierarchy<Dim>& hierarchy, std::size_t k,
                  int sweeps)
{
    if (k + 1 == hierarchy.levels.size()) {
        solve_gathered(ranks, hierarchy, sweeps);
        return;
    }
    SplitLevel<Dim>& level = hierarchy.levels[k];
    SplitLevel<Dim>& next = hierarchy.levels[k + 1];
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        relax(ranks, level, true, false);
    }
    restrict_to(ranks, level, next);
    v_cycle_from(ranks, hierarchy, k + 1, sweeps);
    for_each_cell_in_vtk_order<Dim>(level.owned, [&](const Index<Dim>& i) {
        level.local.x[level.offset(i)] += next.local.x[next.offset(coarse_index<Dim>(i))];
    });
    fill_ghosts(ranks, level, level.local.x);
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        relax(ranks, level, false, sweep + 1 == sweeps);
    }
}

/// The layout below `fine`: the split levels' boxes and routes while stays_split holds (one
/// gather of every rank's box), and the owned boxes of the last.
template <int Dim>
SplitLayout<Dim> make_layout(const Communicator& ranks, const StencilView<Dim>& fine,
                             const LevelPart<Dim>& part)
{
    SplitLayout<Dim> layout{part, fine.n, fine.periodic, {}, {}};
    const int me = ranks.rank();
    const Box<Dim> fine_owned{part.offset, part.offset + fine.n};
    std::vector<Box<Dim>> boxes = gather_owned_boxes<Dim>(ranks, coarse_owned_box<Dim>(fine_owned));
    auto& levels = layout.levels;
    levels.push_back(
        make_split_level<Dim>(boxes, me, coarse_extent<Dim>(part.whole_n), fine.periodic));
    for (;;) {
        std::vector<Box<Dim>> next_boxes;
        next_boxes.reserve(boxes.size());
        for (const Box<Dim>& box : boxes) {
            next_boxes.push_back(coarse_owned_box<Dim>(box));
        }
        if (!stays_split(levels.back(), next_boxes)) {
            break;
        }
        const SplitLevel<Dim>& last = levels.back();
        levels.push_back(
            make_split_level<Dim>(next_boxes, me, coarse_extent<Dim>(last.whole_n), last.periodic));
        boxes = std::move(next_boxes);
    }
    for (SplitLevel<Dim>& level : levels) {
        level.local = CoarseLevel<Dim>{}; // the layout keeps no arrays
    }
    layout.last_boxes = std::move(boxes);
    return layout;
}

} // namespace

template <int Dim>
void build_split_levels(const Communicator& ranks, const StencilView<Dim>& fine,
                        const LevelPart<Dim>& part, SplitHierarchy<Dim>& hierarchy)
{
    SplitLayout<Dim>& layout = hierarchy.layout;
    if (!layout.is_for(fine, part)) {
        layout = make_layout<Dim>(ranks, fine, part);
    }
    auto& levels = hierarchy.levels;
    levels.resize(layout.levels.size());
    for (std::size_t k = 0; k < levels.size(); ++k) {
        CoarseLevel<Dim> arrays = std::move(levels[k].local); // keeps its allocations
        levels[k] = layout.levels[k];
        levels[k].local = std::move(arrays);
        levels[k].local.assign_zero(levels[k].stored.hi - levels[k].stored.lo, {});
        if (k == 0) {
            aggregate_part<Dim>(fine, part, levels[0].stored.lo, levels[0].local);
        } else {
            aggregate_part<Dim>(levels[k - 1].owned_view(), levels[k - 1].part(),
                                levels[k].stored.lo, levels[k].local);
        }
        accumulate_operator(ranks, levels[k]);
    }
    hierarchy.last_boxes = layout.last_boxes;

    const bool is_root = ranks.rank() == split_coarse_root(ranks);
    std::vector<std::vector<double>*> whole_arrays;
    if (is_root) {
        hierarchy.root_levels.resize(1);
        CoarseLevel<Dim>& whole = hierarchy.root_levels.front();
        whole.assign_zero(levels.back().whole_n, levels.back().periodic);
        whole_arrays.push_back(&whole.diagonal);
        for (auto& a : whole.a_nb) {
            whole_arrays.push_back(&a);
        }
    } else {
        hierarchy.root_levels.clear();
    }
    std::vector<const std::vector<double>*> arrays{&levels.back().local.diagonal};
    for (const auto& a : levels.back().local.a_nb) {
        arrays.push_back(&a);
    }
    gather_on_root<Dim>(ranks, hierarchy, arrays, whole_arrays);
    if (is_root) {
        extend_coarse_levels(hierarchy.root_levels);
    }
}

template <int Dim>
void split_v_cycle(const Communicator& ranks, SplitHierarchy<Dim>& hierarchy, int sweeps)
{
    SplitLevel<Dim>& first = hierarchy.levels.front();
    accumulate_ghosts(ranks, first, first.local.rhs);
    std::fill(first.local.x.begin(), first.local.x.end(), 0.0);
    v_cycle_from(ranks, hierarchy, 0, sweeps);
}

template void build_split_levels<2>(const Communicator&, const StencilView<2>&, const LevelPart<2>&,
                                    SplitHierarchy<2>&);
template void build_split_levels<3>(const Communicator&, const StencilView<3>&, const LevelPart<3>&,
                                    SplitHierarchy<3>&);
template void split_v_cycle<2>(const Communicator&, SplitHierarchy<2>&, int);
template void split_v_cycle<3>(const Communicator&, SplitHierarchy<3>&, int);

} // namespace fddem
