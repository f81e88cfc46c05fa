// SPDX-License-Identifier: MIT
// Wrapping into a periodic box and nearest images (core/periodic_domain.hpp): points and
// displacements that need no change keep every bit (so runs whose bodies stay away from
// periodic sides are unchanged), images one or many periods away land on the same point, and
// nothing lands outside [origin, origin + L), even within rounding of the seam.

#include "fddem/core/periodic_domain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fddem {
namespace {

const PeriodicDomain<2> channel{Vec<2>(-1.0, 0.5), Vec<2>(2.0, 3.0), {true, false}};

TEST(PeriodicDomain, WrapLeavesAPointInsideUnchangedBitForBit)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 1000; ++k) {
        const Vec<2> x(-1.0 + 2.0 * unit(rng), 0.5 + 3.0 * unit(rng));
        const Vec<2> wrapped = channel.wrap(x);
        EXPECT_EQ(wrapped.x(), x.x());
        EXPECT_EQ(wrapped.y(), x.y());
    }
}

TEST(PeriodicDomain, WrapMovesImagesOntoTheirPointAlongPeriodicAxesOnly)
{
    // Dyadic coordinates: the images are exact, so is the wrap.
    const Vec<2> x(-0.25, 0.75);
    for (const int k : {-7, -2, -1, 1, 2, 1000}) {
        const Vec<2> image(x.x() + 2.0 * k, 100.0);
        const Vec<2> wrapped = channel.wrap(image);
        EXPECT_EQ(wrapped.x(), x.x()) << k;
        EXPECT_EQ(wrapped.y(), 100.0); // the walled axis is not wrapped
    }
    // The high side is the low side's image.
    EXPECT_EQ(channel.wrap(Vec<2>(1.0, 1.0)).x(), -1.0);
}

TEST(PeriodicDomain, NothingLandsOutsideTheBoxEvenAtTheSeam)
{
    const PeriodicDomain<2> odd{Vec<2>(0.1, 0.0), Vec<2>(0.3, 1.0), {true, true}};
    for (const double x : {std::nextafter(0.1, 0.0), std::nextafter(0.4, 0.0), 0.4,
                           std::nextafter(0.4, 1.0), -1e-300, 0.1 - 3 * 0.3, 1e6 + 0.05}) {
        const double w = odd.wrap(Vec<2>(x, 0.5)).x();
        EXPECT_GE(w, 0.1) << x;
        EXPECT_LT(w, 0.1 + 0.3) << x;
        // and it is an image of x: a whole number of periods away
        const double periods = (x - w) / 0.3;
        EXPECT_NEAR(periods, std::round(periods), 1e-6 * (1.0 + std::abs(periods))) << x;
    }
}

TEST(PeriodicDomain, MinimumImageIsTheShortestDisplacementBetweenImages)
{
    const PeriodicDomain<3> box{Vec<3>::Zero(), Vec<3>(2.0, 4.0, 8.0), {true, false, true}};
    // Short displacements keep every bit.
    const Vec<3> shortest(0.999, -1.9, -3.5);
    EXPECT_EQ(box.minimum_image(shortest), shortest);
    // Across the seams: x 1.75 → −0.25; y is walled (kept); z −7.5 → 0.5.
    const Vec<3> d = box.minimum_image(Vec<3>(1.75, 3.5, -7.5));
    EXPECT_EQ(d, Vec<3>(-0.25, 3.5, 0.5));
    // Many periods away.
    EXPECT_EQ(box.minimum_image(Vec<3>(-9.5, 0.0, 40.25)), Vec<3>(0.5, 0.0, 0.25));
}

} // namespace
} // namespace fddem
