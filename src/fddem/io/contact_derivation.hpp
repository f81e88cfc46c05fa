// SPDX-License-Identifier: MIT
#pragma once
/// [contact] turned into the DEM's coefficients and sub-steps N_i (eq. (18)), recorded in
/// [derived] of the case as run. Each contact model's row owns the keys only it takes and
/// derives its coefficients; the surfaces, the reference collision (a wall collision of the
/// lightest free body) and N_i are common to all.

#include "fddem/contact/material.hpp"
#include "fddem/simulation/case_config.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace fddem {

class CaseDocument;

/// DEM sub-steps per time step at most (contact.substeps' upper limit).
inline constexpr double max_dem_substeps = 10000000;

/// The collision the derived values describe: a wall collision of the lightest free body, or of
/// two of them if the box has no walls.
struct ReferenceCollision {
    double mass = 0.0; ///< the lightest free body's [kg] (2D: per unit depth)
    ContactPair pair;
    bool has_walls = false;
};

/// The case keys and the derivation of one contact model (contact/contact_models.cpp is the
/// registry of the force laws themselves).
struct ContactModelKeys {
    ContactModelKind model;
    /// The keys only this model takes ("contact.stiffness", "bodies.restitution"…), in the
    /// order a case that gives them to another model is told.
    std::vector<std::string> keys;
    /// The keys that set the collision's duration, for the message when it cannot be resolved.
    std::string_view duration_keys;
    /// Checks the keys given together, before anything is derived (may be null).
    void (*check)(const CaseDocument& doc);
    /// Sets c.contact.derived (k and c, or the impact speed; duration and restitution of the
    /// reference collision) and records what only this model derives.
    void (*derive)(CaseDocument& doc, CaseConfig& c, const ReferenceCollision& reference);
};

/// The models that derive something; contact.model = "none" has no row (nothing to derive).
[[nodiscard]] std::vector<ContactModelKeys> contact_model_keys();

/// Surfaces of every body and of the walls, the model's coefficients, and N_i: enough
/// sub-steps for 80 in the shortest collision, or contact.substeps (at least 10 per collision).
void derive_contact(CaseDocument& doc, CaseConfig& c);

} // namespace fddem
