// SPDX-License-Identifier: MIT
#pragma once
/// The surface material of a body or of the walls: what its contacts need (contact/material.hpp
/// holds the rules that combine two of them into the constants of one contact pair).

namespace fddem {

struct Material {
    double young_modulus = 0.0;    ///< E [Pa] (2D: see docs/method.md); 0: not given
    double poisson_ratio = 0.0;    ///< ν
    double friction = 0.0;         ///< sliding friction coefficient μ_s
    double rolling_friction = 0.0; ///< rolling friction coefficient μ_r
    double restitution = 1.0;      ///< normal restitution coefficient e
};

} // namespace fddem
