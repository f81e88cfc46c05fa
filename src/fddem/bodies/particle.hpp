// SPDX-License-Identifier: MIT
#pragma once
/// One rigid particle, the one record of everything fddem knows about it: who it is (a stable
/// id), its shape and material, the state eqs. (13)–(14) and (17) advance, its Lagrangian markers
/// with λ (eqs. (15)–(16)), and what the DEM sub-steps of the current step did to it (eq. (18)).
/// Every stage of the time step reads and writes this record in place: there are no parallel
/// arrays to keep in step.

#include "fddem/bodies/ball.hpp"
#include "fddem/bodies/inertia.hpp"
#include "fddem/bodies/marker_set.hpp"
#include "fddem/bodies/material.hpp"
#include "fddem/bodies/orientation.hpp"
#include "fddem/contact/lubrication_link.hpp"
#include "fddem/core/vec.hpp"

#include <optional>
#include <vector>

namespace fddem {

/// How a body moves: by the fluid and gravity (free), at a given velocity (prescribed, e.g. a
/// towed disk), or not at all (fixed).
enum class Motion { free, prescribed, fixed };

/// The fluid's momentum and angular momentum (about the centre) inside a body, divided by ρf:
/// ∫_P u dx [m⁴/s] and ∫_P r × u dx [m⁵/s] (2D: per unit depth), from the cells' volume
/// fractions (coupling.inner_fluid = "volume", coupling/inner_fluid.hpp).
template <int Dim>
struct InnerFluid {
    Vec<Dim> momentum = Vec<Dim>::Zero();
    AngularVec<Dim> moment = zero_angular<Dim>();
};

/// The fictitious-domain coupling of one body (paper §2.2–2.3): its markers and λ.
template <int Dim>
struct MarkerCoupling {
    MarkerSet<Dim> markers;            ///< body frame
    std::vector<Vec<Dim>> offsets;     ///< r_l in the world frame (rotated) [m]
    std::vector<Vec<Dim>> positions;   ///< X_l = centre + r_l [m]
    std::vector<Vec<Dim>> fluid;       ///< I(u) at the markers [m/s]
    std::vector<Vec<Dim>> lambda;      ///< λ [m/s²]
    std::vector<Vec<Dim>> lambda_star; ///< λ* [m/s²]
    /// Σ ΔV_l (|r_l|² 1 − r_l r_lᵀ) of the markers, body frame, and (set where the markers are
    /// placed) world frame: the fluid inertia the markers represent, divided by ρf [m⁵]
    /// (2D: Σ ΔV_l |r_l|² [m⁴]).
    Inertia<Dim> body_second_moment = isotropic_inertia<Dim>(0.0);
    Inertia<Dim> fluid_second_moment = isotropic_inertia<Dim>(0.0);
    double forcing_change = 0.0; ///< of the last λ update (rigid_coupling.hpp) [m/s]
    /// Per marker and component, max(1, r_m) with r_m the forcing operator's row sum
    /// (coupling.normalised_forcing; coupling/forcing_gain.hpp): eq. (15)'s correction is
    /// divided by it. Empty without the option (the paper's eq. (15)).
    std::vector<Vec<Dim>> gains;
    /// The outermost marker's distance from the centre, max |r_l| [m]: every marker lies within
    /// it (which ranks hold some of the markers: coupling/marker_routes.hpp).
    double reach = 0.0;
    /// With coupling.inner_fluid = "volume" (else unused): the fluid inside the body at the
    /// step's start (u^n over the body at X^n) and at the latest u of the step (eqs. (13)–(14)).
    InnerFluid<Dim> inner_fluid_n;
    InnerFluid<Dim> inner_fluid;

    /// Whether the per-marker arrays (offsets … lambda_star) are held: always, except on a rank
    /// of a split grid that neither owns the body nor holds any of its markers (release_arrays;
    /// coupling/marker_placement.hpp).
    [[nodiscard]] bool has_arrays() const noexcept { return positions.size() == markers.size(); }
    /// Sizes the per-marker arrays to the markers again, I(u), λ and λ* zero, if released.
    void allocate_arrays()
    {
        if (has_arrays()) {
            return;
        }
        const std::size_t n = markers.size();
        offsets.assign(n, Vec<Dim>::Zero());
        positions.assign(n, Vec<Dim>::Zero());
        fluid.assign(n, Vec<Dim>::Zero());
        lambda.assign(n, Vec<Dim>::Zero());
        lambda_star.assign(n, Vec<Dim>::Zero());
    }
    /// Frees the per-marker arrays (and the gains): their memory is then not held on a rank
    /// that does not read them.
    void release_arrays()
    {
        for (auto* values : {&offsets, &positions, &fluid, &lambda, &lambda_star, &gains}) {
            values->clear();
            values->shrink_to_fit();
        }
    }

    MarkerCoupling() = default;
    explicit MarkerCoupling(MarkerSet<Dim> set)
        : markers(std::move(set)), offsets(markers.size()), positions(markers.size()),
          fluid(markers.size()), lambda(markers.size(), Vec<Dim>::Zero()),
          lambda_star(markers.size(), Vec<Dim>::Zero()),
          body_second_moment(second_moment_tensor<Dim>(markers.offsets, markers.volumes)),
          fluid_second_moment(body_second_moment), reach(markers.outermost_radius())
    {
    }
};

/// The DEM sub-steps of one time step (eq. (18), contact/dem_step.hpp): what the step holds on
/// the body, and what the sub-steps did to it. The DEM advances centre, velocity and omega
/// here, from the body's own state at the step's start, which it leaves as it was.
template <int Dim>
struct ContactState {
    Vec<Dim> steady_force = Vec<Dim>::Zero(); ///< held over the step: the buoyant weight [N]
    AngularVec<Dim> steady_torque = zero_angular<Dim>(); ///< [N·m]
    /// The resolved fluid force held over the sub-steps in which the body touches nothing
    /// (contact.fluid_force = "held", or "auto" with lubrication on), or over all of them
    /// ("always"); zero otherwise [N].
    Vec<Dim> held_fluid_force = Vec<Dim>::Zero();
    AngularVec<Dim> held_fluid_torque = zero_angular<Dim>(); ///< [N·m]
    Vec<Dim> centre = Vec<Dim>::Zero();                      ///< at the end of the sub-steps [m]
    Vec<Dim> velocity = Vec<Dim>::Zero();                    ///< [m/s]
    AngularVec<Dim> omega = zero_angular<Dim>();             ///< [rad/s]
    Vec<Dim> mean_force = Vec<Dim>::Zero();                  ///< contact impulse / Δt [N]
    AngularVec<Dim> mean_torque = zero_angular<Dim>();       ///< [N·m]
    /// The lubrication part of mean_force and mean_torque (outputs show the two apart).
    Vec<Dim> lubrication_force = Vec<Dim>::Zero();
    AngularVec<Dim> lubrication_torque = zero_angular<Dim>(); ///< [N·m]
    /// The body's gaps within the lubrication range at the step's start, or carried into it by
    /// the start velocities within the step, with the correction averaged over that travel, for
    /// the implicit coupling (lubrication.coupling = "implicit"); empty otherwise.
    std::vector<LubricationLink<Dim>> lubrication_links;
    /// touched something, or came within the margin (or left a collision within the lubrication
    /// range, lubrication.coupling "implicit") this step
    bool is_in_contact = false;
};

template <int Dim>
struct Particle {
    int id = 0; ///< stable for the whole run (and across ranks and restarts)
    Ball<Dim> shape{1.0};
    double density = 1.0; ///< ρs [kg/m³]
    Motion motion = Motion::free;
    /// A prescribed body becomes free from this time on [s] (bodies.release_time; the
    /// simulation releases it at the start of a step: release_due()).
    std::optional<double> release_time;
    Material material{}; ///< its surface, for contacts

    Vec<Dim> centre = Vec<Dim>::Zero();             ///< [m]
    Orientation<Dim> orientation = unturned<Dim>(); ///< θ about z (2D), q (3D)
    Vec<Dim> velocity = Vec<Dim>::Zero();           ///< U [m/s]
    AngularVec<Dim> omega = zero_angular<Dim>();    ///< ω [rad/s]
    Vec<Dim> force = Vec<Dim>::Zero(); ///< hydrodynamic force of the last step [N] (2D: N/m)
    AngularVec<Dim> torque = zero_angular<Dim>();  ///< hydrodynamic torque of the last step [N·m]
    Vec<Dim> velocity_n = Vec<Dim>::Zero();        ///< U^n, the level the step started from
    AngularVec<Dim> omega_n = zero_angular<Dim>(); ///< ω^n
    Vec<Dim> velocity_nm1 = Vec<Dim>::Zero();      ///< U^{n−1} (time.scheme = "bdf2")
    AngularVec<Dim> omega_nm1 = zero_angular<Dim>(); ///< ω^{n−1}

    MarkerCoupling<Dim> coupling;
    ContactState<Dim> contact;

    [[nodiscard]] double radius() const noexcept { return shape.radius(); }
    [[nodiscard]] double volume() const noexcept { return shape.volume(); }
    [[nodiscard]] double mass() const noexcept { return density * shape.volume(); }
    /// Moment of inertia about any axis through the centre [kg·m²] (2D: per unit depth), the
    /// scalar the DEM uses: a ball's inertia is isotropic.
    [[nodiscard]] double inertia() const noexcept { return density * shape.second_moment(); }
    /// The inertia tensor J_s in the world frame, as eq. (14) takes it [kg·m²].
    [[nodiscard]] Inertia<Dim> inertia_tensor() const
    {
        return inertia_in_world<Dim>(orientation, isotropic_inertia<Dim>(inertia()));
    }
    /// Moved by the fluid and by contacts; a fixed or prescribed body is not.
    [[nodiscard]] bool is_free() const noexcept { return motion == Motion::free; }
    /// Free now, or prescribed until its release: collisions must be set up for it.
    [[nodiscard]] bool moves_freely() const noexcept
    {
        return is_free() || (motion == Motion::prescribed && release_time);
    }
    /// A prescribed body whose release time has come at `time` [s]. `tolerance` [s] absorbs the
    /// round-off of a clock that landed on the release time.
    [[nodiscard]] bool release_due(double time, double tolerance) const noexcept
    {
        return motion == Motion::prescribed && release_time && time >= *release_time - tolerance;
    }
};

} // namespace fddem
