// SPDX-License-Identifier: MIT
// The time derivative of one step (core/time_scheme.hpp): (u^{n+1} − ũ^n)/Δt_e is implicit
// Euler's (u^{n+1} − u^n)/Δt, and BDF2's differentiates the parabola through three levels
// exactly at t^{n+1}, whatever the ratio of the two steps.

#include "fddem/core/time_scheme.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fddem {
namespace {

/// (u^{n+1} − ũ^n)/Δt_e for u sampled at t^{n−1} = t − dt − previous_dt, t^n = t − dt and
/// t^{n+1} = t.
template <class Function>
double derivative(const TimeLevels& levels, Function u, double t, double dt, double previous_dt)
{
    const double now = u(t - dt);
    const double before = u(t - dt - previous_dt);
    return (u(t) - levels.history(now, before)) / levels.dt_effective;
}

TEST(TimeLevels, EulerIsTheBackwardDifferenceBitForBit)
{
    const TimeLevels levels = time_levels(TimeScheme::euler, 0.0025, 0.005);
    EXPECT_EQ(levels.dt_effective, 0.0025);
    EXPECT_FALSE(levels.has_history());
    EXPECT_EQ(levels.history(-0.0, 7.0), -0.0);
    EXPECT_TRUE(std::signbit(levels.history(-0.0, 7.0))); // u^n itself, even its zero's sign
}

TEST(TimeLevels, Bdf2WithoutAPreviousStepIsEuler)
{
    const TimeLevels levels = time_levels(TimeScheme::bdf2, 0.01, 0.0);
    EXPECT_EQ(levels.dt_effective, 0.01);
    EXPECT_FALSE(levels.has_history());
}

TEST(TimeLevels, TheStepRatioIsTheNewStepOverTheLastAndZeroAtTheFirst)
{
    // ω = Δt_n/Δt_{n−1}: what the projection step extrapolates u^n + ω (u^n − u^{n−1}) with, for
    // either scheme; 0 (no extrapolation) where there was no step before.
    for (const TimeScheme scheme : {TimeScheme::euler, TimeScheme::bdf2}) {
        EXPECT_EQ(time_levels(scheme, 0.0025, 0.005).step_ratio, 0.5);
        EXPECT_EQ(time_levels(scheme, 0.01, 0.005).step_ratio, 2.0);
        EXPECT_EQ(time_levels(scheme, 0.01, 0.0).step_ratio, 0.0);
    }
    // A parabola sampled at the two levels: the extrapolation is its tangent at t^n.
    const double t = 1.0;
    const double dt = 0.01;
    const double previous = 0.005;
    const auto u = [](double s) { return 3.0 * s * s + s; };
    const double ratio = time_levels(TimeScheme::euler, dt, previous).step_ratio;
    const double extrapolated = u(t) + ratio * (u(t) - u(t - previous));
    const double tangent = u(t) + dt * (6.0 * t + 1.0);
    // Off the tangent by −3 Δt_n Δt_{n−1}: the O(Δt²) remainder, with u'' = 6.
    EXPECT_NEAR(extrapolated - tangent, -3.0 * dt * previous, 1e-12);
}

TEST(TimeLevels, Bdf2AtAConstantStepIsTheTextbookFormula)
{
    // (3u^{n+1} − 4u^n + u^{n−1})/(2Δt) = (u^{n+1} − ũ^n)/(2Δt/3), ũ^n = u^n + (u^n − u^{n−1})/3.
    const TimeLevels levels = time_levels(TimeScheme::bdf2, 0.3, 0.3);
    EXPECT_NEAR(levels.dt_effective, 0.2, 1e-15);
    EXPECT_NEAR(levels.history_weight, 1.0 / 3.0, 1e-15);
}

TEST(TimeLevels, Bdf2DifferentiatesAParabolaExactlyAtAnyStepRatio)
{
    const auto parabola = [](double t) { return 2.0 - 3.0 * t + 5.0 * t * t; };
    const double t = 1.7;
    for (const double ratio : {0.5, 0.8, 1.0, 1.2, 2.0}) {
        const double previous_dt = 0.1;
        const double dt = ratio * previous_dt;
        const TimeLevels levels = time_levels(TimeScheme::bdf2, dt, previous_dt);
        // Rounding: u ≈ 10, divided by Δt_e ≈ 0.1 → a few 1e-13.
        EXPECT_NEAR(derivative(levels, parabola, t, dt, previous_dt), -3.0 + 10.0 * t, 1e-12)
            << "ω = " << ratio;
        // Euler is off by −u''Δt/2 = −5Δt: first order.
        const TimeLevels euler = time_levels(TimeScheme::euler, dt, previous_dt);
        EXPECT_NEAR(derivative(euler, parabola, t, dt, previous_dt) - (-3.0 + 10.0 * t), -5.0 * dt,
                    1e-12);
    }
}

} // namespace
} // namespace fddem
