// SPDX-License-Identifier: MIT
#pragma once
/// Surface material of a body or of the walls, and the constants of one contact pair built from
/// two of them. Pure data and pure functions.
///
/// Pair rules:
///   m* = 1/(1/m_i + 1/m_j),  R* = 1/(1/R_i + 1/R_j),  J* = 1/(1/J_i + 1/J_j)
///     (a wall, a fixed or a prescribed body counts as infinite mass and inertia; a wall has
///     1/R = 0);
///   1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j,  1/G* = (2 − ν_i)/G_i + (2 − ν_j)/G_j,
///     G = E/(2(1 + ν))  (Hertz 1882 and Mindlin 1949, as written in Johnson 1985, chs. 4
///     and 7);
///   μ_s, μ_r and e of the pair: the geometric mean of the two surfaces' values. fddem's choice:
///     it is symmetric, returns the common value for equal materials, and a frictionless
///     (μ = 0) or perfectly plastic surface makes the pair so, whatever the other surface.

#include "fddem/bodies/material.hpp"

namespace fddem {

/// One side of a contact as the pair rules need it. Inverse quantities, so that a wall or an
/// immovable body is exactly 0 and no infinity enters the arithmetic.
struct PairSide {
    double inverse_mass = 0.0;    ///< 1/m [1/kg]; 0: immovable (wall, fixed, prescribed)
    double inverse_inertia = 0.0; ///< 1/J [1/(kg·m²)]; 0: immovable
    double curvature = 0.0;       ///< 1/R [1/m]; 0: a plane wall
    Material material;
};

/// The constants of one contact, from the two sides (at least one movable, at least one curved).
struct ContactPair {
    double effective_mass = 0.0;    ///< m* [kg] (2D: per unit depth)
    double effective_radius = 0.0;  ///< R* [m]
    double effective_inertia = 0.0; ///< J* [kg·m²] (2D: per unit depth)
    double young_modulus = 0.0;     ///< E* [Pa]; 0 if either side has no E
    double shear_modulus = 0.0;     ///< G* [Pa]; 0 if either side has no E
    double friction = 0.0;          ///< μ_s
    double rolling_friction = 0.0;  ///< μ_r
    double restitution = 1.0;       ///< e
};

[[nodiscard]] ContactPair make_contact_pair(const PairSide& a, const PairSide& b);

/// A movable ball of mass m [kg], moment of inertia J [kg·m²] and radius R [m].
[[nodiscard]] PairSide ball_side(double mass, double inertia, double radius,
                                 const Material& material, bool is_movable);
/// A plane wall (infinite mass, flat).
[[nodiscard]] PairSide wall_side(const Material& material);

} // namespace fddem
