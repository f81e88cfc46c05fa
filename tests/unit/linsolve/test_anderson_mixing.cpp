// SPDX-License-Identifier: MIT
// Anderson mixing (linsolve/anderson_mixing.hpp): on a linear fixed point it is a Krylov method
// (Walker & Ni 2011, Thm 2.2: with m at least the number of iterations, AA is equivalent to
// GMRES), so an iteration with three distinct contraction factors converges to round-off in a
// handful of steps, where the plain iteration needs hundreds.

#include "fddem/linsolve/anderson_mixing.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#ifdef FDDEM_HAVE_OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace fddem {
namespace {

/// G(x) = M x + b with M = Q diag(factors) Qᵀ, Q a random orthogonal matrix.
struct LinearMap {
    Eigen::MatrixXd m;
    Eigen::VectorXd b;
    Eigen::VectorXd solution;

    LinearMap(int n, const std::vector<double>& factors, unsigned seed)
    {
        std::mt19937 random(seed);
        std::normal_distribution<double> normal;
        Eigen::MatrixXd a(n, n);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                a(i, j) = normal(random);
            }
        }
        const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(a).householderQ();
        Eigen::VectorXd d(n);
        for (int i = 0; i < n; ++i) {
            d(i) = factors[static_cast<std::size_t>(i) % factors.size()];
        }
        m = q * d.asDiagonal() * q.transpose();
        b = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(random); });
        solution = (Eigen::MatrixXd::Identity(n, n) - m).partialPivLu().solve(b);
    }
};

/// x after `iterations` steps of x ← G(x) from x = 0, mixed with depth `depth`, γ rounded to
/// `weight_bits` (0: not rounded).
Eigen::VectorXd iterate(const LinearMap& map, int depth, int iterations,
                        int weight_bits = AndersonMixing::default_weight_bits, int measured = -1,
                        double max_step_ratio = AndersonMixing::default_max_step_ratio)
{
    AndersonMixing mixing(depth, weight_bits, max_step_ratio);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(map.b.size());
    const auto n = static_cast<std::size_t>(x.size());
    const std::size_t m = measured < 0 ? n : static_cast<std::size_t>(measured);
    for (int k = 0; k < iterations; ++k) {
        std::vector<MixedSegment> segments{{{x.data(), m}, 1.0}};
        if (m < n) {
            segments.push_back({{x.data() + m, n - m}, 0.0});
        }
        mixing.remember(segments);
        x = map.m * x + map.b;
        mixing.mix(segments);
    }
    return x;
}

/// The error after `iterations` steps of x ← G(x), mixed with depth `depth`.
double error_after(const LinearMap& map, int depth, int iterations,
                   int weight_bits = AndersonMixing::default_weight_bits)
{
    const Eigen::VectorXd x = iterate(map, depth, iterations, weight_bits);
    return (x - map.solution).norm() / map.solution.norm();
}

TEST(AndersonMixing, ConvergesLikeAKrylovMethodOnALinearIteration)
{
    // Three distinct factors near one, as in the 18-disk pile's outer iterations.
    const LinearMap map(60, {0.95, 0.9, 0.6}, 7);
    const double plain = error_after(map, 0, 12);
    const double mixed = error_after(map, 3, 12);
    EXPECT_GT(plain, 0.3);  // 0.95^12 = 0.54 of the slowest component is left
    EXPECT_LT(mixed, 1e-9); // minimal polynomial of degree 3: exact after a few steps
}

TEST(AndersonMixing, RoundsTheWeightsToSignificantBits)
{
    const auto power = [](int e) { return std::ldexp(1.0, e); };
    // Below half a step, half a step (ties to even, either way), above half a step.
    EXPECT_EQ(round_to_significant_bits(1.0 + power(-13), 12), 1.0);
    EXPECT_EQ(round_to_significant_bits(1.0 + power(-12), 12), 1.0);                    // tie, down
    EXPECT_EQ(round_to_significant_bits(1.0 + 3.0 * power(-12), 12), 1.0 + power(-10)); // up
    EXPECT_EQ(round_to_significant_bits(-(1.0 + 3.0 * power(-12)), 12), -(1.0 + power(-10)));
    EXPECT_EQ(round_to_significant_bits(0.625, 2), 0.5); // tie, down to even
    EXPECT_EQ(round_to_significant_bits(0.875, 2), 1.0); // tie, up to even
    EXPECT_EQ(round_to_significant_bits(0.75, 2), 0.75); // already 2 bits
    EXPECT_EQ(round_to_significant_bits(0.0, 12), 0.0);
    const double largest = std::numeric_limits<double>::max();
    const double smallest = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(round_to_significant_bits(largest, 12), largest); // would overflow: as it is
    EXPECT_EQ(round_to_significant_bits(smallest, 12), smallest);
    EXPECT_EQ(round_to_significant_bits(1.0 + power(-52), 53), 1.0 + power(-52));
    EXPECT_TRUE(std::isinf(round_to_significant_bits(std::numeric_limits<double>::infinity(), 12)));
    EXPECT_TRUE(
        std::isnan(round_to_significant_bits(std::numeric_limits<double>::quiet_NaN(), 12)));
    std::mt19937 random(3);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-1070, 1020); // subnormals included
    for (int i = 0; i < 2000; ++i) {
        const double x = std::ldexp(mantissa(random), exponent(random));
        const double r = round_to_significant_bits(x, 12);
        ASSERT_LE(std::abs(r - x), std::ldexp(std::abs(x), -12)) << x;
        ASSERT_EQ(round_to_significant_bits(r, 12), r) << x; // idempotent
    }
}

TEST(AndersonMixing, RoundedWeightsDoNotAmplifyRoundOff)
{
    // Two runs whose G differs by round-off (b scaled by 1 + 1e-15), as a run on several ranks
    // and one on one process do. As in fddem's outer iterations, only a few values are measured
    // (there: the bodies' velocities) and the rest are carried with the same γ. Measured: the
    // plain iteration keeps the runs within 1.3e-15 of |x|; mixed with depth 2, unrounded γ
    // follows the difference and the runs part by up to 1.1e-10 within 40 iterations; rounded
    // to 12 bits they part by up to 2.4e-13 (8e-15 to 8e-14 with 8-14 bits). The bounds ask
    // for the rounding to remove at least 99 % of the amplification.
    const LinearMap map(60, {0.95, 0.9, 0.85, 0.6, 0.3}, 5);
    LinearMap perturbed = map;
    perturbed.b *= 1.0 + 1e-15;
    const auto largest_difference = [&](int depth, int bits) {
        double largest = 0.0;
        for (int iterations = 1; iterations <= 40; ++iterations) {
            const Eigen::VectorXd a = iterate(map, depth, iterations, bits, 3);
            const Eigen::VectorXd b = iterate(perturbed, depth, iterations, bits, 3);
            largest = std::max(largest, (a - b).norm() / a.norm());
        }
        return largest;
    };
    const double plain = largest_difference(0, 0);
    const double unrounded = largest_difference(2, 0);
    const double rounded = largest_difference(2, AndersonMixing::default_weight_bits);
    std::printf("[ info ] largest relative difference of the two runs: %.2e plain, %.2e mixed "
                "unrounded, %.2e mixed rounded\n",
                plain, unrounded, rounded);
    EXPECT_GT(unrounded, 1e4 * plain); // the amplification exists here
    EXPECT_LT(rounded, 1e-2 * unrounded);
    // The rounding leaves the convergence as it was (measured: 4.47e-4 against 4.41e-4 after 40
    // iterations with all values measured), far ahead of the plain iteration.
    const double error_rounded = error_after(map, 2, 40);
    const double error_unrounded = error_after(map, 2, 40, 0);
    EXPECT_LT(error_rounded, 1.1 * error_unrounded);
    EXPECT_LT(error_rounded, 0.1 * error_after(map, 0, 40));
}

TEST(AndersonMixing, DepthOneAcceleratesASingleSlowMode)
{
    // One slow factor and fast ones: depth 1 removes the slow mode like a secant step.
    const LinearMap map(40, {0.93, 0.2, 0.1, 0.05}, 11);
    const double plain = error_after(map, 0, 15);
    const double mixed = error_after(map, 1, 15);
    EXPECT_LT(mixed, 1e-3 * plain);
}

TEST(AndersonMixing, TakesTheStepThatRemovesAModeContractingByUpTo099)
{
    // One mode contracting by ρ and fast ones: the step to the fixed point along it is
    // ρ/(1 − ρ) ‖f‖ (9 at ρ = 0.9, 49 at 0.98), inside a bound of 100, so the bounded mixing is
    // the unbounded one (and a bound of 5 refuses the steps).
    for (const double slow : {0.9, 0.98}) {
        const LinearMap map(30, {slow, 0.2, 0.1}, 17);
        const int bits = AndersonMixing::default_weight_bits;
        const Eigen::VectorXd bounded = iterate(map, 2, 12, bits, -1, 100.0);
        const Eigen::VectorXd unbounded = iterate(map, 2, 12, bits, -1, 0.0);
        const Eigen::VectorXd tight = iterate(map, 2, 12, bits, -1, 5.0);
        EXPECT_GT((tight - unbounded).norm(), 1e-3 * map.solution.norm()) << slow;
        EXPECT_EQ((bounded - unbounded).norm(), 0.0) << slow;
        EXPECT_LT((bounded - map.solution).norm(), 1e-6 * map.solution.norm()) << slow;
    }
}

TEST(AndersonMixing, RefusesAStepFarBeyondTheResidualAndKeepsTheOutput)
{
    // A residual that has stopped shrinking: G(x) = x + f with f alternating between two nearly
    // equal vectors (the noise floor of an inexact inner solve). ΔF is tiny, so γ is huge and
    // the unbounded step throws x a hundred thousand residuals away; the bounded mixing refuses
    // it, keeps G(x_k), and reports the ratio it refused.
    const std::size_t n = 4;
    const auto size = static_cast<Eigen::Index>(n);
    const Eigen::VectorXd f1 = Eigen::VectorXd::Constant(size, 1e-6);
    const Eigen::VectorXd f2 = f1 + 1e-11 * Eigen::VectorXd::Unit(size, 0);
    for (const double bound : {100.0, 0.0}) {
        AndersonMixing mixing(1, 0, bound);
        Eigen::VectorXd x = Eigen::VectorXd::Ones(n);
        bool last_mixed = true;
        Eigen::VectorXd output;
        for (int k = 0; k < 3; ++k) {
            const std::vector<MixedSegment> segments{{{x.data(), n}, 1.0}};
            mixing.remember(segments);
            x += (k % 2 == 0) ? f1 : f2;
            output = x;
            last_mixed = mixing.mix(segments);
        }
        if (bound > 0.0) {
            EXPECT_FALSE(last_mixed);
            EXPECT_GT(mixing.last_step_ratio(), bound);
            EXPECT_EQ((x - output).norm(), 0.0); // G(x_k) kept
        } else {
            EXPECT_TRUE(last_mixed);
            EXPECT_GT((x - output).norm(), 1e3 * f1.norm()); // the step it would have taken
        }
    }
}

TEST(AndersonMixing, DepthZeroIsThePlainIteration)
{
    AndersonMixing mixing(0);
    std::vector<double> x(20, 1.0);
    std::vector<double> g(20, 2.0);
    const std::vector<MixedSegment> before{{x, 1.0}};
    const std::vector<MixedSegment> after{{g, 1.0}};
    mixing.remember(before);
    mixing.mix(after);
    mixing.remember(after);
    mixing.mix(after);
    for (const double v : g) {
        EXPECT_EQ(v, 2.0);
    }
}

TEST(AndersonMixing, KeepsALinearConstraintEveryOutputSatisfies)
{
    // G projects onto Σx = 1 (the analogue of a divergence-free velocity): the mixed iterates,
    // combinations with weights summing to one, satisfy it too.
    const int n = 30;
    const LinearMap map(n, {0.9, 0.7, 0.3}, 5);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
    AndersonMixing mixing(3);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < 8; ++k) {
        const std::vector<MixedSegment> segments{{{x.data(), static_cast<std::size_t>(n)}, 1.0}};
        mixing.remember(segments);
        Eigen::VectorXd g = map.m * x + map.b;
        g += ones * (1.0 - g.sum()) / n;
        x = g;
        mixing.mix(segments);
        EXPECT_NEAR(x.sum(), 1.0, 1e-12) << "iteration " << k;
        if (k >= 2) {
            EXPECT_FALSE(mixing.last_weights().empty());
        }
    }
}

TEST(AndersonMixing, CarriesUnmeasuredSegmentsWithTheSameWeights)
{
    // The carried segment y = C x is derived from the measured one: after mixing it must still
    // be C x of the mixed x (the bodies' U from the fluid in fddem), and must not change γ.
    const int n = 25;
    const LinearMap map(n, {0.95, 0.8, 0.4}, 9);
    Eigen::MatrixXd c = Eigen::MatrixXd::Random(3, n);
    AndersonMixing with_carried(2);
    AndersonMixing measured_only(2);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd x_alone = x;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3);
    for (int k = 0; k < 6; ++k) {
        const std::vector<MixedSegment> segments{{{x.data(), static_cast<std::size_t>(n)}, 1.0},
                                                 {{y.data(), 3}, 0.0}};
        const std::vector<MixedSegment> alone{{{x_alone.data(), static_cast<std::size_t>(n)}, 1.0}};
        with_carried.remember(segments);
        measured_only.remember(alone);
        x = map.m * x + map.b;
        y = c * x;
        x_alone = map.m * x_alone + map.b;
        with_carried.mix(segments);
        measured_only.mix(alone);
        EXPECT_LT((y - c * x).norm(), 1e-12 * (1.0 + y.norm())) << "iteration " << k;
        EXPECT_LT((x - x_alone).norm(), 1e-13 * x.norm()) << "iteration " << k;
    }
}

TEST(AndersonMixing, RejectsAStateWhoseLayoutChanged)
{
    AndersonMixing mixing(2);
    std::vector<double> a(10, 0.0);
    std::vector<double> b(12, 0.0);
    const std::vector<MixedSegment> small{{a, 1.0}};
    const std::vector<MixedSegment> large{{b, 1.0}};
    mixing.remember(small);
    EXPECT_THROW(mixing.mix(large), std::logic_error);
    const std::vector<MixedSegment> carried_first{{a, 0.0}, {b, 1.0}};
    EXPECT_THROW(mixing.remember(carried_first), std::logic_error);
}

TEST(AndersonMixing, WeightsScaleTheNormAsIfTheValuesWereScaled)
{
    // Measuring x with weight w gives the same iterates as measuring the scaled map's w·x
    // with weight 1: a weight is a change of units (ω measured at the rim, ×R).
    const int n = 20;
    const LinearMap map(n, {0.9, 0.6, 0.3}, 13);
    Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(n, 0.5, 3.0);
    AndersonMixing weighted(2);
    AndersonMixing scaled(2);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n); // z = W x
    for (int k = 0; k < 6; ++k) {
        std::vector<MixedSegment> parts;
        for (int i = 0; i < n; ++i) {
            parts.push_back({{&x(i), 1}, weights(i)});
        }
        const std::vector<MixedSegment> whole{{{z.data(), static_cast<std::size_t>(n)}, 1.0}};
        weighted.remember(parts);
        scaled.remember(whole);
        x = map.m * x + map.b;
        z = weights.asDiagonal() * (map.m * (weights.cwiseInverse().asDiagonal() * z) + map.b);
        weighted.mix(parts);
        scaled.mix(whole);
        EXPECT_LT((weights.asDiagonal() * x - z).norm(), 1e-12 * z.norm()) << "iteration " << k;
    }
}

TEST(AndersonMixing, BlockedDotIsTheSameForAnyThreadCount)
{
    std::mt19937 random(1);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double> a(100003);
    std::vector<double> b(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        a[i] = uniform(random);
        b[i] = uniform(random);
    }
    long double exact = 0.0L;
    for (std::size_t i = 0; i < a.size(); ++i) {
        exact += static_cast<long double>(a[i]) * static_cast<long double>(b[i]);
    }
#ifdef FDDEM_HAVE_OPENMP
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const double one = blocked_dot(a, b);
    omp_set_num_threads(2);
    const double two = blocked_dot(a, b);
    omp_set_num_threads(threads);
    EXPECT_EQ(one, two);
#endif
    EXPECT_NEAR(blocked_dot(a, b), static_cast<double>(exact), 1e-10);
}

} // namespace
} // namespace fddem
