// SPDX-License-Identifier: MIT
#pragma once
/// Per-body state of the fictitious-domain coupling: markers, λ and λ*, work arrays.

#include "fddem/bodies/rigid_body.hpp"
#include "fddem/coupling/markers.hpp"

#include <vector>

namespace fddem {

template <int Dim>
struct BodyCoupling {
    MarkerSet<Dim> markers;                 ///< body frame
    std::vector<Vec<Dim>> offsets;          ///< r_l in the world frame (rotated) [m]
    std::vector<Vec<Dim>> positions;        ///< X_l = centre + r_l [m]
    std::vector<Vec<Dim>> fluid;            ///< I(u) at the markers [m/s]
    std::vector<Vec<Dim>> lambda;           ///< λ [m/s²]
    std::vector<Vec<Dim>> lambda_star;      ///< λ* [m/s²]
    double fluid_second_moment = 0.0;       ///< Σ ΔV_l |r_l⊥|²
    Vec<Dim> velocity_n = Vec<Dim>::Zero(); ///< U^n
    AngularVec<Dim> omega_n{};              ///< ω^n
    double forcing_change = 0.0;            ///< of the last λ update (rigid_coupling.hpp) [m/s]
    // The DEM sub-steps of this step (contact/dem_step.hpp):
    Vec<Dim> contact_force = Vec<Dim>::Zero();            ///< mean contact force [N]
    AngularVec<Dim> contact_torque = zero_angular<Dim>(); ///< mean contact torque [N·m]
    bool is_in_contact = false;                           ///< touched something this step
    Vec<Dim> dem_centre = Vec<Dim>::Zero();               ///< end of the sub-steps [m]
    Vec<Dim> dem_velocity = Vec<Dim>::Zero();             ///< [m/s]
    AngularVec<Dim> dem_omega = zero_angular<Dim>();      ///< [rad/s]

    explicit BodyCoupling(MarkerSet<Dim> set)
        : markers(std::move(set)), offsets(markers.size()), positions(markers.size()),
          fluid(markers.size()), lambda(markers.size(), Vec<Dim>::Zero()),
          lambda_star(markers.size(), Vec<Dim>::Zero()),
          fluid_second_moment(markers.second_moment())
    {
        if constexpr (Dim == 3) {
            omega_n = Vec<3>::Zero();
        }
    }
};

} // namespace fddem
