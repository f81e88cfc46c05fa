// SPDX-License-Identifier: MIT
#pragma once
/// The fluid inside a body, integrated over the cells it covers (coupling.inner_fluid =
/// "volume"; beyond the paper, docs/method.md §4, "The fluid inside a body").
///
/// The paper's eqs. (13)–(14) take the fluid inside a body from the markers that fill it:
/// ρf Σ_l ΔV_l u_l for its momentum now, and ρf V U^n for it at level n (the inner fluid taken
/// as moving rigidly with the body at the step's start). Markers on the surface alone (Uhlmann
/// 2005; Breugem 2012) do not fill the body, so the inner fluid's momentum is taken over the
/// grid instead, as Kempe & Fröhlich (2012, J. Comput. Phys. 231) do:
///
///   eq. (13'): ρs V U^{n+1}/Δt = ρs V U^n/Δt + (ρs − ρf) V g
///                               + ρf (∫_P u dx − ∫_P u^n dx)/Δt − ρf Σ_l ΔV_l λ*_l + F_e
///   eq. (14'): J_s·ω^{n+1}/Δt = J_s·ω^n/Δt − ω^n × (J_s·ω^n)
///                               + ρf (∫_P r × u dx − ∫_P r × u^n dx)/Δt − ρf Σ_l ΔV_l r_l × λ*_l +
///                               M_e
///
/// (the body's equation of motion with F_H = −ρf Σ ΔV λ + ρf d/dt ∫_P u dx, λ* of the pass
/// before), both integrals over the body at X^n, where the step's markers are. Bodies are balls
/// (bodies/ball.hpp): the integrals are over a ball, and with a rigid inner fluid eq. (14')
/// equals the paper's (14) because a ball's fluid inertia is isotropic, ω × (J_f ω) = 0.
///
/// ∫_P f dx ≈ Σ α_f f_f ΔV over the faces f of each velocity component, α_f the fraction of the
/// face's control volume (a cell centred on the face) inside the body. α_f is Kempe & Fröhlich's
/// level-set estimate from the signed distances φ_m = |x_m − X| − R at the control volume's 2^Dim
/// corners: α = Σ_m max(−φ_m, 0) / Σ_m |φ_m| (1 inside, 0 outside, linear across the surface).
/// Written here: it is a few lines, and no Debian library computes it.

#include "fddem/bodies/particle.hpp"
#include "fddem/grid/fields.hpp"

#include <span>

namespace fddem {

/// The fraction of the box [lo, lo + size] inside the ball of `radius` about `centre`, from the
/// signed distances at the box's corners (Kempe & Fröhlich 2012). 1 for a box inside the ball,
/// 0 for one outside it.
template <int Dim>
[[nodiscard]] double ball_volume_fraction(const Vec<Dim>& lo, const Vec<Dim>& size,
                                          const Vec<Dim>& centre, double radius) noexcept;

/// ∫_P u dx and ∫_P r × u dx (r from `centre`) over the ball, from the faces this rank owns:
/// this rank's part of the sum, to be added over the ranks. Along periodic axes the faces are
/// taken with their images, so a body across a periodic side is integrated whole.
template <int Dim>
[[nodiscard]] InnerFluid<Dim> inner_fluid_part(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                                               const Vec<Dim>& centre, double radius);

/// inner_fluid_part of the bodies `members` (positions in `bodies`), summed over the ranks in
/// rank order (one sum for all of them), in the order of `members`. Every rank passes the same
/// members.
template <int Dim>
[[nodiscard]] std::vector<InnerFluid<Dim>>
inner_fluid_of(std::span<const Particle<Dim>> bodies, std::span<const std::size_t> members,
               const MacGrid<Dim>& grid, const FaceField<Dim>& u);

/// inner_fluid_of every free body of `bodies`, into its coupling.*`field` (inner_fluid_n at a
/// step's start, inner_fluid at its end, for the force it reports). Every rank calls it.
template <int Dim>
void take_inner_fluid_of_free_bodies(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                                     const FaceField<Dim>& u,
                                     InnerFluid<Dim> MarkerCoupling<Dim>::*field);

} // namespace fddem
