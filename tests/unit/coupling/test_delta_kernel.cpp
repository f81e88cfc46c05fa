// SPDX-License-Identifier: MIT
#include "fddem/coupling/delta_kernel.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fddem {
namespace {

/// Σ_i φ(s − i) and Σ_i (s − i) φ(s − i) over the integers in the support.
template <DeltaKernel K>
std::pair<double, double> moments(double s)
{
    double sum = 0.0;
    double first = 0.0;
    for (int i = static_cast<int>(std::floor(s)) - K::half_width - 1;
         i <= static_cast<int>(std::floor(s)) + K::half_width + 1; ++i) {
        const double w = K::weight(s - i);
        sum += w;
        first += (s - i) * w;
    }
    return {sum, first};
}

template <class T>
class Kernels : public ::testing::Test {
};
using KernelTypes =
    ::testing::Types<HatKernel, RomaPeskin3Kernel, Peskin4Kernel, SmoothedRoma3Kernel>;
TYPED_TEST_SUITE(Kernels, KernelTypes);

TYPED_TEST(Kernels, PartitionOfUnityAndZeroFirstMomentAtAnyOffset)
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> offset(-3.0, 3.0);
    for (int k = 0; k < 1000; ++k) {
        const auto [sum, first] = moments<TypeParam>(offset(rng));
        EXPECT_NEAR(sum, 1.0, 1e-14);
        EXPECT_NEAR(first, 0.0, 1e-14);
    }
}

TYPED_TEST(Kernels, VanishesOutsideItsSupport)
{
    EXPECT_EQ(TypeParam::weight(TypeParam::half_width + 0.01), 0.0);
    EXPECT_EQ(TypeParam::weight(-TypeParam::half_width - 0.01), 0.0);
}

TYPED_TEST(Kernels, TheSupportRadiusIsWhereTheWeightEnds)
{
    // coupling.markers_off_reach's default is built on it (support + 0.5 cells): zero at and
    // beyond it, nonzero just inside (roma3's 1.5 is below its stencil half width of 2).
    const double r = TypeParam::support_radius;
    EXPECT_NEAR(TypeParam::weight(r), 0.0, 1e-14);
    EXPECT_EQ(TypeParam::weight(r + 0.01), 0.0);
    EXPECT_GT(TypeParam::weight(r - 0.01), 0.0); // 6.4e-7 for the smoothed kernel
    EXPECT_LE(r, TypeParam::half_width);
}

TEST(Kernels, TheWallMarkerReachIsTheSupportAndHalfACell)
{
    EXPECT_EQ(default_wall_marker_reach(support_radius(KernelKind::hat)), 1.5);
    EXPECT_EQ(default_wall_marker_reach(support_radius(KernelKind::roma3)), 2.0);
    EXPECT_EQ(default_wall_marker_reach(support_radius(KernelKind::peskin4)), 2.5);
    EXPECT_EQ(default_wall_marker_reach(support_radius(KernelKind::roma3_smoothed)), 2.5);
}

TEST(Kernels, TheSmoothedKernelIsRoma3AveragedOverACell)
{
    // Yang et al. (2009) build φ̃(s) = ∫_{s−1/2}^{s+1/2} φ(t) dt from the three-point kernel φ;
    // the closed form must agree with the integral (Simpson's rule on 20000 intervals).
    for (double s = -2.2; s <= 2.2; s += 0.0371) {
        const int n = 20000;
        const double dt = 1.0 / n;
        double integral = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double t = s - 0.5 + i * dt;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
            integral += w * RomaPeskin3Kernel::weight(t);
        }
        integral *= dt / 3.0;
        EXPECT_NEAR(SmoothedRoma3Kernel::weight(s), integral, 1e-9) << "s = " << s;
    }
    // Continuous where its pieces meet, and zero at the end of its support.
    EXPECT_NEAR(SmoothedRoma3Kernel::weight(1.0 - 1e-12), SmoothedRoma3Kernel::weight(1.0 + 1e-12),
                1e-10);
    EXPECT_NEAR(SmoothedRoma3Kernel::weight(2.0), 0.0, 1e-14);
}

TEST(Kernels, NamesSelectKernels)
{
    EXPECT_TRUE(std::holds_alternative<HatKernel>(make_kernel(KernelKind::hat)));
    EXPECT_TRUE(std::holds_alternative<Peskin4Kernel>(make_kernel(KernelKind::peskin4)));
    EXPECT_TRUE(
        std::holds_alternative<SmoothedRoma3Kernel>(make_kernel(KernelKind::roma3_smoothed)));
}

} // namespace
} // namespace fddem
