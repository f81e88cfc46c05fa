// SPDX-License-Identifier: MIT
#pragma once
/// The Lagrangian markers that fill a body (paper §3.1, Fig. 1), in the body frame: where they
/// sit and the volume each represents. coupling/markers.hpp lays them out.

#include "fddem/core/vec.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fddem {

template <int Dim>
struct MarkerSet {
    std::vector<Vec<Dim>> offsets; ///< from the body centre, body frame [m]
    std::vector<double> volumes;   ///< ΔV_l [m³] (2D: m²), Σ = body volume
    double spacing = 0.0;          ///< h_L [m]

    [[nodiscard]] std::size_t size() const noexcept { return offsets.size(); }
    /// Σ ΔV_l |r_l⊥|² about an axis through the centre: the fluid inertia the markers
    /// represent, divided by ρf [m⁵] (2D: m⁴).
    [[nodiscard]] double second_moment() const
    {
        double sum = 0.0;
        for (std::size_t l = 0; l < offsets.size(); ++l) {
            sum += volumes[l] * offsets[l].squaredNorm();
        }
        if constexpr (Dim == 3) {
            sum *= 2.0 / 3.0; // about one axis: ∫ |r⊥|² = ⅔ ∫ |r|² for an isotropic set
        }
        return sum;
    }
    /// The radius of the outermost marker shell, max |r_l| (0 for an empty set) [m].
    [[nodiscard]] double outermost_radius() const
    {
        double largest = 0.0;
        for (const Vec<Dim>& r : offsets) {
            largest = std::max(largest, r.squaredNorm());
        }
        return std::sqrt(largest);
    }
};

} // namespace fddem
