// SPDX-License-Identifier: MIT
#pragma once
// Template definitions of aggregation_multigrid.hpp (included at its end).

#include "fddem/grid/loops.hpp"

#include <algorithm>

namespace fddem {

/// Calls f(i) for the fine unknowns i of the block of coarse unknown `c` (those inside `fine_n`).
template <int Dim, class F>
void for_each_in_block(const Index<Dim>& c, const Index<Dim>& fine_n, F&& f)
{
    for (int member = 0; member < (1 << Dim); ++member) {
        Index<Dim> i{};
        bool is_inside = true;
        for (int d = 0; d < Dim; ++d) {
            const auto sd = static_cast<std::size_t>(d);
            i[sd] = 2 * c[sd] + ((member >> d) & 1);
            is_inside = is_inside && i[sd] < fine_n[sd];
        }
        if (is_inside) {
            f(i);
        }
    }
}

/// The Gauss–Seidel change (rhs − A x)/a_P of unknown `o` of `level`, whose 2·Dim neighbours
/// all sit at o ± stride[d] (none across a wrap or beyond a side: those take residual_at's
/// path in the one-process sweep, or are ghosts on a split level).
template <int Dim>
[[nodiscard]] double interior_update(const CoarseLevel<Dim>& level,
                                     const std::array<std::size_t, Dim>& stride,
                                     std::size_t o) noexcept
{
    double r = level.rhs[o] - level.diagonal[o] * level.x[o];
    for (std::size_t d = 0; d < stride.size(); ++d) {
        r += level.a_nb[2 * d][o] * level.x[o - stride[d]] +
             level.a_nb[2 * d + 1][o] * level.x[o + stride[d]];
    }
    return r / level.diagonal[o];
}

template <int Dim, class Residual>
void restrict_sum(const Index<Dim>& fine_n, Residual&& residual, CoarseLevel<Dim>& coarse)
{
    Box<Dim> blocks;
    blocks.hi = coarse.n;
    for_each_index(
        blocks,
        [&](const Index<Dim>& c) {
            double sum = 0.0;
            for_each_in_block<Dim>(c, fine_n, [&](const Index<Dim>& i) { sum += residual(i); });
            const std::size_t flat = coarse.offset(c);
            coarse.rhs[flat] = sum;
            coarse.x[flat] = 0.0;
        },
        std::size_t{1} << Dim);
}

} // namespace fddem
