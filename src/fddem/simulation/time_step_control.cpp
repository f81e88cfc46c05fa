// SPDX-License-Identifier: MIT
#include "fddem/simulation/time_step_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace fddem {

bool is_step_collapsed(const TimeStepSettings& settings, double speed_per_cell,
                       double min_dt) noexcept
{
    return settings.max_courant && speed_per_cell > 0.0 &&
           *settings.max_courant < min_dt * speed_per_cell;
}

namespace {

/// x > limit, or x not a number (without the floating-point trap an ordered compare raises).
bool is_above(double x, double limit) noexcept
{
    return std::isnan(x) || std::isgreater(x, limit);
}

} // namespace

std::string retry_reason(const RetrySettings& retry, const StepReport& report)
{
    if (retry.mass_residual && is_above(report.mass_residual, *retry.mass_residual)) {
        return fmt::format("mass residual {:.3g} above time.retry_mass_residual = {:g}",
                           report.mass_residual, *retry.mass_residual);
    }
    if (retry.courant && is_above(report.courant, *retry.courant)) {
        return fmt::format("Courant number {:.3g} above time.retry_courant = {:g}", report.courant,
                           *retry.courant);
    }
    return {};
}

std::optional<double> retry_courant_limit(std::optional<double> retry_courant,
                                          std::optional<double> max_courant) noexcept
{
    if (retry_courant || !max_courant) {
        return retry_courant;
    }
    return default_retry_courant_factor * *max_courant;
}

bool may_retry(const TimeStepSettings& settings, const RetrySettings& retry, int retries, double dt,
               double min_dt) noexcept
{
    return settings.max_courant && !settings.is_steady && retries < retry.max_retries &&
           0.5 * dt >= min_dt;
}

namespace {

/// `next` shortened to land on a time `left` [s] ahead rather than step past it or stop short
/// of it: the last one or two steps share what is left evenly; a remainder within a hundredth
/// of a step is taken in one.
double land(double next, double left) noexcept
{
    if (left > 0.0 && left < next * 1.01) {
        return left;
    }
    if (left > 0.0 && left < 2.0 * next) {
        return 0.5 * left;
    }
    return next;
}

} // namespace

double next_time_step(const TimeStepSettings& settings, double dt, double time,
                      double speed_per_cell, const TimeStepHistory& history,
                      std::optional<double> landing)
{
    double next = dt;
    if (settings.is_steady) {
        // SER: the step grows as the residual falls (and shrinks if it rises).
        if (!history.is_converged) {
            next = dt / settings.max_growth;
        } else if (history.previous_residual > 0.0 && history.residual > 0.0) {
            const double ratio = std::clamp(history.previous_residual / history.residual,
                                            1.0 / settings.max_growth, settings.max_growth);
            next = dt * ratio;
        }
    } else {
        next = std::min(settings.initial_dt, dt * settings.max_growth);
    }
    if (settings.max_courant && speed_per_cell > 0.0) {
        next = std::min(next, *settings.max_courant / speed_per_cell);
    }
    if (!settings.is_steady) {
        // Land on the nearer of the two ahead (the end test allows half a step; a release is
        // met exactly, to round-off).
        std::optional<double> target = settings.end_time;
        if (landing && *landing > time && (!target || *landing < *target)) {
            target = landing;
        }
        if (target) {
            next = land(next, *target - time);
        }
    }
    return next;
}

} // namespace fddem
