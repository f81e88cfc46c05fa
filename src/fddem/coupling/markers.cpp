// SPDX-License-Identifier: MIT
#include "fddem/coupling/markers.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fddem {

template <int Dim>
MarkerSet<Dim> make_ball_markers(const Ball<Dim>& ball, int n_rings)
{
    if (n_rings < 1) {
        throw InternalError("make_ball_markers: at least one ring");
    }
    constexpr double pi = std::numbers::pi;
    MarkerSet<Dim> set;
    const double h = ball.radius() / (n_rings + 0.5);
    set.spacing = h;
    set.offsets.push_back(Vec<Dim>::Zero());
    if constexpr (Dim == 2) {
        set.volumes.push_back(pi * 0.25 * h * h);
        for (int i = 1; i <= n_rings; ++i) {
            const int count = 6 * i;
            const double annulus = pi * h * h * ((i + 0.5) * (i + 0.5) - (i - 0.5) * (i - 0.5));
            for (int k = 0; k < count; ++k) {
                const double phi = 2.0 * pi * k / count;
                set.offsets.push_back(Vec<2>(i * h * std::cos(phi), i * h * std::sin(phi)));
                set.volumes.push_back(annulus / count);
            }
        }
    } else {
        set.volumes.push_back(4.0 / 3.0 * pi * std::pow(0.5 * h, 3));
        const double golden = pi * (3.0 - std::sqrt(5.0));
        for (int i = 1; i <= n_rings; ++i) {
            // Mirror-symmetric in each axis plane: a golden-angle spiral over one octant of the
            // shell, reflected into the other seven. The centroid is then the centre, and a body
            // in a symmetric flow feels no sideways force from its layout (a whole spiral put
            // the centroid up to 1 % of R off, and a settling sphere drifted sideways).
            const int per_octant = std::max(1, static_cast<int>(std::lround(pi * i * i / 2.0)));
            const double shell =
                4.0 / 3.0 * pi * h * h * h * (std::pow(i + 0.5, 3) - std::pow(i - 0.5, 3));
            const double volume = shell / (8.0 * per_octant);
            for (int k = 0; k < per_octant; ++k) {
                const double z = 1.0 - (k + 0.5) / per_octant;
                const double r = std::sqrt(1.0 - z * z);
                const double phi = std::fmod(golden * k, 0.5 * pi) + 0.25 * pi / per_octant;
                const Vec<3> first = i * h * Vec<3>(r * std::cos(phi), r * std::sin(phi), z);
                for (int signs = 0; signs < 8; ++signs) {
                    set.offsets.push_back(first.cwiseProduct(
                        Vec<3>((signs & 1) != 0 ? -1.0 : 1.0, (signs & 2) != 0 ? -1.0 : 1.0,
                               (signs & 4) != 0 ? -1.0 : 1.0)));
                    set.volumes.push_back(volume);
                }
            }
        }
    }
    return set;
}

int rings_for_spacing(double radius, double grid_spacing, double ratio)
{
    return std::max(1, static_cast<int>(std::lround(radius / (ratio * grid_spacing) - 0.5)));
}

template MarkerSet<2> make_ball_markers<2>(const Ball<2>&, int);
template MarkerSet<3> make_ball_markers<3>(const Ball<3>&, int);

} // namespace fddem
