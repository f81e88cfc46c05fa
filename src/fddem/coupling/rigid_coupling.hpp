// SPDX-License-Identifier: MIT
#pragma once
/// The fictitious-domain update of one body inside a SIMPLE outer iteration, eqs. (13)–(15),
/// in dimensional form (docs/method.md §2). λ is the pseudo body force per unit mass of fluid
/// on the markers (ρf λ is the force per volume added to the fluid's momentum equation).
///
/// eq. (13): ρs V U^{n+1}/Δt = (ρs − ρf) V (U^n/Δt + g) + ρf Σ_l ΔV_l (u_l/Δt − λ*_l) + F_e
/// eq. (14): J_s·ω^{n+1}/Δt = (J_s − J_f)·ω^n/Δt − ω^n × ((J_s − J_f)·ω^n)
///                            + ρf Σ_l ΔV_l r_l × (u_l/Δt − λ*_l) + M_e
///           with the tensors J (bodies/inertia.hpp; numbers in 2D, where the gyroscopic term
///           is zero; it is zero too for a ball's isotropic J, but not for a later shape)
/// eq. (15): λ_l = λ*_l + (U^{n+1} + ω^{n+1} × r_l − u_l)/Δt
/// with u_l = I(u) at marker l, r_l its offset from the centre, J_s = ρs ∫|r⊥|², and
/// J_f = ρf Σ_l ΔV_l (|r_l|² 1 − r_l r_lᵀ) the fluid inertia *as the markers represent it*, so that
/// at convergence (u_l rigid) eq. (14) is exactly the discrete form of the paper's eq. (5b).
/// Dividing the particle's equation of motion ρs V dU/dt = F_H + (ρs − ρf) V g by it gives the
/// hydrodynamic force for output: F_H = ρs V (U^{n+1} − U^n)/Δt − (ρs − ρf) V g − F_e.
/// F_e, M_e: other forces on the body (contacts, "additive" coupling); zero in the paper.

#include "fddem/bodies/particle.hpp"

#include <span>

namespace fddem {

template <int Dim>
struct RigidVelocity {
    Vec<Dim> velocity;
    AngularVec<Dim> omega;
};

/// The body's level-n motion and the parameters eqs. (13)–(14) need.
template <int Dim>
struct RigidUpdateInput {
    Vec<Dim> velocity_n;              ///< U^n [m/s]
    AngularVec<Dim> omega_n;          ///< ω^n [rad/s]
    double body_density;              ///< ρs [kg/m³]
    double volume;                    ///< V [m³] (2D: m²)
    Inertia<Dim> body_inertia;        ///< J_s, world frame [kg·m²]
    double fluid_density;             ///< ρf [kg/m³]
    Inertia<Dim> fluid_second_moment; ///< J_f/ρf, world frame [m⁵] (2D: m⁴)
    Vec<Dim> gravity;                 ///< g [m/s²]
    double dt;                        ///< Δt [s]
    /// Any other force on the body over the step, e.g. the mean contact force of the DEM
    /// sub-steps (contact.coupling = "additive") [N]; added to the right side of eq. (13).
    Vec<Dim> external_force = Vec<Dim>::Zero();
    AngularVec<Dim> external_torque = zero_angular<Dim>(); ///< likewise for eq. (14) [N·m]
    /// coupling.inner_fluid = "volume" (coupling/inner_fluid.hpp): the fluid inside the body now
    /// and at the step's start, over the cells it covers; eqs. (13')–(14') then take them in place
    /// of the markers' Σ ΔV_l u_l and of the paper's rigid inner fluid ρf V U^n. Null: the paper's.
    const InnerFluid<Dim>* inner_fluid = nullptr;
    const InnerFluid<Dim>* inner_fluid_n = nullptr;
};

/// The right sides of eqs. (13)–(14), as rates: eq. (13) is mass_rate U^{n+1} = impulse_rate,
/// eq. (14) inertia_rate·ω^{n+1} = moment_rate.
template <int Dim>
struct RigidBalance {
    Vec<Dim> impulse_rate;       ///< [N]
    double mass_rate;            ///< ρs V/Δt [kg/s]
    AngularVec<Dim> moment_rate; ///< [N·m]
    Inertia<Dim> inertia_rate;   ///< J_s/Δt [kg·m²/s]
};

/// Both sides of eqs. (13)–(14) of a free body, before they are solved: a body with other
/// implicit terms (the lubrication links, coupling/lubrication_coupling.hpp) adds them.
template <int Dim>
[[nodiscard]] RigidBalance<Dim>
rigid_balance(const RigidUpdateInput<Dim>& in, std::span<const Vec<Dim>> offsets,
              std::span<const double> volumes, std::span<const Vec<Dim>> fluid_at_markers,
              std::span<const Vec<Dim>> lambda_star);

/// eqs. (13)–(14): U^{n+1}, ω^{n+1} of a free body.
template <int Dim>
[[nodiscard]] RigidVelocity<Dim>
rigid_velocity(const RigidUpdateInput<Dim>& in, std::span<const Vec<Dim>> offsets,
               std::span<const double> volumes, std::span<const Vec<Dim>> fluid_at_markers,
               std::span<const Vec<Dim>> lambda_star);

/// eq. (15): λ on every marker; returns the rigid-motion defect max_l |U + ω×r_l − u_l| [m/s].
/// With `gains` (coupling.normalised_forcing: g_l ≥ 1 per component, coupling/forcing_gain.hpp)
/// the correction is divided by them, λ_l = λ*_l + (U + ω×r_l − u_l)/(g_l Δt), so that no slip
/// mode overshoots; empty: the paper's eq. (15).
template <int Dim>
double update_marker_force(const RigidVelocity<Dim>& motion, std::span<const Vec<Dim>> offsets,
                           std::span<const Vec<Dim>> fluid_at_markers,
                           std::span<const Vec<Dim>> lambda_star, double dt,
                           std::span<Vec<Dim>> lambda, std::span<const Vec<Dim>> gains = {});

/// How much the last λ update changed the force on a body, as the velocity change it would
/// give a body of fluid density in one step: Δt (|Σ ΔV_l δλ_l| + 2 |Σ ΔV_l r_l × δλ_l| / r) / V
/// with δλ = λ − λ* (the rotational part taken at the rim, r the radius). The convergence
/// measure of a prescribed or fixed body, whose velocity does not change [m/s].
template <int Dim>
double forcing_change(std::span<const Vec<Dim>> offsets, std::span<const double> volumes,
                      std::span<const Vec<Dim>> lambda, std::span<const Vec<Dim>> lambda_star,
                      double dt, double volume, double radius);

} // namespace fddem
