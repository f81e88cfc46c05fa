// SPDX-License-Identifier: MIT
#pragma once
// The issue-15 tests' comparison of an array on a split grid with the one-process array.

#include "fddem/grid/communicator.hpp"
#include "fddem/grid/fields.hpp"
#include "fddem/grid/loops.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fddem::test {

/// The largest |split − whole| over the entries `owned` of each rank, and the largest |whole|
/// there, both over all ranks of `world`.
template <int Dim>
std::pair<double, double> compare_owned(const Communicator& world, const Box<Dim>& owned,
                                        const GridArray<Dim>& split, const GridArray<Dim>& whole)
{
    double worst = 0.0;
    double largest = 0.0;
    for_each_cell_in_vtk_order(owned, [&](const Index<Dim>& i) {
        worst = std::max(worst, std::abs(split(i) - whole(i)));
        largest = std::max(largest, std::abs(whole(i)));
    });
    return {world.max(worst), world.max(largest)};
}

} // namespace fddem::test
