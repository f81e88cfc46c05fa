// SPDX-License-Identifier: MIT
#pragma once
/// What the contact model factory (contact/contact_models.hpp) takes from a case whose
/// [contact] values are derived (io/contact_derivation.hpp): one place for the reader, which
/// builds the model to size the sub-steps, and the simulation, which runs it.

#include "fddem/contact/contact_models.hpp"
#include "fddem/simulation/case_config.hpp"

namespace fddem {

[[nodiscard]] ContactModelInput contact_model_input(const CaseConfig& c);

} // namespace fddem
