// SPDX-License-Identifier: MIT
#include "fddem/grid/grid_partition.hpp"

#include "fddem/core/errors.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace fddem {
namespace {

constexpr std::size_t ax(int axis) noexcept
{
    return static_cast<std::size_t>(axis);
}

template <int Dim>
std::string cells_text(const Index<Dim>& cells)
{
    std::string text;
    for (int d = 0; d < Dim; ++d) {
        text += (d == 0 ? "" : " × ") + std::to_string(cells[ax(d)]);
    }
    return text;
}

/// Whether every block of `ranks` is at least min_block_cells thick along every split axis.
template <int Dim>
bool blocks_are_thick_enough(const Index<Dim>& cells, const Index<Dim>& ranks)
{
    for (int d = 0; d < Dim; ++d) {
        const int p = ranks[ax(d)];
        if (p < 1 || (p > 1 && cells[ax(d)] / p < min_block_cells)) {
            return false;
        }
    }
    return true;
}

/// Total area (in cell faces) of the interfaces between blocks.
template <int Dim>
double interface_area(const Index<Dim>& cells, const Index<Dim>& ranks)
{
    double area = 0.0;
    for (int d = 0; d < Dim; ++d) {
        double cross = 1.0;
        for (int e = 0; e < Dim; ++e) {
            cross *= e == d ? 1.0 : cells[ax(e)];
        }
        area += (ranks[ax(d)] - 1) * cross;
    }
    return area;
}

/// Calls f(layout) for every way to write n as a product of Dim factors.
template <int Dim, class F>
void for_each_factorisation(int n, Index<Dim>& layout, int axis, F& f)
{
    if (axis == Dim - 1) {
        layout[ax(axis)] = n;
        f(layout);
        return;
    }
    for (int p = 1; p <= n; ++p) {
        if (n % p == 0) {
            layout[ax(axis)] = p;
            for_each_factorisation<Dim>(n / p, layout, axis + 1, f);
        }
    }
}

} // namespace

std::pair<int, int> block_range(int n, int parts, int part)
{
    if (parts < 1 || part < 0 || part >= parts) {
        throw InternalError("block_range: part " + std::to_string(part) + " of " +
                            std::to_string(parts));
    }
    const int base = n / parts;
    const int extra = n % parts;
    const int lo = part * base + (part < extra ? part : extra);
    return {lo, lo + base + (part < extra ? 1 : 0)};
}

int block_of_cell(int n, int parts, int i) noexcept
{
    const int base = n / parts;
    const int extra = n % parts;
    const int long_cells = extra * (base + 1); // the first `extra` blocks hold base + 1 cells
    return i < long_cells ? i / (base + 1) : extra + (i - long_cells) / base;
}

template <int Dim>
Index<Dim> choose_rank_layout(const Index<Dim>& cells, int n_ranks)
{
    if (n_ranks < 1) {
        throw InternalError("choose_rank_layout: no ranks");
    }
    Index<Dim> best{};
    double best_area = std::numeric_limits<double>::infinity();
    Index<Dim> layout{};
    auto consider = [&](const Index<Dim>& candidate) {
        if (!blocks_are_thick_enough<Dim>(cells, candidate)) {
            return;
        }
        // <: of equal areas the first one enumerated wins, which has the fewest ranks along
        // the first axes, so the later axes are split: slabs across the slowest index, as
        // FFTW-MPI's transforms split them.
        const double area = interface_area<Dim>(cells, candidate);
        if (area < best_area) {
            best_area = area;
            best = candidate;
        }
    };
    for_each_factorisation<Dim>(n_ranks, layout, 0, consider);
    if (!(best_area < std::numeric_limits<double>::infinity())) {
        throw InputError("", 0, "domain.cells",
                         std::to_string(n_ranks) + " ranks cannot split the " +
                             cells_text<Dim>(cells) + " grid into blocks of at least " +
                             std::to_string(min_block_cells) +
                             " cells along each split axis; run on fewer ranks");
    }
    return best;
}

template <int Dim>
void check_rank_layout(const Index<Dim>& cells, const Index<Dim>& ranks, int n_ranks)
{
    int product = 1;
    for (int d = 0; d < Dim; ++d) {
        product *= ranks[ax(d)];
    }
    if (product != n_ranks) {
        throw InputError("", 0, "parallel.ranks",
                         "the layout " + cells_text<Dim>(ranks) + " has " +
                             std::to_string(product) + " blocks but the run has " +
                             std::to_string(n_ranks) + " ranks");
    }
    if (!blocks_are_thick_enough<Dim>(cells, ranks)) {
        throw InputError("", 0, "parallel.ranks",
                         "the layout " + cells_text<Dim>(ranks) + " cuts the " +
                             cells_text<Dim>(cells) + " grid into blocks thinner than " +
                             std::to_string(min_block_cells) + " cells");
    }
}

template <int Dim>
GridPartition<Dim> whole_grid(const Index<Dim>& cells, const std::array<bool, Dim>& is_periodic)
{
    GridPartition<Dim> part;
    part.ranks.fill(1);
    part.block = Box<Dim>{Index<Dim>{}, cells};
    for (int d = 0; d < Dim; ++d) {
        const int self = is_periodic[ax(d)] ? 0 : Communicator::no_rank;
        part.neighbours[ax(d)] = {self, self};
    }
    return part;
}

template <int Dim>
GridPartition<Dim> partition_grid(const Communicator& comm, const Index<Dim>& cells,
                                  const std::array<bool, Dim>& is_periodic, const Index<Dim>& ranks)
{
    check_rank_layout<Dim>(cells, ranks, comm.size());
    GridPartition<Dim> part;
    part.ranks = ranks;
    part.communicator = comm.cartesian(std::span<const int>(ranks.data(), ranks.size()),
                                       std::span<const bool>(is_periodic.data(), Dim));
    part.communicator.cartesian_coords(std::span<int>(part.coords.data(), part.coords.size()));
    for (int d = 0; d < Dim; ++d) {
        const auto [lo, hi] = block_range(cells[ax(d)], ranks[ax(d)], part.coords[ax(d)]);
        part.block.lo[ax(d)] = lo;
        part.block.hi[ax(d)] = hi;
        part.neighbours[ax(d)] = part.communicator.cartesian_neighbours(d, is_periodic[ax(d)]);
    }
    std::size_t n_blocks = 1;
    for (int d = 0; d < Dim; ++d) {
        n_blocks *= static_cast<std::size_t>(ranks[ax(d)]);
    }
    part.rank_of_block.resize(n_blocks);
    for (std::size_t b = 0; b < n_blocks; ++b) {
        std::array<int, Dim> coords{};
        std::size_t rest = b;
        for (int d = 0; d < Dim; ++d) {
            const auto parts = static_cast<std::size_t>(ranks[ax(d)]);
            coords[static_cast<std::size_t>(d)] = static_cast<int>(rest % parts);
            rest /= parts;
        }
        part.rank_of_block[b] = part.communicator.cartesian_rank(coords);
    }
    return part;
}

template Index<2> choose_rank_layout<2>(const Index<2>&, int);
template Index<3> choose_rank_layout<3>(const Index<3>&, int);
template void check_rank_layout<2>(const Index<2>&, const Index<2>&, int);
template void check_rank_layout<3>(const Index<3>&, const Index<3>&, int);
template GridPartition<2> whole_grid<2>(const Index<2>&, const std::array<bool, 2>&);
template GridPartition<3> whole_grid<3>(const Index<3>&, const std::array<bool, 3>&);
template GridPartition<2> partition_grid<2>(const Communicator&, const Index<2>&,
                                            const std::array<bool, 2>&, const Index<2>&);
template GridPartition<3> partition_grid<3>(const Communicator&, const Index<3>&,
                                            const std::array<bool, 3>&, const Index<3>&);

} // namespace fddem
