// SPDX-License-Identifier: MIT
#include "fddem/grid/gather_storage.hpp"

#include "fddem/grid/box_values.hpp"
#include "fddem/grid/loops.hpp"

#include <vector>

namespace fddem {

namespace {

// Message tags of a gather: the box first, then its values.
constexpr int tag_box = 41;
constexpr int tag_values = 42;

} // namespace

template <int Dim>
Box<Dim> contributed_box(const MacGrid<Dim>& grid) noexcept
{
    Box<Dim> box = grid.owned_cells();
    const Box<Dim> storage = grid.storage_box();
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        if (grid.partition().coords[sd] == 0) {
            box.lo[sd] = storage.lo[sd];
        }
        if (grid.partition().coords[sd] + 1 == grid.partition().ranks[sd]) {
            box.hi[sd] = storage.hi[sd];
        }
    }
    return box;
}

template <int Dim>
void gather_to_root(const MacGrid<Dim>& grid, const GridArray<Dim>& part, GridArray<Dim>& whole)
{
    const Communicator& ranks = grid.communicator();
    const Box<Dim> mine = contributed_box(grid);
    if (ranks.rank() != 0) {
        std::vector<double> box(2 * Dim);
        for (std::size_t d = 0; d < Dim; ++d) {
            box[d] = mine.lo[d];
            box[Dim + d] = mine.hi[d];
        }
        ranks.exchange(box, 0, {}, Communicator::no_rank, tag_box);
        ranks.exchange(pack(part, mine), 0, {}, Communicator::no_rank, tag_values);
        return;
    }
    unpack(whole, mine, pack(part, mine));
    for (int source = 1; source < ranks.size(); ++source) {
        std::vector<double> box(2 * Dim);
        ranks.exchange({}, Communicator::no_rank, box, source, tag_box);
        Box<Dim> theirs;
        for (std::size_t d = 0; d < Dim; ++d) {
            theirs.lo[d] = static_cast<int>(box[d]);
            theirs.hi[d] = static_cast<int>(box[Dim + d]);
        }
        std::vector<double> values(theirs.size());
        ranks.exchange({}, Communicator::no_rank, values, source, tag_values);
        unpack(whole, theirs, values);
    }
}

template <int Dim>
void take_block(const MacGrid<Dim>& grid, const GridArray<Dim>& whole, GridArray<Dim>& part)
{
    // A block's storage lies inside the one-process storage box (the block's ghosts beyond a
    // side of the domain are the one-process ghosts there).
    for_each_cell_in_vtk_order(grid.storage_box(),
                               [&](const Index<Dim>& i) { part(i) = whole(i); });
}

template Box<2> contributed_box<2>(const MacGrid<2>&) noexcept;
template Box<3> contributed_box<3>(const MacGrid<3>&) noexcept;
template void gather_to_root<2>(const MacGrid<2>&, const GridArray<2>&, GridArray<2>&);
template void gather_to_root<3>(const MacGrid<3>&, const GridArray<3>&, GridArray<3>&);
template void take_block<2>(const MacGrid<2>&, const GridArray<2>&, GridArray<2>&);
template void take_block<3>(const MacGrid<3>&, const GridArray<3>&, GridArray<3>&);

} // namespace fddem
