// SPDX-License-Identifier: MIT
#pragma once
/// Friction and rolling resistance of one contact, the same for every contact model (the model
/// gives F_n, k_t and c_t: contact_model.hpp). Beyond the paper, which is frictionless.
///
/// Tangential spring with Coulomb limit (Cundall & Strack 1979; the form of e.g. Luding 2008):
///   ξ ← ξ rotated into the current tangent plane (length kept), then ξ ← ξ + v_t Δt_i;
///   F_t = −k_t ξ − c_t v_t   (on the second body; v_t its slip relative to the first);
///   if |F_t| > μ_s max(F_n, 0): sliding, F_t ← μ_s max(F_n, 0) F_t/|F_t| and ξ ← −F_t/k_t,
///   so that the spring alone carries the Coulomb force when the contact sticks again.
/// ξ is the elastic tangential displacement of the contact, kept per contact across sub-steps
/// and time steps (contact_history.hpp).
///
/// Rolling resistance, constant directional torque (CDT; Zhou et al. 1999, model A of Ai et al.
/// 2011):
///   M_r = −μ_r R* max(F_n, 0) ω_r/|ω_r|   on the first body (+M_r on the second),
/// with ω_r = ω_first − ω_second projected on the tangent plane (in 2D: all of it). The torque
/// has a constant magnitude while the bodies roll on each other and opposes the relative
/// rolling. fddem's regularisation: |M_r| is at most J* |ω_r| / Δt_i, the torque that stops the
/// relative rolling within one sub-step, so that the torque does not flip sign from sub-step to
/// sub-step once the rolling has stopped (there M_r acts as a viscous damper that holds it).
/// Limits of that damper (docs/method.md §6, "Contacts in 3D"): a sustained rolling load M below
/// μ_r R* F_n is not held exactly but creeps at |ω_r| = M Δt_i / J*, and the dampers of a ball's
/// several contacts add up and can overshoot; a pile keeps moving at about 1e-5 m/s.

#include "fddem/contact/contact_model.hpp"
#include "fddem/core/vec.hpp"

namespace fddem {

/// F_t on the second body [N]; updates the elastic tangential displacement ξ [m]. `step` is the
/// time over which the slip acts, Δt_i (0: re-evaluate without moving the spring).
template <int Dim>
[[nodiscard]] Vec<Dim> tangential_force(const Vec<Dim>& normal, const Vec<Dim>& slip_velocity,
                                        const ContactLaw& law, double friction, double step,
                                        Vec<Dim>& displacement);

/// M_r on the first body [N·m] for the relative angular velocity ω_first − ω_second [rad/s];
/// `step` = Δt_i > 0 bounds it (see the file comment).
template <int Dim>
[[nodiscard]] AngularVec<Dim> rolling_torque(const AngularVec<Dim>& relative_omega,
                                             const Vec<Dim>& normal, double normal_force,
                                             const ContactPair& pair, double step);

} // namespace fddem
