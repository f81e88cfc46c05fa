// SPDX-License-Identifier: MIT
#pragma once
/// Seeded random insertion of equal balls (disks in 2D, spheres in 3D) in a box region, none
/// overlapping another or a ball already there (issue 14): random sequential addition (RSA).
/// Trial centres are drawn uniformly; one that leaves less than `gap` to a placed ball or to the
/// region's faces is rejected, and the next is drawn, up to a bounded number of trials.
///
/// RSA cannot fill space densely: it jams at a volume fraction of 0.547 for disks (Hinrichsen,
/// Feder & Jøssang 1986) and 0.384 for spheres (Torquato, Uche & Stillinger 2006), and in a
/// finite region with faces below that. The same seed gives the same balls on every machine:
/// std::mt19937_64's output is fixed by the C++ standard, and the uniform numbers are made from
/// it here (uniform_unit) rather than by std::uniform_real_distribution, whose algorithm each
/// standard library chooses for itself.

#include "fddem/core/vec.hpp"

#include <cstdint>
#include <vector>

namespace fddem {

/// A ball already in place, which inserted balls keep clear of.
template <int Dim>
struct PlacedBall {
    Vec<Dim> centre; ///< [m]
    double radius;   ///< [m]
};

template <int Dim>
struct PackingRequest {
    Vec<Dim> low;             ///< region's lower corner [m]
    Vec<Dim> high;            ///< region's upper corner [m]
    double diameter = 0.0;    ///< of every inserted ball [m]
    long count = 0;           ///< balls to insert
    double gap = 0.0;         ///< least clearance between balls, and from the faces [m]
    std::uint64_t seed = 1;   ///< of std::mt19937_64
    long trials_per_ball = 0; ///< the bound: count · trials_per_ball trial centres at most
    std::vector<PlacedBall<Dim>> obstacles;
};

template <int Dim>
struct Packing {
    std::vector<Vec<Dim>> centres; ///< in the order placed; fewer than asked if jammed [m]
    long trials = 0;               ///< trial centres drawn
};

/// Up to `request.count` centres. Precondition: the region holds one ball with its gap on
/// every axis (high − low ≥ diameter + 2 gap).
template <int Dim>
[[nodiscard]] Packing<Dim> random_packing(const PackingRequest<Dim>& request);

/// The fraction of space at which random sequential addition of equal balls jams: 0.547 for
/// disks, 0.384 for spheres (see above).
template <int Dim>
[[nodiscard]] constexpr double jamming_fraction()
{
    return Dim == 2 ? 0.547 : 0.384;
}

/// A uniform double in [0, 1) from 64 random bits: their top 53 bits, as the significand.
[[nodiscard]] constexpr double uniform_unit(std::uint64_t bits)
{
    constexpr double two_to_minus_53 = 1.0 / 9007199254740992.0;
    return static_cast<double>(bits >> 11U) * two_to_minus_53;
}

} // namespace fddem
