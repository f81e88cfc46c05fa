// SPDX-License-Identifier: MIT
// The adaptive time step (time.max_courant) and the pseudo-time march (time.steady).

#include "fddem/simulation/time_step_control.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/nans_allowed.hpp"

namespace fddem {
namespace {

TEST(TimeStepControl, CourantLimitHoldsTheStepToTheGivenCellsPerStep)
{
    const TimeStepSettings s{0.1, 0.5, false, std::nullopt, 1.2};
    // 40 cells per second: C/40 = 0.0125 s, below time.dt.
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.0, 40.0, {}), 0.5 / 40.0);
    // A slow flow: time.dt is the largest step.
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.0, 0.1, {}), 0.1);
}

TEST(TimeStepControl, ACourantStepBelowTheShortestAllowedIsACollapse)
{
    const TimeStepSettings s{0.1, 0.5, false, 1.0, 1.2};
    // 40 cells per second ask for 0.0125 s.
    EXPECT_FALSE(is_step_collapsed(s, 40.0, 0.01));
    EXPECT_TRUE(is_step_collapsed(s, 40.0, 0.02));
    // A fluid at rest asks for nothing; without the Courant limit nothing collapses.
    EXPECT_FALSE(is_step_collapsed(s, 0.0, 0.02));
    const TimeStepSettings fixed{0.1, std::nullopt, false, 1.0, 1.2};
    EXPECT_FALSE(is_step_collapsed(fixed, 1e9, 0.02));
}

TEST(TimeStepControl, AStepIsRetriedWhenItEndsAboveALimit)
{
    StepReport report;
    report.mass_residual = 0.2;
    report.courant = 0.9;
    // No limit given: kept, whatever its residual and Courant number.
    EXPECT_EQ(retry_reason(RetrySettings{3, std::nullopt, std::nullopt}, report), "");
    EXPECT_EQ(retry_reason(RetrySettings{3, 0.5, 1.0}, report), "");
    EXPECT_EQ(retry_reason(RetrySettings{3, 0.1, 1.0}, report),
              "mass residual 0.2 above time.retry_mass_residual = 0.1");
    EXPECT_EQ(retry_reason(RetrySettings{3, std::nullopt, 0.6}, report),
              "Courant number 0.9 above time.retry_courant = 0.6");
    // A residual that is not a number is above every limit.
    const test::NansAllowed nan; // the NaN is made on purpose
    report.mass_residual = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(retry_reason(RetrySettings{3, 0.5, std::nullopt}, report), "");
}

TEST(TimeStepControl, WithoutItsKeyAStepIsRetriedAboveFourTimesTheCourantLimit)
{
    // The case's value wins; without one, 4 × time.max_courant; without the limit, none.
    EXPECT_EQ(retry_courant_limit(0.9, 0.3), 0.9);
    EXPECT_EQ(retry_courant_limit(std::nullopt, 0.3), 1.2);
    EXPECT_EQ(retry_courant_limit(std::nullopt, std::nullopt), std::nullopt);
    EXPECT_EQ(retry_courant_limit(2.0, std::nullopt), 2.0);
    // Gondret St 27 at Δt 1e-4 s (C = 0.3): the step that ended at 8.4 is retried, the
    // largest a healthy run of it reached (0.371) is not.
    StepReport report;
    report.courant = 8.4;
    const RetrySettings defaulted{3, std::nullopt, retry_courant_limit(std::nullopt, 0.3)};
    EXPECT_EQ(retry_reason(defaulted, report), "Courant number 8.4 above time.retry_courant = 1.2");
    report.courant = 0.371;
    EXPECT_EQ(retry_reason(defaulted, report), "");
}

TEST(TimeStepControl, ARetryNeedsTheAdaptiveStepRetriesLeftAndRoomAboveTheShortestStep)
{
    const TimeStepSettings adaptive{0.1, 0.5, false, 1.0, 1.2};
    const RetrySettings three{3, std::nullopt, std::nullopt};
    EXPECT_TRUE(may_retry(adaptive, three, 0, 0.01, 1e-6));
    EXPECT_TRUE(may_retry(adaptive, three, 2, 0.01, 1e-6));
    EXPECT_FALSE(may_retry(adaptive, three, 3, 0.01, 1e-6)); // none left
    EXPECT_TRUE(may_retry(adaptive, three, 0, 0.01, 0.005));
    EXPECT_FALSE(may_retry(adaptive, three, 0, 0.01, 0.0051)); // Δt/2 below time.min_dt
    EXPECT_FALSE(may_retry(adaptive, RetrySettings{0, 0.1, 0.1}, 0, 0.01, 1e-6));
    // The fixed step of the paper's cases is never changed; the steady march has its own rule.
    const TimeStepSettings fixed{0.1, std::nullopt, false, 1.0, 1.2};
    EXPECT_FALSE(may_retry(fixed, three, 0, 0.01, 1e-6));
    const TimeStepSettings steady{0.1, 0.5, true, std::nullopt, 2.0};
    EXPECT_FALSE(may_retry(steady, three, 0, 0.01, 1e-6));
}

TEST(TimeStepControl, StepGrowsByAtMostTheGrowthFactor)
{
    const TimeStepSettings s{1.0, 0.5, false, std::nullopt, 1.2};
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 0.0, {}), 0.012);
}

TEST(TimeStepControl, LastStepLandsOnTheEndTime)
{
    const TimeStepSettings s{0.1, 0.5, false, 1.0, 1.2};
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.95, 1.0, {}), 1.0 - 0.95);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.5, 1.0, {}), 0.1);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.85, 1.0, {}), 0.075); // two equal last steps
}

TEST(TimeStepControl, StepLandsOnABodysReleaseAsOnTheEndTime)
{
    const TimeStepSettings s{0.1, 0.5, false, 2.0, 1.2};
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.95, 1.0, {}, 1.0), 1.0 - 0.95);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.85, 1.0, {}, 1.0), 0.075); // two equal steps
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 0.5, 1.0, {}, 1.0), 0.1);    // far ahead
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 1.2, 1.0, {}, 1.0), 0.1);    // passed: none
    // The end time still wins where it comes first; a release just before the end is met
    // exactly, and one past the end does not split the last step.
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 1.95, 1.0, {}, 3.0), 2.0 - 1.95);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 1.9, 1.0, {}, 1.9995), 1.9995 - 1.9);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.1, 1.9, 1.0, {}, 2.05), 2.0 - 1.9);
    // A fixed-step march (no Courant limit) lands on it too when the controller runs.
    const TimeStepSettings fixed{0.1, std::nullopt, false, std::nullopt, 1.2};
    EXPECT_DOUBLE_EQ(next_time_step(fixed, 0.1, 0.97, 0.0, {}, 1.0), 1.0 - 0.97);
}

TEST(TimeStepControl, SerFollowsTheResidualWithinItsBounds)
{
    const TimeStepSettings s{0.01, std::nullopt, true, std::nullopt, 2.0};
    TimeStepHistory h;
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 1.0, h), 0.01); // no history yet
    h.push(1e-2, true);
    h.push(0.8e-2, true); // fell by 1.25: Δt grows by 1.25
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 1.0, h), 0.0125);
    h.push(1e-4, true); // fell by 80: at most 2×
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 1.0, h), 0.02);
    h.push(1e-2, true); // rose by 100: at most halved
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 1.0, h), 0.005);
    h.push(1e-6, false); // fell, but the step did not converge: halved
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.01, 0.0, 1.0, h), 0.005);
}

TEST(TimeStepControl, SerStepIsCappedByTheCourantLimit)
{
    const TimeStepSettings s{0.01, 20.0, true, std::nullopt, 2.0};
    TimeStepHistory h;
    h.push(1.0, true);
    h.push(0.5, true);
    EXPECT_DOUBLE_EQ(next_time_step(s, 0.4, 0.0, 100.0, h), 0.2); // 20 cells / 100 per s
}

} // namespace
} // namespace fddem
