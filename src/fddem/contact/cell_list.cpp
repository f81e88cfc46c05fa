// SPDX-License-Identifier: MIT
#include "fddem/contact/cell_list.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace fddem {

template <int Dim>
CellList<Dim>::CellList(const Vec<Dim>& origin, const Vec<Dim>& length, double range)
    : CellList(PeriodicDomain<Dim>{origin, length, {}}, range)
{
}

template <int Dim>
CellList<Dim>::CellList(const PeriodicDomain<Dim>& domain, double range)
    : domain_(domain), range_(range)
{
    if (!(range > 0.0)) {
        throw InternalError("CellList: the interaction range must be positive");
    }
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        n_[k] = std::max(1, static_cast<int>(std::floor(domain.length[d] / range)));
        cell_size_[d] = domain.length[d] / n_[k];
        total *= static_cast<std::size_t>(n_[k]);
    }
    head_.assign(total, -1);
}

template <int Dim>
int CellList<Dim>::cell_of(const Vec<Dim>& x) const noexcept
{
    const Vec<Dim> inside = domain_.wrap(x);
    int flat = 0;
    int stride = 1;
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        const int i = std::clamp(
            static_cast<int>(std::floor((inside[d] - domain_.origin[d]) / cell_size_[d])), 0,
            n_[k] - 1);
        flat += i * stride;
        stride *= n_[k];
    }
    return flat;
}

template <int Dim>
void CellList<Dim>::find_pairs(std::span<const Vec<Dim>> centres,
                               std::vector<std::pair<int, int>>& pairs)
{
    pairs.clear();
    std::fill(head_.begin(), head_.end(), -1);
    next_.assign(centres.size(), -1);
    for (std::size_t b = 0; b < centres.size(); ++b) {
        const int cell = cell_of(centres[b]);
        next_[b] = head_[static_cast<std::size_t>(cell)];
        head_[static_cast<std::size_t>(cell)] = static_cast<int>(b);
    }
    const double range_squared = range_ * range_;
    std::array<int, Dim> strides{};
    int stride = 1;
    for (int d = 0; d < Dim; ++d) {
        strides[static_cast<std::size_t>(d)] = stride;
        stride *= n_[static_cast<std::size_t>(d)];
    }
    for (std::size_t b = 0; b < centres.size(); ++b) {
        // The neighbour cells of b's cell along each axis: one below, itself, one above;
        // wrapped on a periodic axis (each cell once, however few there are), dropped past the
        // box's side on the others.
        std::array<std::array<int, 3>, Dim> along{};
        std::array<int, Dim> n_along{};
        int n_neighbours = 1;
        int rest = cell_of(centres[b]);
        for (int d = 0; d < Dim; ++d) {
            const auto k = static_cast<std::size_t>(d);
            const int home = rest % n_[k];
            rest /= n_[k];
            for (int offset = -1; offset <= 1; ++offset) {
                int i = home + offset;
                if (domain_.periodic(d)) {
                    i = (i + n_[k]) % n_[k];
                } else if (i < 0 || i >= n_[k]) {
                    continue;
                }
                const auto first = along[k].begin();
                if (std::find(first, first + n_along[k], i) == first + n_along[k]) {
                    along[k][static_cast<std::size_t>(n_along[k]++)] = i;
                }
            }
            n_neighbours *= n_along[k];
        }
        // Visit each neighbour cell once; keep each pair once (i < j).
        for (int m = 0; m < n_neighbours; ++m) {
            int code = m;
            int cell = 0;
            for (int d = 0; d < Dim; ++d) {
                const auto k = static_cast<std::size_t>(d);
                cell += along[k][static_cast<std::size_t>(code % n_along[k])] * strides[k];
                code /= n_along[k];
            }
            for (int other = head_[static_cast<std::size_t>(cell)]; other >= 0;
                 other = next_[static_cast<std::size_t>(other)]) {
                if (other <= static_cast<int>(b)) {
                    continue;
                }
                if (domain_.minimum_image(centres[b] - centres[static_cast<std::size_t>(other)])
                        .squaredNorm() < range_squared) {
                    pairs.emplace_back(static_cast<int>(b), other);
                }
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

template <int Dim>
std::vector<std::pair<int, int>> brute_force_pairs(std::span<const Vec<Dim>> centres, double range,
                                                   const PeriodicDomain<Dim>& domain)
{
    std::vector<std::pair<int, int>> pairs;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        for (std::size_t j = i + 1; j < centres.size(); ++j) {
            if (domain.minimum_image(centres[i] - centres[j]).squaredNorm() < range * range) {
                pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
            }
        }
    }
    return pairs;
}

template class CellList<2>;
template class CellList<3>;
template std::vector<std::pair<int, int>> brute_force_pairs<2>(std::span<const Vec<2>>, double,
                                                               const PeriodicDomain<2>&);
template std::vector<std::pair<int, int>> brute_force_pairs<3>(std::span<const Vec<3>>, double,
                                                               const PeriodicDomain<3>&);

} // namespace fddem
