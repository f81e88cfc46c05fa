// SPDX-License-Identifier: MIT
#pragma once
/// Reads a case file (TOML) against the schema (io/case_schema.cpp) into a CaseConfig.
/// Every problem — syntax, unknown or misspelt key, wrong type, out of range, missing,
/// contradictory — throws InputError naming the file, the line and the key, before any work.
/// The steps, one file each: the TOML document and --set (io/case_document.cpp), each key
/// against the schema (io/case_keys.cpp), the bodies of the [[bodies]] entries
/// (io/body_entries.cpp), the keys together (io/case_checks.cpp), and the values fddem derives
/// (io/nondimensional_derivation.cpp, io/contact_derivation.cpp).

#include "fddem/io/did_you_mean.hpp"
#include "fddem/simulation/case_config.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace fddem {

/// `overrides` are `section.key=value` strings (from `--set`); value is TOML (`1e-3`,
/// `[64,64]`, `"upwind"`) or a bare word taken as a string (`upwind`).
[[nodiscard]] CaseConfig read_case(const std::string& path,
                                   const std::vector<std::string>& overrides = {});

/// The same from text; `source_name` names it in messages.
[[nodiscard]] CaseConfig read_case_string(std::string_view text, const std::string& source_name,
                                          const std::vector<std::string>& overrides = {});

} // namespace fddem
