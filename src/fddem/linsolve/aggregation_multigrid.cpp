// SPDX-License-Identifier: MIT
#include "fddem/linsolve/aggregation_multigrid.hpp"

#include <cmath>

namespace fddem {

namespace {

/// Every index of the box [0, n), x fastest (serial: for the small coarse levels).
template <int Dim, class F>
void for_each_dense(const Index<Dim>& n, F&& f)
{
    Box<Dim> box;
    box.hi = n;
    for_each_cell_in_vtk_order<Dim>(box, std::forward<F>(f));
}

/// (A v) at unknown `i` (flat offset `o`) of a coarse level; links out of a bounded side
/// (known values) are dropped, links out of a periodic one wrap around.
template <int Dim>
double product_at(const CoarseLevel<Dim>& level, const std::vector<double>& v, const Index<Dim>& i,
                  std::size_t o) noexcept
{
    double product = level.diagonal[o] * v[o];
    std::size_t stride = 1;
    for (std::size_t d = 0; d < i.size(); ++d) {
        const auto last = static_cast<std::size_t>(level.n[d] - 1);
        const auto at = static_cast<std::size_t>(i[d]);
        const double low = level.a_nb[2 * d][o];
        const double high = level.a_nb[2 * d + 1][o];
        if (at > 0) {
            product -= low * v[o - stride];
        } else if (level.periodic[d]) {
            product -= low * v[o + last * stride];
        }
        if (at < last) {
            product -= high * v[o + stride];
        } else if (level.periodic[d]) {
            product -= high * v[o - last * stride];
        }
        stride *= static_cast<std::size_t>(level.n[d]);
    }
    return product;
}

/// The residual rhs − A x of a coarse level at `i` (flat offset `o`).
template <int Dim>
double residual_at(const CoarseLevel<Dim>& level, const Index<Dim>& i, std::size_t o) noexcept
{
    return level.rhs[o] - product_at<Dim>(level, level.x, i, o);
}

/// A red-black Gauss–Seidel sweep, red first or black first (returns the largest change).
/// Each colour's rows run in parallel; unknowns away from the box's faces take a branch-free
/// path.
template <int Dim>
double gauss_seidel(CoarseLevel<Dim>& level, bool is_red_first)
{
    const auto n0 = static_cast<std::size_t>(level.n[0]);
    const std::array<std::size_t, Dim> stride = level.strides();
    double* x = level.x.data();
    const double* diagonal = level.diagonal.data();
    Box<Dim> all;
    all.hi = level.n;
    Box<Dim> rows = all;
    rows.hi[0] = 1;
    // An odd periodic extent across rows puts same-coloured rows next to each other through
    // the wrap: those levels run their rows serially.
    bool is_race_free = true;
    for (std::size_t d = 1; d < stride.size(); ++d) {
        is_race_free = is_race_free && !(level.periodic[d] && level.n[d] % 2 == 1);
    }
    double change = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
        const int colour = is_red_first ? pass : 1 - pass;
        const auto relax_row = [&](const Index<Dim>& row) {
            Index<Dim> i = row;
            bool is_inner_row = true;
            int parity = 0;
            for (std::size_t d = 1; d < i.size(); ++d) {
                is_inner_row = is_inner_row && i[d] > 0 && i[d] + 1 < level.n[d];
                parity += i[d];
            }
            const std::size_t row_start = level.offset(row);
            double row_change = 0.0;
            for (auto x0 = static_cast<std::size_t>((parity + colour) % 2); x0 < n0; x0 += 2) {
                const std::size_t o = row_start + x0;
                double update = 0.0;
                if (is_inner_row && x0 > 0 && x0 + 1 < n0) {
                    update = interior_update<Dim>(level, stride, o);
                } else {
                    i[0] = static_cast<int>(x0);
                    update = residual_at<Dim>(level, i, o) / diagonal[o];
                }
                x[o] += update;
                row_change = std::max(row_change, std::abs(update));
            }
            return row_change;
        };
        if (is_race_free) {
            change = std::max(change, max_over_rows(Communicator::self(), all, relax_row));
        } else {
            for_each_cell_in_vtk_order<Dim>(
                rows, [&](const Index<Dim>& row) { change = std::max(change, relax_row(row)); });
        }
    }
    return change;
}

/// The first fine unknown of the block of coarse unknown `c`.
template <int Dim>
Index<Dim> coarse_index_origin(Index<Dim> c) noexcept
{
    for (int& x : c) {
        x *= 2;
    }
    return c;
}

enum class Link { inside_block, to_next_block, to_known_value };

/// Where the link of fine unknown `at` (along an axis of fine extent `n`, coarse extent
/// `n_coarse`) across its low (side 0) or high (side 1) face leads under 2-blocking.
constexpr Link classify_link(int at, int side, int n, int n_coarse, bool is_periodic) noexcept
{
    const int there = at + (side == 0 ? -1 : 1);
    if (there < 0 || there >= n) {
        if (!is_periodic) {
            return Link::to_known_value;
        }
        // Wrapped: into the block at the other end, which is this one if there is only one.
        return n_coarse == 1 ? Link::inside_block : Link::to_next_block;
    }
    return there / 2 == at / 2 ? Link::inside_block : Link::to_next_block;
}

/// Sizes `coarse` as the aggregation of a level of extent `fine_n`, all zero.
template <int Dim>
void reset_coarse(const Index<Dim>& fine_n, const std::array<bool, Dim>& periodic,
                  CoarseLevel<Dim>& coarse)
{
    coarse.assign_zero(coarse_extent<Dim>(fine_n), periodic);
}

/// Adds fine unknown `at` (flat offset `fo`; `at` and `n` are whole-level indices and extent)
/// to its block's coarse unknown (flat offset `co` in `coarse`'s arrays): its diagonal, its
/// links inside the block taken off the diagonal, its links to the next blocks as theirs.
template <int Dim>
void add_member(const StencilView<Dim>& fine, std::ptrdiff_t fo, const Index<Dim>& at,
                const Index<Dim>& n, std::size_t co, CoarseLevel<Dim>& coarse)
{
    const Index<Dim> coarse_n = coarse_extent<Dim>(n);
    coarse.diagonal[co] += fine.diagonal[fo] * fine.diagonal_scale;
    for (std::size_t d = 0; d < at.size(); ++d) {
        for (int side = 0; side < 2; ++side) {
            const double a = fine.a_nb[2 * d + static_cast<std::size_t>(side)][fo];
            switch (classify_link(at[d], side, n[d], coarse_n[d], fine.periodic[d])) {
            case Link::inside_block:
                coarse.diagonal[co] -= a;
                break;
            case Link::to_next_block:
                coarse.a_nb[2 * d + static_cast<std::size_t>(side)][co] += a;
                break;
            case Link::to_known_value:
                break; // no error there
            }
        }
    }
}

/// coarse = R A P of `fine` (blocks of 2^Dim, piecewise-constant P, summing R).
template <int Dim>
void aggregate(const StencilView<Dim>& fine, CoarseLevel<Dim>& coarse)
{
    reset_coarse<Dim>(fine.n, fine.periodic, coarse);

    Box<Dim> blocks;
    blocks.hi = coarse.n;
    // One coarse unknown per call: each writes only its own coefficients.
    for_each_index(
        blocks,
        [&](const Index<Dim>& c) {
            const std::size_t co = coarse.offset(c);
            bool is_interior = true;
            for (std::size_t d = 0; d < c.size(); ++d) {
                is_interior = is_interior && c[d] > 0 && 2 * c[d] + 2 < fine.n[d];
            }
            if (is_interior) {
                // Every member and every neighbour exists: a link along d is inside the block
                // exactly when it points from the member's side of the block inwards.
                const std::ptrdiff_t base = fine.at(coarse_index_origin<Dim>(c));
                double diagonal = 0.0;
                std::array<double, 2 * Dim> links{};
                for (int member = 0; member < (1 << Dim); ++member) {
                    std::ptrdiff_t fo = base;
                    for (std::size_t d = 0; d < c.size(); ++d) {
                        fo += ((member >> d) & 1) * fine.stride[d];
                    }
                    diagonal += fine.diagonal[fo] * fine.diagonal_scale;
                    for (std::size_t d = 0; d < c.size(); ++d) {
                        const bool is_high_member = ((member >> d) & 1) != 0;
                        const double low = fine.a_nb[2 * d][fo];
                        const double high = fine.a_nb[2 * d + 1][fo];
                        diagonal -= is_high_member ? low : high;
                        links[2 * d + (is_high_member ? 1 : 0)] += is_high_member ? high : low;
                    }
                }
                coarse.diagonal[co] = diagonal;
                for (std::size_t k = 0; k < links.size(); ++k) {
                    coarse.a_nb[k][co] = links[k];
                }
                return;
            }
            for_each_in_block<Dim>(c, fine.n, [&](const Index<Dim>& i) {
                add_member<Dim>(fine, fine.at(i), i, fine.n, co, coarse);
            });
        },
        std::size_t{1} << Dim);
}

} // namespace

template <int Dim>
StencilView<Dim> CoarseLevel<Dim>::view() const noexcept
{
    StencilView<Dim> v;
    v.n = n;
    v.periodic = periodic;
    std::ptrdiff_t stride = 1;
    for (std::size_t d = 0; d < n.size(); ++d) {
        v.stride[d] = stride;
        stride *= n[d];
    }
    v.diagonal = diagonal.data();
    for (std::size_t k = 0; k < a_nb.size(); ++k) {
        v.a_nb[k] = a_nb[k].data();
    }
    return v;
}

template <int Dim>
std::array<std::size_t, Dim> CoarseLevel<Dim>::strides() const noexcept
{
    std::array<std::size_t, Dim> stride{};
    std::size_t s = 1;
    for (std::size_t d = 0; d < stride.size(); ++d) {
        stride[d] = s;
        s *= static_cast<std::size_t>(n[d]);
    }
    return stride;
}

template <int Dim>
void CoarseLevel<Dim>::assign_zero(const Index<Dim>& extent,
                                   const std::array<bool, Dim>& is_periodic)
{
    n = extent;
    periodic = is_periodic;
    std::size_t size = 1;
    for (const int e : n) {
        size *= static_cast<std::size_t>(e);
    }
    diagonal.assign(size, 0.0);
    for (auto& a : a_nb) {
        a.assign(size, 0.0);
    }
    rhs.assign(size, 0.0);
    x.assign(size, 0.0);
}

template <int Dim>
void build_coarse_levels(const StencilView<Dim>& fine, std::vector<CoarseLevel<Dim>>& levels,
                         std::size_t coarsest_size)
{
    if (coarse_extent<Dim>(fine.n) == fine.n) {
        levels.clear(); // every extent is 1: nothing to merge
        return;
    }
    if (levels.empty()) {
        levels.emplace_back();
    }
    aggregate(fine, levels.front());
    extend_coarse_levels(levels, coarsest_size);
}

template <int Dim>
void extend_coarse_levels(std::vector<CoarseLevel<Dim>>& levels, std::size_t coarsest_size)
{
    std::size_t count = 1;
    while (levels[count - 1].size() > coarsest_size) {
        // (The view points into the level's arrays, which a reallocation of `levels` moves
        // without copying.)
        const StencilView<Dim> above = levels[count - 1].view();
        if (coarse_extent<Dim>(above.n) == above.n) {
            break; // every extent is 1: nothing left to merge
        }
        if (levels.size() <= count) {
            levels.emplace_back();
        }
        aggregate(above, levels[count]);
        ++count;
    }
    levels.resize(count);
}

template <int Dim>
void aggregate_part(const StencilView<Dim>& fine, const LevelPart<Dim>& part,
                    const Index<Dim>& origin, CoarseLevel<Dim>& coarse)
{
    // The blocks that meet the part, one coarse unknown per call: each writes only its own
    // coefficients, from the members this part holds.
    const Box<Dim> blocks = coarse_part_box<Dim>(part, fine.n);
    for_each_index(
        blocks,
        [&](const Index<Dim>& c) {
            const std::size_t co = coarse.offset(c - origin);
            for_each_in_block<Dim>(c, part.whole_n, [&](const Index<Dim>& at) {
                Index<Dim> i{};
                for (std::size_t d = 0; d < i.size(); ++d) {
                    i[d] = at[d] - part.offset[d];
                    if (i[d] < 0 || i[d] >= fine.n[d]) {
                        return; // another process's member
                    }
                }
                add_member<Dim>(fine, fine.at(i), at, part.whole_n, co, coarse);
            });
        },
        std::size_t{1} << Dim);
}

template <int Dim>
void coarse_v_cycle(std::vector<CoarseLevel<Dim>>& levels, std::size_t k, int sweeps)
{
    CoarseLevel<Dim>& level = levels[k];
    if (k + 1 == levels.size()) {
        // The coarsest level is small and strongly diagonal (the time term adds up under
        // merging, the links do not): sweep it to convergence.
        const double scale = [&] {
            double largest = 0.0;
            for (std::size_t o = 0; o < level.size(); ++o) {
                largest = std::max(largest, std::abs(level.rhs[o] / level.diagonal[o]));
            }
            return largest;
        }();
        for (int sweep = 0; sweep < 50; ++sweep) {
            if (gauss_seidel(level, sweep % 2 == 0) <= 1e-6 * scale) {
                break;
            }
        }
        return;
    }
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        gauss_seidel(level, true);
    }
    CoarseLevel<Dim>& coarse = levels[k + 1];
    restrict_sum<Dim>(
        level.n, [&](const Index<Dim>& i) { return residual_at<Dim>(level, i, level.offset(i)); },
        coarse);
    coarse_v_cycle(levels, k + 1, sweeps);
    for_each_dense<Dim>(level.n, [&](const Index<Dim>& i) {
        level.x[level.offset(i)] += coarse.x[coarse.offset(coarse_index<Dim>(i))];
    });
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        gauss_seidel(level, false);
    }
}

template struct CoarseLevel<2>;
template struct CoarseLevel<3>;
template void build_coarse_levels<2>(const StencilView<2>&, std::vector<CoarseLevel<2>>&,
                                     std::size_t);
template void build_coarse_levels<3>(const StencilView<3>&, std::vector<CoarseLevel<3>>&,
                                     std::size_t);
template void extend_coarse_levels<2>(std::vector<CoarseLevel<2>>&, std::size_t);
template void extend_coarse_levels<3>(std::vector<CoarseLevel<3>>&, std::size_t);
template void aggregate_part<2>(const StencilView<2>&, const LevelPart<2>&, const Index<2>&,
                                CoarseLevel<2>&);
template void aggregate_part<3>(const StencilView<3>&, const LevelPart<3>&, const Index<3>&,
                                CoarseLevel<3>&);
template void coarse_v_cycle<2>(std::vector<CoarseLevel<2>>&, std::size_t, int);
template void coarse_v_cycle<3>(std::vector<CoarseLevel<3>>&, std::size_t, int);

} // namespace fddem
