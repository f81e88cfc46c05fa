// SPDX-License-Identifier: MIT
#include "fddem/contact/lubrication.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;

/// ln(1/ξ), clamped at 0 beyond ξ = 1 where the expansion means nothing.
double log_inverse(double xi)
{
    return std::max(0.0, -std::log(xi));
}

/// The sphere forms' coefficients: c_n = 6πμ a1 [g1 ā/h + g2 ln(ā/h)], c_t = 6πμ a1 g_t ln(ā/h).
struct SphereCoefficients {
    double mean; ///< ā: a1 for a wall, (a1 + a2)/2 for two spheres
    double g1;
    double g2;
    double gt;
};

SphereCoefficients sphere_coefficients(double radius, double other_radius)
{
    if (std::isinf(other_radius)) {
        // A plane wall (Cox & Brenner 1967; Goldman, Cox & Brenner 1967).
        return {radius, 1.0, 0.2, 8.0 / 15.0};
    }
    // Two spheres (Jeffrey 1982; Jeffrey & Onishi 1984), β = a2/a1, ξ = 2h/(a1 + a2).
    const double beta = other_radius / radius;
    const double cube = (1.0 + beta) * (1.0 + beta) * (1.0 + beta);
    return {0.5 * (radius + other_radius), 2.0 * beta * beta / cube,
            beta * (1.0 + 7.0 * beta + beta * beta) / (5.0 * cube),
            4.0 * beta * (2.0 + beta + 2.0 * beta * beta) / (15.0 * cube)};
}

LubricationResistance spheres(double gap, double radius, double other_radius, double viscosity)
{
    const double scale = 6.0 * pi * viscosity * radius; // 6πμ a1
    const SphereCoefficients k = sphere_coefficients(radius, other_radius);
    const double logs = log_inverse(gap / k.mean);
    return {scale * (k.g1 * k.mean / gap + k.g2 * logs), scale * k.gt * logs};
}

LubricationResistance disks(double gap, double radius, double other_radius, double viscosity)
{
    // Reynolds' lubrication equation for the gap h + x²/(2a*), per unit length
    // (docs/method.md §5, Lubrication).
    const double reduced =
        std::isinf(other_radius) ? radius : radius * other_radius / (radius + other_radius);
    const double ratio = reduced / gap;
    return {3.0 * std::numbers::sqrt2 * pi * viscosity * ratio * std::sqrt(ratio),
            2.0 * std::numbers::sqrt2 * pi * viscosity * std::sqrt(ratio)};
}

/// ∫ max(0, ln(ā/h)) dh from 0: h (ln(ā/h) + 1) up to ā, then constant.
double log_inverse_integral(double gap, double mean_radius)
{
    return gap < mean_radius ? gap * (std::log(mean_radius / gap) + 1.0) : mean_radius;
}

/// An antiderivative in h of spheres(): its 1/h terms give logarithms, its ln(1/ξ) terms
/// log_inverse_integral.
LubricationResistance spheres_integral(double gap, double radius, double other_radius,
                                       double viscosity)
{
    const double scale = 6.0 * pi * viscosity * radius;
    const SphereCoefficients k = sphere_coefficients(radius, other_radius);
    const double logs = log_inverse_integral(gap, k.mean);
    return {scale * (k.g1 * k.mean * std::log(gap) + k.g2 * logs), scale * k.gt * logs};
}

/// An antiderivative in h of disks(): of h^(−3/2), −2 h^(−1/2); of h^(−1/2), 2 h^(1/2).
LubricationResistance disks_integral(double gap, double radius, double other_radius,
                                     double viscosity)
{
    const double reduced =
        std::isinf(other_radius) ? radius : radius * other_radius / (radius + other_radius);
    return {-2.0 * 3.0 * std::numbers::sqrt2 * pi * viscosity * reduced * std::sqrt(reduced / gap),
            2.0 * 2.0 * std::numbers::sqrt2 * pi * viscosity * std::sqrt(reduced * gap)};
}

template <int Dim>
LubricationResistance resistance_integral(double gap, double radius, double other_radius,
                                          double viscosity)
{
    if constexpr (Dim == 2) {
        return disks_integral(gap, radius, other_radius, viscosity);
    } else {
        return spheres_integral(gap, radius, other_radius, viscosity);
    }
}

LubricationResistance operator-(const LubricationResistance& x, const LubricationResistance& y)
{
    return {x.normal - y.normal, x.tangential - y.tangential};
}

LubricationResistance operator+(const LubricationResistance& x, const LubricationResistance& y)
{
    return {x.normal + y.normal, x.tangential + y.tangential};
}

LubricationResistance operator*(double factor, const LubricationResistance& x)
{
    return {factor * x.normal, factor * x.tangential};
}

} // namespace

template <int Dim>
LubricationResistance lubrication_resistance(double gap, double radius, double other_radius,
                                             double viscosity)
{
    if constexpr (Dim == 2) {
        return disks(gap, radius, other_radius, viscosity);
    } else {
        return spheres(gap, radius, other_radius, viscosity);
    }
}

template <int Dim>
LubricationResistance lubrication_correction(double gap, double radius, double other_radius,
                                             const LubricationSettings& settings, double shell_gap)
{
    const double roughness = settings.roughness * std::min(radius, other_radius);
    if (!settings.is_enabled || gap >= settings.range || roughness >= settings.range) {
        return {};
    }
    if (gap <= 0.0 && settings.in_contact == LubricationInContact::off) {
        return {}; // in contact: the contact model alone (Costa et al. 2015)
    }
    const auto c = [&](double h) {
        return lubrication_resistance<Dim>(h, radius, other_radius, settings.viscosity);
    };
    const LubricationResistance near = c(std::max(gap, roughness));
    LubricationResistance resolved = c(settings.range);
    if (settings.resolved == LubricationResolved::shells) {
        // The film between the marker shells, h + s, less its share at h_Δ (continuity).
        const LubricationResistance shells = c(std::max(gap, roughness) + shell_gap);
        const LubricationResistance shells_at_range = c(settings.range + shell_gap);
        resolved.normal += shells.normal - shells_at_range.normal;
        resolved.tangential += shells.tangential - shells_at_range.tangential;
    }
    return {std::max(0.0, near.normal - resolved.normal),
            std::max(0.0, near.tangential - resolved.tangential)};
}

namespace {

/// ∫ c_corr over [from, to] (either order), piece by piece: the overlap (0 or the held value),
/// (0, h_σ] (the held value), (h_σ, h_Δ) (the antiderivative's difference over that piece
/// alone, so that no large constant of another piece enters the difference), beyond h_Δ (0).
template <int Dim>
LubricationResistance correction_between(double from, double to, double radius, double other_radius,
                                         const LubricationSettings& settings, double shell_gap)
{
    const double roughness = settings.roughness * std::min(radius, other_radius);
    if (!settings.is_enabled || roughness >= settings.range || from == to) {
        return {};
    }
    const double sign = to > from ? 1.0 : -1.0;
    const double lo = std::min(from, to);
    const double hi = std::max(from, to);
    const bool has_shells = settings.resolved == LubricationResolved::shells;
    const auto c = [&](double h) {
        return lubrication_resistance<Dim>(h, radius, other_radius, settings.viscosity);
    };
    const auto integral = [&](double h) {
        return resistance_integral<Dim>(h, radius, other_radius, settings.viscosity);
    };
    // c_corr(h) = p(max(h, h_σ)) − k below h_Δ (lubrication_correction; it is ≥ 0 there, as c
    // and c(h) − c(h + s) fall with h), with p(x) = c(x) [− c(x + s)] and its antiderivative P.
    const auto p = [&](double x) { return has_shells ? c(x) - c(x + shell_gap) : c(x); };
    const auto big_p = [&](double x) {
        return has_shells ? integral(x) - integral(x + shell_gap) : integral(x);
    };
    const LubricationResistance k = p(settings.range);
    const LubricationResistance held = p(roughness) - k; // c_corr on (0, h_σ]
    const auto length = [&](double a, double b) {
        return std::max(0.0, std::min(hi, b) - std::max(lo, a));
    };
    LubricationResistance sum =
        length(0.0, roughness) * held +
        (settings.in_contact == LubricationInContact::saturated ? length(lo, 0.0) : 0.0) * held;
    const double film_lo = std::max(lo, roughness);
    const double film_hi = std::min(hi, settings.range);
    if (film_hi > film_lo) {
        sum = sum + (big_p(film_hi) - big_p(film_lo)) - (film_hi - film_lo) * k;
    }
    return sign * sum;
}

} // namespace

template <int Dim>
LubricationResistance
lubrication_correction_integral(double gap, double radius, double other_radius,
                                const LubricationSettings& settings, double shell_gap)
{
    return correction_between<Dim>(0.0, gap, radius, other_radius, settings, shell_gap);
}

template <int Dim>
LubricationResistance
lubrication_correction_over(double from, double to, double radius, double other_radius,
                            const LubricationSettings& settings, double shell_gap)
{
    const auto resistance = [&](double h) {
        return lubrication_correction<Dim>(h, radius, other_radius, settings, shell_gap);
    };
    if (to == from) {
        return resistance(from);
    }
    const double roughness = settings.roughness * std::min(radius, other_radius);
    const auto crosses = [&](double joint) { return (from - joint) * (to - joint) <= 0.0; };
    if (std::abs(to - from) > 1e-2 * std::max(std::abs(from), roughness) || crosses(0.0) ||
        crosses(roughness) || crosses(settings.range)) {
        return (1.0 / (to - from)) *
               correction_between<Dim>(from, to, radius, other_radius, settings, shell_gap);
    }
    // A travel below 1 % of the gap, over which c_corr is smooth: G's two values would agree
    // in most of their digits, Simpson's rule is within 1e-9 of the mean.
    return (1.0 / 6.0) * (resistance(from) + resistance(to) + 4.0 * resistance(0.5 * (from + to)));
}

template <int Dim>
FilmStep film_step(double gap, double gap_rate, double inverse_mass, double step, double radius,
                   double other_radius, const LubricationSettings& settings, double shell_gap)
{
    const auto resistance = [&](double h) {
        return lubrication_correction<Dim>(h, radius, other_radius, settings, shell_gap);
    };
    // ∫ c_corr over the travel at `rate` (G(h1) − G(h0)).
    const auto between = [&](double rate) {
        const double travel = step * rate;
        return travel * lubrication_correction_over<Dim>(gap, gap + travel, radius, other_radius,
                                                         settings, shell_gap);
    };
    double rate = gap_rate;
    if (inverse_mass > 0.0 && gap_rate != 0.0) {
        // Newton on r − ḣ0 + K [G(h0 + step r) − G(h0)] = 0 (slope 1 + K step c_corr), each
        // iterate kept inside the bracket [lo, hi] of the root (bisection when it leaves it).
        double lo = std::min(0.0, gap_rate);
        double hi = std::max(0.0, gap_rate);
        rate = gap_rate / (1.0 + resistance(gap).normal * step * inverse_mass);
        for (int iteration = 0; iteration < 200; ++iteration) {
            const double end = gap + step * rate;
            const double residual = rate - gap_rate + inverse_mass * between(rate).normal;
            if (std::abs(residual) <= 1e-13 * std::abs(gap_rate)) {
                break;
            }
            (residual > 0.0 ? hi : lo) = rate;
            // Newton's step, or bisection where it leaves the bracket (at a joint of c_corr:
            // its slope is one-sided there, and the root may lie on the other side).
            double next = rate - residual / (1.0 + inverse_mass * step * resistance(end).normal);
            if (!(next > lo && next < hi)) {
                next = 0.5 * (lo + hi);
            }
            if (next == lo || next == hi) {
                break; // the bracket is two neighbouring doubles: `rate` is the root
            }
            rate = next;
        }
    }
    const double travel = step * rate;
    const LubricationResistance mean = lubrication_correction_over<Dim>(
        gap, gap + travel, radius, other_radius, settings, shell_gap);
    // Where the film takes most of the rate, the impulse is the rate's change over K (the same
    // to the solve's round-off, and the body's rate then never crosses zero); else the
    // integral, which the rate's change would give to fewer digits.
    const bool is_stiff =
        inverse_mass > 0.0 && std::abs(rate - gap_rate) > 0.5 * std::abs(gap_rate);
    const double impulse = is_stiff ? (rate - gap_rate) / inverse_mass : -travel * mean.normal;
    const double tangential = mean.tangential;
    return {rate, impulse, tangential};
}

template LubricationResistance lubrication_resistance<2>(double, double, double, double);
template LubricationResistance lubrication_resistance<3>(double, double, double, double);
template LubricationResistance lubrication_correction<2>(double, double, double,
                                                         const LubricationSettings&, double);
template LubricationResistance lubrication_correction<3>(double, double, double,
                                                         const LubricationSettings&, double);
template LubricationResistance
lubrication_correction_integral<2>(double, double, double, const LubricationSettings&, double);
template LubricationResistance
lubrication_correction_integral<3>(double, double, double, const LubricationSettings&, double);
template LubricationResistance lubrication_correction_over<2>(double, double, double, double,
                                                              const LubricationSettings&, double);
template LubricationResistance lubrication_correction_over<3>(double, double, double, double,
                                                              const LubricationSettings&, double);
template FilmStep film_step<2>(double, double, double, double, double, double,
                               const LubricationSettings&, double);
template FilmStep film_step<3>(double, double, double, double, double, double,
                               const LubricationSettings&, double);

} // namespace fddem
