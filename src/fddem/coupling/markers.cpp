// SPDX-License-Identifier: MIT
#include "fddem/coupling/markers.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
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
            // Point-symmetric: the spiral covers the upper half of the shell and each of its
            // markers has a twin at −r, so that the centroid is the centre to round-off (a whole
            // spiral put it up to 1 % of R off, and a settling sphere drifted sideways).
            const int pairs = std::max(1, static_cast<int>(std::lround(2.0 * pi * i * i)));
            const double shell =
                4.0 / 3.0 * pi * h * h * h * (std::pow(i + 0.5, 3) - std::pow(i - 0.5, 3));
            for (int k = 0; k < pairs; ++k) {
                const double z = 1.0 - (2.0 * k + 1.0) / (2.0 * pairs);
                const double r = std::sqrt(1.0 - z * z);
                const double phi = golden * k;
                const Vec<3> offset = i * h * Vec<3>(r * std::cos(phi), r * std::sin(phi), z);
                for (const Vec<3>& twin : {offset, Vec<3>(-offset)}) {
                    set.offsets.push_back(twin);
                    set.volumes.push_back(shell / (2.0 * pairs));
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
