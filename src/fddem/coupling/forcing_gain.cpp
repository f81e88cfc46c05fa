// SPDX-License-Identifier: MIT
#include "fddem/coupling/forcing_gain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <variant>

namespace fddem {
namespace {

/// The faces of one component near a point: the first face index per axis and the 1-D weights
/// of the 2 · half_width faces from there (zero beyond the support).
template <int Dim, DeltaKernel Kernel>
struct Stencil {
    static constexpr int width = 2 * Kernel::half_width;
    std::array<long, Dim> first{};
    std::array<std::array<double, width>, Dim> weight{};

    Stencil(const Vec<Dim>& x, int component, const Vec<Dim>& origin, const Vec<Dim>& spacing)
    {
        for (int d = 0; d < Dim; ++d) {
            // the component's faces lie on the grid lines along its axis, at cell centres across
            const double shift = d == component ? 0.0 : 0.5;
            const double t = (x[d] - origin[d]) / spacing[d] - shift;
            const auto base = static_cast<long>(std::floor(t));
            first[static_cast<std::size_t>(d)] = base - Kernel::half_width + 1;
            for (int k = 0; k < width; ++k) {
                weight[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)] =
                    Kernel::weight(t - static_cast<double>(first[static_cast<std::size_t>(d)] + k));
            }
        }
    }
};

/// A dense block of faces covering every marker's stencil (the body's support only).
template <int Dim>
struct Patch {
    std::array<long, Dim> low{};
    std::array<long, Dim> extent{};
    std::vector<double> values;

    [[nodiscard]] std::size_t offset(const std::array<long, Dim>& index) const
    {
        std::size_t o = 0;
        for (int d = 0; d < Dim; ++d) {
            const auto i = static_cast<std::size_t>(d);
            o = o * static_cast<std::size_t>(extent[i]) +
                static_cast<std::size_t>(index[i] - low[i]);
        }
        return o;
    }
};

/// Calls visit(index, weight) for every face of a stencil: weight is the product of the 1-D ones.
template <int Dim, DeltaKernel Kernel, class Visit>
void for_each_face(const Stencil<Dim, Kernel>& s, Visit visit)
{
    constexpr int width = Stencil<Dim, Kernel>::width;
    int count = 1;
    for (int d = 0; d < Dim; ++d) {
        count *= width;
    }
    for (int n = 0; n < count; ++n) {
        std::array<long, Dim> index{};
        double w = 1.0;
        int rest = n;
        for (int d = 0; d < Dim; ++d) {
            const auto i = static_cast<std::size_t>(d);
            const int k = rest % width;
            rest /= width;
            index[i] = s.first[i] + k;
            w *= s.weight[i][static_cast<std::size_t>(k)];
        }
        if (w != 0.0) {
            visit(index, w);
        }
    }
}

} // namespace

template <int Dim, DeltaKernel Kernel>
std::vector<Vec<Dim>> forcing_row_sums(std::span<const Vec<Dim>> positions,
                                       std::span<const double> volumes, const Vec<Dim>& origin,
                                       const Vec<Dim>& spacing)
{
    double cell_volume = 1.0;
    for (int d = 0; d < Dim; ++d) {
        cell_volume *= spacing[d];
    }
    std::vector<Vec<Dim>> sums(positions.size(), Vec<Dim>::Zero());
    for (int a = 0; a < Dim; ++a) {
        std::vector<Stencil<Dim, Kernel>> stencils;
        stencils.reserve(positions.size());
        Patch<Dim> patch;
        std::array<long, Dim> high{};
        patch.low.fill(std::numeric_limits<long>::max());
        high.fill(std::numeric_limits<long>::min());
        for (const Vec<Dim>& x : positions) {
            stencils.emplace_back(x, a, origin, spacing);
            for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
                patch.low[d] = std::min(patch.low[d], stencils.back().first[d]);
                high[d] = std::max(high[d], stencils.back().first[d] + Kernel::half_width * 2);
            }
        }
        if (positions.empty()) {
            break;
        }
        std::size_t size = 1;
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
            patch.extent[d] = high[d] - patch.low[d];
            size *= static_cast<std::size_t>(patch.extent[d]);
        }
        patch.values.assign(size, 0.0);
        // D of a unit value at every marker (ΔV_l / ΔV_cell weighted, as transfer.hpp spreads) …
        for (std::size_t l = 0; l < positions.size(); ++l) {
            const double share = volumes[l] / cell_volume;
            for_each_face<Dim, Kernel>(stencils[l], [&](const std::array<long, Dim>& f, double w) {
                patch.values[patch.offset(f)] += share * w;
            });
        }
        // … and I of that at every marker: Σ_l M_ml.
        for (std::size_t m = 0; m < positions.size(); ++m) {
            double sum = 0.0;
            for_each_face<Dim, Kernel>(stencils[m], [&](const std::array<long, Dim>& f, double w) {
                sum += w * patch.values[patch.offset(f)];
            });
            sums[m][a] = sum;
        }
    }
    return sums;
}

template <int Dim>
std::vector<Vec<Dim>> forcing_row_sums(const AnyKernel& kernel, std::span<const Vec<Dim>> positions,
                                       std::span<const double> volumes, const Vec<Dim>& origin,
                                       const Vec<Dim>& spacing)
{
    return std::visit(
        [&](auto k) {
            return forcing_row_sums<Dim, decltype(k)>(positions, volumes, origin, spacing);
        },
        kernel);
}

template std::vector<Vec<2>> forcing_row_sums<2>(const AnyKernel&, std::span<const Vec<2>>,
                                                 std::span<const double>, const Vec<2>&,
                                                 const Vec<2>&);
template std::vector<Vec<3>> forcing_row_sums<3>(const AnyKernel&, std::span<const Vec<3>>,
                                                 std::span<const double>, const Vec<3>&,
                                                 const Vec<3>&);

} // namespace fddem
