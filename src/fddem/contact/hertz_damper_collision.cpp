// SPDX-License-Identifier: MIT
#include "fddem/contact/hertz_damper_collision.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fddem {
namespace {

struct Phase {
    double x; ///< scaled overlap
    double v; ///< x'
};

/// x'' for damping γ; no spring outside the contact (a Runge–Kutta stage may step past x = 0).
double acceleration(const Phase& s, double damping)
{
    const double x = std::max(s.x, 0.0);
    return -damping * s.v - x * std::sqrt(x);
}

Phase rk4_step(const Phase& s, double damping, double h)
{
    const auto rate = [damping](const Phase& p) { return Phase{p.v, acceleration(p, damping)}; };
    const auto along = [](const Phase& p, const Phase& d, double t) {
        return Phase{p.x + t * d.x, p.v + t * d.v};
    };
    const Phase k1 = rate(s);
    const Phase k2 = rate(along(s, k1, 0.5 * h));
    const Phase k3 = rate(along(s, k2, 0.5 * h));
    const Phase k4 = rate(along(s, k3, h));
    return {s.x + h / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x),
            s.v + h / 6.0 * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v)};
}

/// The fraction θ ∈ [0, 1] of a step of length h at which the cubic Hermite interpolant of x
/// through (a, b) crosses 0 (a.x > 0 ≥ b.x), by bisection; and x' there.
Phase exit_within_step(const Phase& a, const Phase& b, double h, double& theta)
{
    const auto x_at = [&](double t) {
        const double t2 = t * t;
        const double t3 = t2 * t;
        return (2.0 * t3 - 3.0 * t2 + 1.0) * a.x + (t3 - 2.0 * t2 + t) * h * a.v +
               (-2.0 * t3 + 3.0 * t2) * b.x + (t3 - t2) * h * b.v;
    };
    double low = 0.0;
    double high = 1.0;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (low + high);
        (x_at(mid) > 0.0 ? low : high) = mid;
    }
    theta = 0.5 * (low + high);
    const double t = theta;
    const double t2 = t * t;
    const double v = ((6.0 * t2 - 6.0 * t) * a.x + (3.0 * t2 - 4.0 * t + 1.0) * h * a.v +
                      (-6.0 * t2 + 6.0 * t) * b.x + (3.0 * t2 - 2.0 * t) * h * b.v) /
                     h;
    return {0.0, v};
}

} // namespace

ScaledCollision scaled_hertz_damper_collision(double damping)
{
    if (!(damping >= 0.0) || !std::isfinite(damping)) {
        throw InternalError("scaled_hertz_damper_collision: the damping must be finite and >= 0");
    }
    constexpr double h = 1e-3;        // see the file comment
    constexpr double longest = 100.0; // τ beyond which a collision counts as never ending
    const auto n_max = static_cast<long>(longest / h);
    Phase s{0.0, 1.0};
    ScaledCollision out;
    for (long n = 0; n < n_max; ++n) {
        const Phase next = rk4_step(s, damping, h);
        if (next.x <= 0.0) {
            double theta = 0.0;
            const Phase exit = exit_within_step(s, next, h, theta);
            out.restitution = -exit.v;
            out.duration = (static_cast<double>(n) + theta) * h;
            return out;
        }
        out.max_overlap = std::max(out.max_overlap, next.x);
        s = next;
    }
    out.restitution = 0.0;
    out.duration = std::numeric_limits<double>::infinity();
    return out;
}

double scaled_damping_for_restitution(double restitution)
{
    if (!(restitution > 0.0 && restitution <= 1.0)) {
        throw InternalError("scaled_damping_for_restitution: e must be in (0, 1]");
    }
    if (restitution == 1.0) {
        return 0.0;
    }
    // e(γ) falls from 1 at γ = 0 to 0 at γ* ≈ 1.128 (e(2) = 0): the root lies in [0, 2].
    double low = 0.0;
    double high = 2.0;
    while (high - low > 4.0 * std::numeric_limits<double>::epsilon() * high) {
        const double mid = 0.5 * (low + high);
        (scaled_hertz_damper_collision(mid).restitution > restitution ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

} // namespace fddem
