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
using KernelTypes = ::testing::Types<HatKernel, RomaPeskin3Kernel, Peskin4Kernel>;
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

TEST(Kernels, NamesSelectKernels)
{
    EXPECT_TRUE(std::holds_alternative<HatKernel>(make_kernel(KernelKind::hat)));
    EXPECT_TRUE(std::holds_alternative<Peskin4Kernel>(make_kernel(KernelKind::peskin4)));
}

} // namespace
} // namespace fddem
