// SPDX-License-Identifier: MIT
#include "fddem/coupling/markers.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;

/// The volume (2D: area) of the ball of radius r.
template <int Dim>
double ball_volume(double r)
{
    if constexpr (Dim == 2) {
        return pi * r * r;
    } else {
        return 4.0 / 3.0 * pi * r * r * r;
    }
}

/// The volume between the spheres (circles) of radii (i − ½) h and (i + ½) h, in the form the
/// paper's layout has always used (kept for its bits).
template <int Dim>
double middle_shell(int i, double h)
{
    if constexpr (Dim == 2) {
        return pi * h * h * ((i + 0.5) * (i + 0.5) - (i - 0.5) * (i - 0.5));
    } else {
        return 4.0 / 3.0 * pi * h * h * h * (std::pow(i + 0.5, 3) - std::pow(i - 0.5, 3));
    }
}

/// The markers of ring (shell) i at radius i h, sharing `shell_volume` equally: 6i evenly spaced
/// angles in 2D, 8 round(π i²/2) points in 3D (an octant's golden-angle spiral, mirrored).
template <int Dim>
void add_ring(MarkerSet<Dim>& set, int i, double h, double shell_volume)
{
    if constexpr (Dim == 2) {
        const int count = 6 * i;
        for (int k = 0; k < count; ++k) {
            const double phi = 2.0 * pi * k / count;
            set.offsets.push_back(Vec<2>(i * h * std::cos(phi), i * h * std::sin(phi)));
            set.volumes.push_back(shell_volume / count);
        }
    } else {
        // Mirror-symmetric in each axis plane: a golden-angle spiral over one octant of the
        // shell, reflected into the other seven. The centroid is then the centre, and a body
        // in a symmetric flow feels no sideways force from its layout (a whole spiral put
        // the centroid up to 1 % of R off, and a settling sphere drifted sideways).
        const double golden = pi * (3.0 - std::sqrt(5.0));
        const int per_octant = std::max(1, static_cast<int>(std::lround(pi * i * i / 2.0)));
        const double volume = shell_volume / (8.0 * per_octant);
        for (int k = 0; k < per_octant; ++k) {
            const double z = 1.0 - (k + 0.5) / per_octant;
            const double r = std::sqrt(1.0 - z * z);
            const double phi = std::fmod(golden * k, 0.5 * pi) + 0.25 * pi / per_octant;
            const Vec<3> first = i * h * Vec<3>(r * std::cos(phi), r * std::sin(phi), z);
            for (int signs = 0; signs < 8; ++signs) {
                set.offsets.push_back(first.cwiseProduct(Vec<3>((signs & 1) != 0 ? -1.0 : 1.0,
                                                                (signs & 2) != 0 ? -1.0 : 1.0,
                                                                (signs & 4) != 0 ? -1.0 : 1.0)));
                set.volumes.push_back(volume);
            }
        }
    }
}

/// The centre marker and rings 1..n at spacing h, ring i owning ((i − ½) h, (i + ½) h); the last
/// ring's share reaches out to `outer_edge` when it is given (else to (n + ½) h).
template <int Dim>
MarkerSet<Dim> ring_markers(int n_rings, double h, std::optional<double> outer_edge)
{
    if (n_rings < 1) {
        throw InternalError("make_ball_markers: at least one ring");
    }
    MarkerSet<Dim> set;
    set.spacing = h;
    set.offsets.push_back(Vec<Dim>::Zero());
    set.volumes.push_back(ball_volume<Dim>(0.5 * h));
    for (int i = 1; i <= n_rings; ++i) {
        const double shell = i == n_rings && outer_edge
                                 ? ball_volume<Dim>(*outer_edge) - ball_volume<Dim>((i - 0.5) * h)
                                 : middle_shell<Dim>(i, h);
        add_ring<Dim>(set, i, h, shell);
    }
    return set;
}

} // namespace

template <int Dim>
MarkerSet<Dim> make_ball_markers(const Ball<Dim>& ball, int n_rings)
{
    return ring_markers<Dim>(n_rings, ball.radius() / (n_rings + 0.5), std::nullopt);
}

template <int Dim>
MarkerSet<Dim> make_retracted_ball_markers(const Ball<Dim>& ball, int n_rings, double retraction)
{
    if (!(retraction >= 0.0 && retraction < ball.radius())) {
        throw InternalError("make_retracted_ball_markers: retraction outside [0, R)");
    }
    return ring_markers<Dim>(n_rings, (ball.radius() - retraction) / n_rings, ball.radius());
}

template <int Dim>
MarkerSet<Dim> make_surface_ball_markers(const Ball<Dim>& ball, double retraction, double spacing,
                                         double thickness)
{
    const double radius = ball.radius() - retraction;
    if (!(retraction >= 0.0 && radius > 0.0 && spacing > 0.0 && thickness > 0.0)) {
        throw InternalError("make_surface_ball_markers: retraction outside [0, R) or a spacing "
                            "or thickness not positive");
    }
    // Ring i of add_ring at ring spacing h_L = radius / i: 6i markers π h_L/3 apart in 2D,
    // 8 round(π i²/2) in 3D (≈ h_L apart); i from the target spacing.
    const double per_ring = Dim == 2 ? std::numbers::pi / 3.0 : 1.0;
    const int i = std::max(1, static_cast<int>(std::lround(radius * per_ring / spacing)));
    const double area = Dim == 2 ? 2.0 * pi * radius : 4.0 * pi * radius * radius;
    MarkerSet<Dim> set;
    set.spacing = radius / i;
    add_ring<Dim>(set, i, radius / i, area * thickness);
    return set;
}

int rings_for_spacing(double radius, double grid_spacing, double ratio)
{
    return std::max(1, static_cast<int>(std::lround(radius / (ratio * grid_spacing) - 0.5)));
}

int retracted_rings_for_spacing(double radius, double retraction, double grid_spacing, double ratio)
{
    return std::max(1,
                    static_cast<int>(std::lround((radius - retraction) / (ratio * grid_spacing))));
}

template MarkerSet<2> make_ball_markers<2>(const Ball<2>&, int);
template MarkerSet<3> make_ball_markers<3>(const Ball<3>&, int);
template MarkerSet<2> make_retracted_ball_markers<2>(const Ball<2>&, int, double);
template MarkerSet<3> make_retracted_ball_markers<3>(const Ball<3>&, int, double);
template MarkerSet<2> make_surface_ball_markers<2>(const Ball<2>&, double, double, double);
template MarkerSet<3> make_surface_ball_markers<3>(const Ball<3>&, double, double, double);

} // namespace fddem
