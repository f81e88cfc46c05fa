// SPDX-License-Identifier: MIT
#include "fddem/io/nondimensional.hpp"

#include <cmath>

namespace fddem {

double happel_brenner_wall_factor(double width_ratio)
{
    const double w2 = width_ratio * width_ratio;
    const double w4 = w2 * w2;
    const double w6 = w4 * w2;
    const double w8 = w4 * w4;
    return 1.0 /
           (std::log(width_ratio) - 0.9157 + 1.7244 / w2 - 1.7302 / w4 + 2.4056 / w6 - 4.5913 / w8);
}

DerivedScales derive_scales(double reynolds, double density_ratio, double width_ratio,
                            double fluid_density, double diameter, double velocity)
{
    DerivedScales s{};
    s.wall_factor = happel_brenner_wall_factor(width_ratio);
    s.viscosity = fluid_density * velocity * diameter / reynolds;
    s.body_density = density_ratio * fluid_density;
    // eq. (21) solved for g; with ρf = D = U_c = 1 this is eq. (22)'s Fr = 16K/((ρr − 1) Re).
    s.gravity = 16.0 * s.wall_factor * s.viscosity * velocity /
                (diameter * diameter * (s.body_density - fluid_density));
    return s;
}

} // namespace fddem
