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

LubricationResistance spheres(double gap, double radius, double other_radius, double viscosity)
{
    const double scale = 6.0 * pi * viscosity * radius; // 6πμ a1
    if (std::isinf(other_radius)) {
        // A plane wall (Cox & Brenner 1967; Goldman, Cox & Brenner 1967).
        const double xi = gap / radius;
        return {scale * (1.0 / xi + 0.2 * log_inverse(xi)), scale * (8.0 / 15.0) * log_inverse(xi)};
    }
    // Two spheres (Jeffrey 1982; Jeffrey & Onishi 1984), β = a2/a1, ξ = 2h/(a1 + a2).
    const double beta = other_radius / radius;
    const double cube = (1.0 + beta) * (1.0 + beta) * (1.0 + beta);
    const double xi = 2.0 * gap / (radius + other_radius);
    const double g1 = 2.0 * beta * beta / cube;
    const double g2 = beta * (1.0 + 7.0 * beta + beta * beta) / (5.0 * cube);
    const double gt = 4.0 * beta * (2.0 + beta + 2.0 * beta * beta) / (15.0 * cube);
    return {scale * (g1 / xi + g2 * log_inverse(xi)), scale * gt * log_inverse(xi)};
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

template LubricationResistance lubrication_resistance<2>(double, double, double, double);
template LubricationResistance lubrication_resistance<3>(double, double, double, double);
template LubricationResistance lubrication_correction<2>(double, double, double,
                                                         const LubricationSettings&, double);
template LubricationResistance lubrication_correction<3>(double, double, double,
                                                         const LubricationSettings&, double);

} // namespace fddem
