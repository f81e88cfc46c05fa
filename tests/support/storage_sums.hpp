// SPDX-License-Identifier: MIT
#pragma once
// Sums over every entry of a grid array this process stores (owned entries and ghosts), for
// the halo-exchange tests: the adjoint identity ⟨fill x, y⟩ = ⟨x, accumulate y⟩ and the
// conservation of the total hold over all stored entries.

#include "fddem/grid/fields.hpp"
#include "fddem/grid/loops.hpp"

namespace fddem::test {

/// Σ a(i) b(i) over the grid's storage box.
template <int Dim>
double storage_dot(const MacGrid<Dim>& grid, const GridArray<Dim>& a, const GridArray<Dim>& b)
{
    double sum = 0.0;
    for_each_cell_in_vtk_order(grid.storage_box(),
                               [&](const Index<Dim>& i) { sum += a(i) * b(i); });
    return sum;
}

/// Σ a(i) over the grid's storage box.
template <int Dim>
double storage_total(const MacGrid<Dim>& grid, const GridArray<Dim>& a)
{
    double sum = 0.0;
    for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) { sum += a(i); });
    return sum;
}

} // namespace fddem::test
