// SPDX-License-Identifier: MIT
#pragma once
/// The physical box of a run and which of its axes are periodic: where points are wrapped into
/// the box and how far apart two points are across a periodic boundary. Grid, bodies, markers
/// and the contact search all use this one definition, so that a body, its markers and its
/// contacts agree on where it is.
///
/// On a periodic axis of length L a point x and x + k L (k an integer) are the same point.
/// wrap() picks the image in [origin, origin + L); minimum_image() turns a displacement into the
/// shortest one between images (the minimum-image convention, Allen & Tildesley 1987, §1.5.2).
/// Both leave a value that needs no change bit for bit unchanged, so a run whose bodies never
/// come near a periodic boundary computes exactly what it computed without them.

#include "fddem/core/vec.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace fddem {

template <int Dim>
struct PeriodicDomain {
    Vec<Dim> origin = Vec<Dim>::Zero(); ///< low corner [m]
    Vec<Dim> length = Vec<Dim>::Zero(); ///< side lengths [m], each > 0
    std::array<bool, Dim> is_periodic{};

    [[nodiscard]] bool periodic(int axis) const noexcept
    {
        return is_periodic[static_cast<std::size_t>(axis)];
    }
    [[nodiscard]] bool has_periodic_axis() const noexcept
    {
        for (const bool p : is_periodic) {
            if (p) {
                return true;
            }
        }
        return false;
    }

    /// `x` with each periodic coordinate moved by whole periods into [origin, origin + L);
    /// other coordinates unchanged, and a coordinate already inside unchanged bit for bit.
    [[nodiscard]] Vec<Dim> wrap(Vec<Dim> x) const noexcept
    {
        for (int d = 0; d < Dim; ++d) {
            if (periodic(d)) {
                x[d] = wrap_coordinate(x[d], origin[d], length[d]);
            }
        }
        return x;
    }

    /// The displacement between the nearest images: each periodic component of `d` moved by
    /// whole periods into [−L/2, L/2]; a component already there unchanged bit for bit.
    [[nodiscard]] Vec<Dim> minimum_image(Vec<Dim> d) const noexcept
    {
        for (int k = 0; k < Dim; ++k) {
            if (periodic(k)) {
                d[k] = nearest_displacement(d[k], length[k]);
            }
        }
        return d;
    }

private:
    [[nodiscard]] static double wrap_coordinate(double x, double lo, double period) noexcept
    {
        const double hi = lo + period;
        if (x >= lo && x < hi) {
            return x;
        }
        // Whole periods at once for a far point, then at most one more step each way: the
        // division may round either way, and lo + period may round below hi itself.
        x -= period * std::floor((x - lo) / period);
        while (x >= hi) {
            x -= period;
        }
        while (x < lo) {
            x += period;
        }
        // Only a point within rounding of the seam can still be outside: it is at lo.
        return x < hi ? x : lo;
    }

    [[nodiscard]] static double nearest_displacement(double d, double period) noexcept
    {
        const double half = 0.5 * period;
        if (d >= -half && d <= half) {
            return d;
        }
        return d - period * std::round(d / period);
    }
};

} // namespace fddem
