// SPDX-License-Identifier: MIT
#pragma once
/// One gap of a body within the lubrication range, as the implicit coupling of the correction
/// (lubrication.coupling = "implicit"; coupling/lubrication_coupling.hpp) needs it: fixed at the
/// step's start (the level-n positions), the velocities left to eqs. (13)–(14).

#include "fddem/contact/lubrication.hpp"
#include "fddem/core/vec.hpp"

#include <cstddef>
#include <limits>

namespace fddem {

template <int Dim>
struct LubricationLink {
    /// `partner` of a gap to a wall.
    static constexpr std::size_t wall = std::numeric_limits<std::size_t>::max();

    std::size_t partner = wall;                ///< the other body's index in the store
    Vec<Dim> normal = Vec<Dim>::Zero();        ///< unit, from this body toward the partner
    Vec<Dim> lever = Vec<Dim>::Zero();         ///< from this body's centre to the gap [m]
    Vec<Dim> partner_lever = Vec<Dim>::Zero(); ///< from the partner's centre to the gap [m]
    Vec<Dim> wall_velocity = Vec<Dim>::Zero(); ///< the wall's velocity (a wall's gap) [m/s]
    /// c_corr averaged over the gaps from the step's start to where the start velocities would
    /// take it in Δt (lubrication_correction_over): the body slows, so the mean leans to the
    /// nearer gaps as the damping on U^{n+1} needs to take the film's integral over the step
    LubricationResistance resistance;
};

} // namespace fddem
