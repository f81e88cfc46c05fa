// SPDX-License-Identifier: MIT
#pragma once
/// The entries of a grid array over a box, as one contiguous buffer (x fastest), and back: what
/// a message between ranks carries (grid/halo_exchange.cpp), and a checkpoint's piece
/// (io/piece_archive.hpp).

#include "fddem/grid/fields.hpp"
#include "fddem/grid/loops.hpp"

#include <vector>

namespace fddem {

/// The values of `array` over `box`, x fastest.
template <int Dim>
[[nodiscard]] std::vector<double> pack(const GridArray<Dim>& array, const Box<Dim>& box)
{
    std::vector<double> buffer;
    buffer.reserve(box.size());
    for_each_cell_in_vtk_order(box, [&](const Index<Dim>& i) { buffer.push_back(array(i)); });
    return buffer;
}

/// Writes `buffer` (x fastest, as pack gives it) into `array` over `box`.
template <int Dim>
void unpack(GridArray<Dim>& array, const Box<Dim>& box, const std::vector<double>& buffer)
{
    std::size_t k = 0;
    for_each_cell_in_vtk_order(box, [&](const Index<Dim>& i) { array(i) = buffer[k++]; });
}

} // namespace fddem
