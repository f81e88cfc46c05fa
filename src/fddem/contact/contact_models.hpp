// SPDX-License-Identifier: MIT
#pragma once
/// The registry of contact models (STYLE.md §6): the only list of the models a case can name in
/// `contact.model`, each with its factory and its source. `none` turns collisions off.

#include "fddem/contact/adaptive_collision.hpp"
#include "fddem/contact/hertz_mindlin.hpp"
#include "fddem/contact/linear_spring_dashpot.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fddem {

/// Dispatched once per force evaluation (std::visit), never inside the pair loop.
using AnyContactModel = std::variant<LinearSpringDashpot, HertzMindlin, AdaptiveCollision>;

/// Everything a factory may need from the case.
struct ContactModelInput {
    LinearSpringDashpot::Params linear{1.0, 0.0}; ///< k, c, κ of the linear model
    double reference_mass = 1.0;          ///< lightest movable body [kg]: the linear model's checks
    AdaptiveCollision::Params adaptive{}; ///< e_dry, N_c, v_min, Δt, κ of the adaptive model
};

/// The models a case can name in contact.model.
enum class ContactModelKind { linear, hertz_mindlin, adaptive, none };

/// How DEM and the fluid update share a body in contact: the paper's (DEM replaces (13)–(14) and
/// (17) while in contact) or additive (the mean contact force is added to (13)–(14)).
enum class ContactCoupling { paper, additive };

/// What the resolved fluid does to a body during the DEM sub-steps (contact.fluid_force): none
/// (the paper's eq. (18): the buoyant weight only) or held (the resolved hydrodynamic force and
/// torque of the step before, held constant over the sub-steps in which the body touches
/// nothing, as resolved codes hold the fluid force over their collision sub-steps); automatic:
/// held with the lubrication correction on and coupled through the DEM (lubrication.coupling
/// "dem"), none otherwise (held_fluid_force_applies()); always: held, also over the sub-steps in
/// which the body touches (an enduring contact: two spheres that touch while they settle keep
/// their drag; docs/method.md §5, "A fluid force in an enduring contact").
enum class ContactFluidForce { automatic, none, held, always };

/// Whether the sub-steps hold the resolved fluid force: contact.fluid_force = "held" or
/// "always", or "auto" with `is_lubrication_through_dem` (lubrication.enabled with coupling "dem").
/// Then the paper coupling hands a body to the DEM whenever it is within the lubrication range
/// (about 2 h) of a wall or another body, for as long as it stays there; without the resolved force
/// a sphere sliding down a side wall 0.8 h away then falls at its buoyant weight alone, 2.8 times
/// faster than in open fluid after 0.06 s instead of slower (docs/method.md §5, Coupling).
[[nodiscard]] constexpr bool held_fluid_force_applies(ContactFluidForce choice,
                                                      bool is_lubrication_through_dem)
{
    return choice == ContactFluidForce::held || choice == ContactFluidForce::always ||
           (choice == ContactFluidForce::automatic && is_lubrication_through_dem);
}

/// Whether the held fluid force acts also while the body touches (contact.fluid_force =
/// "always"); otherwise the contact model alone acts during a contact.
[[nodiscard]] constexpr bool held_fluid_force_acts_in_contact(ContactFluidForce choice)
{
    return choice == ContactFluidForce::always;
}

struct ContactModelEntry {
    ContactModelKind kind;
    std::string_view name;     ///< the case-file name
    std::string_view citation; ///< where the force law comes from
    /// The model, or nothing for a case without collisions.
    std::optional<AnyContactModel> (*make)(const ContactModelInput&);
};

[[nodiscard]] std::span<const ContactModelEntry> contact_models();
[[nodiscard]] std::vector<std::string> contact_model_names();
/// The model registered as `kind`.
[[nodiscard]] std::optional<AnyContactModel> make_contact_model(ContactModelKind kind,
                                                                const ContactModelInput& input);

/// The shortest undamped binary collision [s] at impact speed `impact_speed` [m/s] among `bodies`
/// (each against itself, i.e. two alike, and against every other) and, if `wall` is given,
/// each against a wall. Pairs that cannot move (both immovable) are left out; sets the DEM
/// sub-steps. Returns +∞ if no pair can collide.
[[nodiscard]] double shortest_collision(const AnyContactModel& model,
                                        std::span<const PairSide> bodies,
                                        const std::optional<Material>& wall, double impact_speed);

} // namespace fddem
