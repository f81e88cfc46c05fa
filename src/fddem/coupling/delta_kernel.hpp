// SPDX-License-Identifier: MIT
#pragma once
/// Discrete delta functions for the transfer between the grid and the markers (paper §2.2).
/// The multi-dimensional weight is the product of 1-D weights φ(r/h) per axis.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <variant>

namespace fddem {

template <class K>
concept DeltaKernel = requires(double s)
{
    {
        K::half_width
        } -> std::convertible_to<int>; // the stencil: |s| < half_width
    {
        K::support_radius
        } -> std::convertible_to<double>; // where the weight is nonzero: |s| < support_radius
    {
        K::weight(s)
        } -> std::same_as<double>; // 1-D weight, s = r / h
};

/// Linear hat d_h(r) = 1 − |r|/h for |r| < h, else 0 (paper §2.2).
struct HatKernel {
    static constexpr int half_width = 1;
    static constexpr double support_radius = 1.0;
    [[nodiscard]] static double weight(double s) noexcept
    {
        const double a = std::abs(s);
        return a < 1.0 ? 1.0 - a : 0.0;
    }
};

/// Roma, Peskin & Berger (1999), J. Comput. Phys. 153, eq. (12): three-point kernel.
struct RomaPeskin3Kernel {
    static constexpr int half_width = 2;
    static constexpr double support_radius = 1.5;
    [[nodiscard]] static double weight(double s) noexcept
    {
        const double a = std::abs(s);
        if (a <= 0.5) {
            return (1.0 + std::sqrt(1.0 - 3.0 * a * a)) / 3.0;
        }
        if (a <= 1.5) {
            const double b = 1.0 - a;
            return (5.0 - 3.0 * a - std::sqrt(1.0 - 3.0 * b * b)) / 6.0;
        }
        return 0.0;
    }
};

/// Peskin (2002), Acta Numerica 11, eq. (6.27): the standard four-point kernel.
struct Peskin4Kernel {
    static constexpr int half_width = 2;
    static constexpr double support_radius = 2.0;
    [[nodiscard]] static double weight(double s) noexcept
    {
        const double a = std::abs(s);
        if (a <= 1.0) {
            return (3.0 - 2.0 * a + std::sqrt(1.0 + 4.0 * a - 4.0 * a * a)) / 8.0;
        }
        if (a <= 2.0) {
            return (5.0 - 2.0 * a - std::sqrt(-7.0 + 12.0 * a - 4.0 * a * a)) / 8.0;
        }
        return 0.0;
    }
};

/// Yang, Zhang, Li & He (2009), J. Comput. Phys. 228, 7821–7836: the smoothed three-point
/// kernel, Roma, Peskin & Berger's kernel averaged over one cell, φ̃(s) = ∫_{s−1/2}^{s+1/2} φ,
/// so that its first derivative is continuous. Designed to damp the spurious oscillations of the
/// force on a body moving across the grid (its weights change smoothly as a marker crosses a face).
/// Support |s| < 2. (Written here from the published formula: no library provides it.)
struct SmoothedRoma3Kernel {
    static constexpr int half_width = 2;
    static constexpr double support_radius = 2.0;
    [[nodiscard]] static double weight(double s) noexcept
    {
        const double a = std::abs(s);
        const double sqrt3 = std::sqrt(3.0);
        const double pi = 3.14159265358979323846;
        if (a <= 1.0) {
            return 17.0 / 48.0 + sqrt3 * pi / 108.0 + a / 4.0 - a * a / 4.0 +
                   (1.0 - 2.0 * a) / 16.0 *
                       std::sqrt(std::max(0.0, -12.0 * a * a + 12.0 * a + 1.0)) -
                   sqrt3 / 12.0 * std::asin(sqrt3 / 2.0 * (2.0 * a - 1.0));
        }
        if (a <= 2.0) {
            return 55.0 / 48.0 - sqrt3 * pi / 108.0 - 13.0 * a / 12.0 + a * a / 4.0 +
                   (2.0 * a - 3.0) / 48.0 *
                       std::sqrt(std::max(0.0, -12.0 * a * a + 36.0 * a - 23.0)) +
                   sqrt3 / 36.0 * std::asin(sqrt3 / 2.0 * (2.0 * a - 3.0));
        }
        return 0.0;
    }
};

static_assert(DeltaKernel<HatKernel> && DeltaKernel<RomaPeskin3Kernel> &&
              DeltaKernel<Peskin4Kernel> && DeltaKernel<SmoothedRoma3Kernel>);

/// Chosen at run time (case key coupling.kernel), dispatched once per body loop.
using AnyKernel = std::variant<HatKernel, RomaPeskin3Kernel, Peskin4Kernel, SmoothedRoma3Kernel>;

/// The kernels a case can choose (coupling.kernel).
enum class KernelKind { hat, roma3, peskin4, roma3_smoothed };

[[nodiscard]] AnyKernel make_kernel(KernelKind kind);

/// The support radius of the kernel `kind` [cells].
[[nodiscard]] double support_radius(KernelKind kind) noexcept;

/// How close to a wall [cells] a marker is switched off by coupling.markers_off_at_walls when
/// coupling.markers_off_reach is not given: the kernel's support radius and half a cell, so that
/// no marker reads the row of cells beside the wall (whose tangential velocity sits h/2 from it),
/// the row that drains the fluid squeezed out between a body and the wall (docs/method.md §5,
/// "The wall's row of cells left free").
[[nodiscard]] inline double default_wall_marker_reach(double kernel_support_radius) noexcept
{
    return kernel_support_radius + 0.5;
}

} // namespace fddem
