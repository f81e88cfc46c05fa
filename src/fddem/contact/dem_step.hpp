// SPDX-License-Identifier: MIT
#pragma once
/// The contact part of one fluid time step: the bodies are advanced through N_i sub-steps of
/// Δt_i = Δt/N_i under contact forces and torques (ball–ball and ball–wall; the model of
/// contact_models.hpp, friction and rolling resistance of tangential_contact.hpp) plus a force
/// held constant over the step (the buoyant weight), eq. (18), with the paper's velocity formula
/// split into half-kicks around the drift (dem_integrator.hpp). The tangential springs, and the
/// constants a PerContactModel fixes when a contact opens (the adaptive model, from the approach
/// speed then and the step's Δt), persist in a ContactHistory the caller owns.
///
/// The result is used in two ways (contact.coupling): the time-averaged contact force and torque
/// enter eqs. (13)–(14) ("additive"), or the sub-stepped end state replaces (13)–(14) and (17)
/// for a body in contact ("paper", §2.3: "When the collision happens, the DEM is used in place
/// of (13) and (14)").

#include "fddem/bodies/particle.hpp"
#include "fddem/contact/cell_list.hpp"
#include "fddem/contact/contact_history.hpp"
#include "fddem/contact/contact_models.hpp"
#include "fddem/contact/lubrication.hpp"
#include "fddem/contact/material.hpp"
#include "fddem/core/vec.hpp"

#include <array>
#include <span>
#include <vector>

namespace fddem {

/// The box walls a body can hit: the non-periodic axes of [origin, origin + length].
template <int Dim>
struct DemWalls {
    Vec<Dim> origin;
    Vec<Dim> length;
    std::array<bool, Dim> has_walls; ///< per axis
    /// Velocity of each wall [m/s], [axis][side]; tangential only (a sliding wall).
    std::array<std::array<Vec<Dim>, 2>, Dim> velocity = at_rest();
    Material material{}; ///< the walls' surface

    [[nodiscard]] static std::array<std::array<Vec<Dim>, 2>, Dim> at_rest()
    {
        std::array<std::array<Vec<Dim>, 2>, Dim> v;
        for (auto& axis : v) {
            axis.fill(Vec<Dim>::Zero());
        }
        return v;
    }
};

struct DemSettings {
    AnyContactModel model;
    double beta = 0.0; ///< velocity damping β of eq. (18) [kg/s]
    int substeps = 1;  ///< N_i
    /// Bodies closer than this to another body or a wall at any sub-step count as in contact
    /// for the step (has_contact) without a force: with the paper's coupling DEM then moves
    /// them, instead of the fluid update, which cannot see them close in [m]. 0: touching only.
    double margin = 0.0;
    /// Lubrication correction (contact/lubrication.hpp), off by default. When on, pairs and
    /// walls closer than its range get, after each sub-step's first half-kick, a backward-Euler
    /// damping impulse of their relative normal and tangential surface velocities, with the
    /// resistance averaged over the drift that follows (film_step). With
    /// coupling "dem" they count as in contact (as within the margin: with the paper's coupling
    /// the DEM moves them, so the damping acts on the velocity the body keeps); with "implicit"
    /// only those leaving a collision do (a gap opening within the range after a touch, until it
    /// has left the range: ContactHistory::rebounds), and each body's gaps at the step's start
    /// (within the range, or carried into it by the start velocities) are kept in
    /// contact.lubrication_links for eqs. (13)–(14). The cell list must reach 2 r_max +
    /// max(margin, range); a pair it does not hold at a sub-step's start that the drift brings
    /// into the range gets no film for that drift (a loss below c_corr's vanishing tail at h_Δ).
    /// The travel is predicted along the normal, h0 + Δt_i ḣ: a pair sliding past each other
    /// whose prediction dips into the range while its path stays out gets the film of that
    /// prediction, again from c_corr's tail at h_Δ (the path's departure from the straight line
    /// is (v_t Δt_i)²/(4 ā), far below h_Δ at the steps' Courant numbers), and with "dem" it is
    /// not counted as in contact for it.
    LubricationSettings lubrication{};
    /// The held fluid force (ContactState::held_fluid_force) acts also in the sub-steps in which
    /// the body touches (contact.fluid_force = "always"); otherwise only while it touches nothing.
    bool is_fluid_force_held_in_contact = false;
};

/// What the contacts did over the step, beyond what each body's record holds.
struct DemOutcome {
    double max_overlap = 0.0;          ///< largest α seen in any sub-step [m]
    double max_relative_overlap = 0.0; ///< largest α / r of the smaller body
    int n_contacts = 0;                ///< contacts at the end of the step
    /// lubrication.film_solve "joint": its solves that stopped at an iteration limit before
    /// their tolerance or met a NaN, over the step's sub-steps (JointFilms::n_unfinished)
    int n_unfinished_film_solves = 0;
};

/// Advances every body of `bodies` through settings.substeps sub-steps of dt (one time step),
/// in place in its record's contact part (bodies/particle.hpp): from its state (centre, velocity,
/// omega) to contact.centre, contact.velocity, contact.omega, under the contact forces and
/// contact.steady_force and steady_torque, held over the step; writes contact.mean_force,
/// mean_torque and is_in_contact. The body's own state is left as it was. A fixed or prescribed
/// body moves at its velocity, unaffected. `cells` must reach at least 2 r_max +
/// settings.margin; what it reaches beyond is the skin of the sub-steps' neighbour list
/// (contact/neighbour_list.hpp: none, and the list is rebuilt at every sub-step, if it reaches no
/// further). `history` holds the tangential springs and per-contact constants of the open
/// contacts and (lubrication.coupling "implicit") the collisions under way, keyed by the bodies'
/// ids; on return it holds those of the end of the step.
/// `dt` is the fluid step: the adaptive model stretches a collision to N_c dt.
template <int Dim>
DemOutcome advance_contacts(std::span<Particle<Dim>> bodies, const DemWalls<Dim>& walls,
                            const DemSettings& settings, double dt, CellList<Dim>& cells,
                            ContactHistory<Dim>& history);

} // namespace fddem
