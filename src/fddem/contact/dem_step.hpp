// SPDX-License-Identifier: MIT
#pragma once
/// The contact part of one fluid time step: the bodies are advanced through N_i sub-steps of
/// Δt_i = Δt/N_i under contact forces (ball–ball and ball–wall, linear spring–dashpot) plus a
/// force held constant over the step (weight and the last hydrodynamic force), eq. (18), with
/// the paper's velocity formula split into half-kicks around the drift (dem_integrator.hpp).
///
/// The result is used in two ways (contact.coupling): the time-averaged contact force and torque
/// enter eqs. (13)–(14) ("additive"), or the sub-stepped end state replaces (13)–(14) and (17)
/// for a body in contact ("paper", §2.3: "When the collision happens, the DEM is used in place
/// of (13) and (14)").

#include "fddem/contact/cell_list.hpp"
#include "fddem/contact/linear_spring_dashpot.hpp"
#include "fddem/core/vec.hpp"

#include <span>
#include <vector>

namespace fddem {

/// One body as the DEM sees it.
template <int Dim>
struct DemBody {
    Vec<Dim> centre;
    Vec<Dim> velocity;
    AngularVec<Dim> omega;
    double radius;
    double mass;           ///< [kg] (2D: per unit depth)
    double inertia;        ///< [kg·m²]
    bool is_mobile = true; ///< false: fixed or prescribed (moves at its velocity, unaffected)
    Vec<Dim> steady_force; ///< held over the step: weight, hydrodynamic force [N]
    AngularVec<Dim> steady_torque; ///< [N·m]
};

/// The box walls a body can hit: the non-periodic axes of [origin, origin + length].
template <int Dim>
struct DemWalls {
    Vec<Dim> origin;
    Vec<Dim> length;
    std::array<bool, Dim> has_walls; ///< per axis
};

struct DemSettings {
    LinearSpringDashpot::Params law;
    double beta = 0.0; ///< velocity damping β of eq. (18) [kg/s]
    int substeps = 1;  ///< N_i
};

/// What the contacts did to each body over the step.
template <int Dim>
struct DemOutcome {
    std::vector<Vec<Dim>> mean_force;         ///< contact impulse / Δt [N]
    std::vector<AngularVec<Dim>> mean_torque; ///< [N·m]
    std::vector<bool> has_contact;            ///< touched something during the step
    double max_overlap = 0.0;                 ///< largest α seen in any sub-step [m]
    double max_relative_overlap = 0.0;        ///< largest α / r of the smaller body
    int n_contacts = 0;                       ///< contacts at the end of the step
};

/// Advances `bodies` (centre, velocity, omega) through settings.substeps sub-steps of dt.
template <int Dim>
DemOutcome<Dim> advance_contacts(std::span<DemBody<Dim>> bodies, const DemWalls<Dim>& walls,
                                 const DemSettings& settings, double dt, CellList<Dim>& cells);

} // namespace fddem
