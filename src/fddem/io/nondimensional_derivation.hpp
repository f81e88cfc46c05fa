// SPDX-License-Identifier: MIT
#pragma once
/// The paper's non-dimensional cases (§3.1) as dimensional ones: [nondimensional] names a set of
/// numbers (Re; or Re and ρr), and that set's row derives the dimensional values they fix
/// (eqs. (19)–(22), io/nondimensional.hpp) into the case, recorded in [derived] of the case as
/// run.

#include "fddem/simulation/case_config.hpp"

#include <string_view>
#include <vector>

namespace fddem {

class CaseDocument;

/// One set of non-dimensional numbers a case can give: its [nondimensional] keys, and what it
/// derives from them.
struct NondimensionalSet {
    std::string_view name;
    std::vector<std::string_view> keys; ///< [nondimensional] keys that select it, all given
    void (*derive)(CaseDocument& doc, CaseConfig& c);
};

/// Every set, each with its own keys.
[[nodiscard]] std::vector<NondimensionalSet> nondimensional_sets();

/// Checks that each value is given once (dimensional, or through [nondimensional]) and derives
/// the values of the set the case gives, if any.
void derive_nondimensional(CaseDocument& doc, CaseConfig& c);

} // namespace fddem
