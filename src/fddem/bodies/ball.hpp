// SPDX-License-Identifier: MIT
#pragma once
/// The round body of each dimension: a disk in 2D (quantities per unit depth), a sphere in 3D.
/// Shapes provide volume(), radius(), contains(offset) and the geometric second moment
/// ∫ |r⊥|² dV about an axis through the centre; further shapes plug in beside it.

#include "fddem/core/vec.hpp"

#include <numbers>

namespace fddem {

template <int Dim>
struct Ball {
    double diameter; ///< [m]

    [[nodiscard]] double radius() const noexcept { return 0.5 * diameter; }
    /// π r² [m²] (per unit depth) in 2D, 4/3 π r³ [m³] in 3D.
    [[nodiscard]] double volume() const noexcept
    {
        const double r = radius();
        if constexpr (Dim == 2) {
            return std::numbers::pi * r * r;
        } else {
            return 4.0 / 3.0 * std::numbers::pi * r * r * r;
        }
    }
    /// ∫ |r⊥|² dV about an axis through the centre: V r²/2 (disk, polar), 2/5 V r² (sphere).
    [[nodiscard]] double second_moment() const noexcept
    {
        const double r = radius();
        return (Dim == 2 ? 0.5 : 0.4) * volume() * r * r;
    }
    [[nodiscard]] bool contains(const Vec<Dim>& offset) const noexcept
    {
        return offset.squaredNorm() <= radius() * radius() * (1.0 + 1e-12);
    }
};

} // namespace fddem
