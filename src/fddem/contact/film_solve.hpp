// SPDX-License-Identifier: MIT
#pragma once
/// The lubrication films of one DEM sub-step solved together (lubrication.film_solve = "joint";
/// docs/method.md §5, "The films solved together").
///
/// The sweep (film_step, pair by pair in the neighbour list's order) applies each film's
/// backward-Euler impulse on the velocities the films before it left: a Gauss–Seidel pass whose
/// result depends on the order of the pairs, so that a rank holding only some of them cannot
/// reproduce it. A Jacobi pass is order-free but unstable: in the stiff limit each film alone
/// cancels its pair's approach, and a body between two films gets both (docs/parallel.md).
///
/// Here every film's impulse is taken at the velocities all of them leave together. The normal
/// part is film_step's equation for every gap k at once,
///
///   M (v − v*) = Σ_k B_kᵀ J_k,   J_k = G_k(h_k) − G_k(h_k + Δt_i r_k),   r_k = ḣ*_k + B_k (v −
///   v*),
///
/// with v the free bodies' velocities, v* those before the films, B_k the gap rate's row (+nᵀ on
/// the second body, −nᵀ on the first), G_k the correction's integral over the gap
/// (lubrication_correction_integral) and J_k the impulse on the second body along n. It is the
/// stationarity condition of
///
///   Φ(v) = ½ (v − v*)ᵀ M (v − v*) + Σ_k [Γ_k(h_k + Δt_i r_k) − G_k(h_k) Δt_i r_k] / Δt_i,   Γ_k' =
///   G_k,
///
/// which is strictly convex (c_corr = G' ≥ 0): the root is unique, whatever the order of the
/// films, and is found by Newton's method with a line search on Φ along the Newton direction
/// (its slope dᵀ∇Φ grows monotonically along it, so the search is a bracketed root of one
/// variable and needs only G). The gaps are solved in components, each the gaps joined by the
/// free bodies they share; a component of one gap is the sweep's own step (film_step and
/// damping_impulse, the same bits), since nothing else acts on its bodies. The slip of each film is
/// then damped by backward Euler with film_step's mean tangential resistance c̄_t over its
/// travel, all films at once: a linear system in the free bodies' velocities and angular
/// velocities, (M + Δt_i Σ_k c̄_t,k C_kᵀ C_k) Δw = −Δt_i Σ_k c̄_t,k C_kᵀ s_k, with C_k the slip's
/// Jacobian (the tangential projection of the contact points' relative velocity) and s_k the
/// slip after the normal impulses; for one film, the sweep's damping_impulse.
///
/// Stability, whatever the stiffness: M (v − v*) = −Σ_k B_kᵀ [G_k(h1) − G_k(h0)], and each bracket
/// has the sign of its rate r_k (G is non-decreasing), so vᵀM(v − v*) ≤ 0 and |v|_M ≤ |v*|_M
/// with the walls and the bodies that are not free at rest: the films never add kinetic energy,
/// and a body between two stiff films is stopped, not reversed (the slip's step is backward Euler
/// with a positive semi-definite damping, the same).

#include "fddem/contact/contact_geometry.hpp"
#include "fddem/contact/lubrication.hpp"
#include "fddem/core/vec.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace fddem {

/// A body as the films see it.
template <int Dim>
struct FilmBody {
    double mass = 1.0;    ///< [kg] (2D: per unit length)
    double inertia = 1.0; ///< about its centre (a ball's: scalar) [kg m²] (2D: per unit length)
    bool is_free = true;  ///< false: fixed or prescribed, its velocity kept
};

/// One gap the films may act on: a pair of bodies or a body and a wall, its geometry at the
/// sub-step's state (the velocities before the films).
template <int Dim>
struct FilmGap {
    static constexpr std::size_t wall = std::numeric_limits<std::size_t>::max();

    std::size_t first = 0;         ///< a body's index
    std::size_t second = wall;     ///< a body's index, or `wall`
    ContactGeometry<Dim> geometry; ///< normal first → second, rates of second − first
    double first_radius = 0.0;     ///< [m]
    double second_radius = 0.0;    ///< [m]; +∞ for a wall
    double shell_gap = 0.0;        ///< the pair's outermost_shell_depth sum [m]
};

/// Outcome of the joint step. The free bodies' new velocities are the solve's, not the sum of
/// the impulses over the masses: in the stiff limit a gap's rate is a small difference of the
/// velocities, which the solve gives to its tolerance and the impulses (c̄ Δt_i times that rate)
/// would give only to c̄ Δt_i K times less (film_step does the same with its `is_stiff`). The two
/// agree to the solve's tolerance, so momentum is kept to it (about 1e-13 of the rates).
template <int Dim>
struct JointFilms {
    /// the impulse on each gap's second body at its contact point [N·s] (the first body gets its
    /// opposite): what the bodies' forces report; zero for a gap the film does not reach
    std::vector<Vec<Dim>> on_second;
    std::vector<Vec<Dim>> velocity_change;     ///< per body [m/s]; zero if not free
    std::vector<AngularVec<Dim>> omega_change; ///< per body [1/s]; zero if not free
    int n_newton_iterations = 0;
    /// solves of the widening's last pass that stopped at an iteration limit before their
    /// tolerance (Newton's for the normal part, conjugate gradients' for the slips) or met a
    /// NaN (a factorised slip solve only that); the last iterate is used
    int n_unfinished = 0;
};

/// One gap's film over a sub-step `step` [s] as if it alone acted (the sweep's step, dem_step.cpp's
/// damp): the impulse on the second body at the contact point [N·s] (film_step along the normal,
/// damping_impulse across it), or none if the film does not act (out of the range now and after
/// the drift, or a zero correction). `first` and `second` null: a wall.
template <int Dim>
[[nodiscard]] std::optional<Vec<Dim>>
lone_film_impulse(const FilmGap<Dim>& gap, const FilmBody<Dim>* first, const FilmBody<Dim>* second,
                  double step, const LubricationSettings& settings);

/// The films' impulses over one sub-step `step` [s], all gaps together (above). A gap is in the
/// solve if its correction is not zero over its travel, at the velocities before the films or
/// after them; the set is widened until it stops changing.
template <int Dim>
[[nodiscard]] JointFilms<Dim> joint_film_impulses(std::span<const FilmBody<Dim>> bodies,
                                                  std::span<const FilmGap<Dim>> gaps, double step,
                                                  const LubricationSettings& settings);

} // namespace fddem
