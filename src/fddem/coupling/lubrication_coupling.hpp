// SPDX-License-Identifier: MIT
#pragma once
/// The lubrication correction inside eqs. (13)–(14) (lubrication.coupling = "implicit"; issue 16,
/// docs/method.md §5, "Implicit coupling"). fddem's, beyond the paper.
///
/// A gap j of body i (a LubricationLink, fixed at the step's start, its resistance the
/// correction averaged over the travel of the start velocities) exerts the linear damping force
/// of contact/lubrication.hpp on the relative surface velocity at the gap:
///   F_j = −C_j (U_i + ω_i × l_j − S_j),   C_j = c_n n nᵀ + c_t (1 − n nᵀ),
///   M_j = l_j × F_j,
/// with l_j the lever from i's centre to the gap, n the unit normal toward the partner and S_j
/// the partner's surface velocity there (U_k + ω_k × l'_j for a body k, the wall's velocity for
/// a wall). Taken implicitly in the body's own U_i and ω_i, eq. (13) becomes
///   (ρs V/Δt 1 + Σ C_j) U^{n+1} = [right side of (13)] + Σ C_j (S_j − ω_i × l_j)
/// and eq. (14)
///   (J_s/Δt + Σ K_j) ω^{n+1} = [right side of (14)] + Σ l_j × C_j (S_j − U_i),
/// K_j = c_t (|l_j|² 1 − l_j l_jᵀ) (c_t |l_j|² in 2D), the part of −l_j × C_j (ω × l_j) that is
/// linear in ω (the normal part gives none: ω × l_j is normal to n). The bodies the links join
/// (a group, linked_groups) have their eqs. (13) solved together (coupled_velocities), so the
/// partner's U_k is implicit too; then each one's eq. (14) with the group's new velocities. What
/// stays at its latest value, for the outer iterations to converge: the ω in eq. (13), the
/// partners' ω in eq. (14), and S_j of a partner outside the group (a wall, a fixed, prescribed
/// or DEM-moved body).
///
/// Why implicit: the film's c_n grows as 1/h (3D) or h^(−3/2) (2D) and soon exceeds m/Δt.
/// Added explicitly, the force overshoots once c Δt > m; implicit, the body's relative velocity
/// is damped by m/(m + c Δt) per step, never reversed. In eqs. (13)–(14) it acts with the
/// resolved fluid (its added mass included) instead of against the body's mass alone in the
/// DEM sub-steps, where the lagged fluid force of a light body grows (docs/method.md §5).

#include "fddem/bodies/particle.hpp"
#include "fddem/coupling/rigid_coupling.hpp"

#include <span>
#include <vector>

namespace fddem {

/// The links' force and moment on a body as affine functions of its own motion:
/// F = −force_rate U + force_target, M = −moment_rate ω + moment_target.
template <int Dim>
struct LinkedDamping {
    Matrix<Dim> force_rate = Matrix<Dim>::Zero();           ///< Σ C_j [N·s/m]
    Vec<Dim> force_target = Vec<Dim>::Zero();               ///< [N]
    Inertia<Dim> moment_rate = isotropic_inertia<Dim>(0.0); ///< Σ K_j [N·m·s]
    AngularVec<Dim> moment_target = zero_angular<Dim>();    ///< [N·m]
};

/// C_j of one gap: c_n n nᵀ + c_t (1 − n nᵀ).
template <int Dim>
[[nodiscard]] Matrix<Dim> gap_resistance(const Vec<Dim>& normal, const LubricationResistance& c);

/// The partner's surface velocity at the gap, S_j.
template <int Dim>
[[nodiscard]] Vec<Dim> partner_surface_velocity(const LubricationLink<Dim>& link,
                                                std::span<const Particle<Dim>> bodies);

/// Σ over `links` of a body moving at `velocity`, `omega` (the latest values; each equation
/// takes only its own unknown implicitly), with its partners in `bodies` as they are now.
template <int Dim>
[[nodiscard]] LinkedDamping<Dim>
linked_damping(std::span<const LubricationLink<Dim>> links, const Vec<Dim>& velocity,
               const AngularVec<Dim>& omega, std::span<const Particle<Dim>> bodies);

/// The force and moment the links exert on a body at `velocity`, `omega`: Σ F_j, Σ l_j × F_j.
template <int Dim>
struct LinkedForce {
    Vec<Dim> force = Vec<Dim>::Zero();
    AngularVec<Dim> moment = zero_angular<Dim>();
};
template <int Dim>
[[nodiscard]] LinkedForce<Dim> linked_force(std::span<const LubricationLink<Dim>> links,
                                            const Vec<Dim>& velocity, const AngularVec<Dim>& omega,
                                            std::span<const Particle<Dim>> bodies);

/// Eq. (13) of the bodies `members` (indices into `bodies`; those the links join, each moved by
/// eqs. (13)–(14)) solved together with the links' damping on their left sides:
///   (ρs V/Δt)_m U_m + Σ_j C_j (U_m − U_p(j)) = impulse_rate_m + Σ_j C_j (ω_p × l'_j − ω_m × l_j)
/// for a partner p among the members, the partner's surface velocity S_j on the right for any
/// other (a wall, a fixed, prescribed or DEM-moved body). The pair terms are equal and opposite,
/// so the links keep the members' momentum exactly; the system is symmetric positive definite
/// (Eigen's sparse LDLᵀ). ω on the right is each body's latest. Returns U^{n+1} per member.
template <int Dim>
[[nodiscard]] std::vector<Vec<Dim>> coupled_velocities(std::span<const Particle<Dim>> bodies,
                                                       std::span<const std::size_t> members,
                                                       std::span<const RigidBalance<Dim>> balances);

/// The bodies that lubrication links join, among the free ones eqs. (13)–(14) move: each group
/// (in store order) is updated together (coupled_velocities); a body with links to walls or to
/// bodies that are not moved so (fixed, prescribed, in the DEM's hands) alone is a group of one.
/// Bodies without links are in no group.
struct LinkedGroups {
    explicit LinkedGroups(std::size_t n_bodies) : group_of(n_bodies, -1) {}
    std::vector<std::vector<std::size_t>> groups;
    std::vector<int> group_of; ///< per body: its group, or −1

    [[nodiscard]] bool is_linked(std::size_t body) const { return group_of[body] >= 0; }
    /// The group whose first member is `body`, or null.
    [[nodiscard]] const std::vector<std::size_t>* group_starting_at(std::size_t body) const
    {
        const int g = group_of[body];
        return g >= 0 && groups[static_cast<std::size_t>(g)].front() == body
                   ? &groups[static_cast<std::size_t>(g)]
                   : nullptr;
    }
};

template <int Dim>
[[nodiscard]] LinkedGroups linked_groups(std::span<const Particle<Dim>> bodies,
                                         bool is_paper_contact);

/// After the DEM sub-steps: a free body eqs. (13)–(14) move (`is_paper_contact`: the paper's
/// contact coupling, which hands a body in contact to the DEM) loses the sub-steps' lubrication
/// from its mean force and torque; its links take their place in eqs. (13)–(14).
template <int Dim>
void drop_substep_lubrication(std::span<Particle<Dim>> bodies, bool is_paper_contact);

/// After the outer iterations: the links' force and moment on each such body at its new motion
/// (and its partners'), as its lubrication force and torque and added to its mean force and
/// torque, which the outputs split into contact and lubrication.
template <int Dim>
void record_linked_lubrication(std::span<Particle<Dim>> bodies, bool is_paper_contact);

} // namespace fddem
