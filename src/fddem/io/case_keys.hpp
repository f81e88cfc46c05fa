// SPDX-License-Identifier: MIT
#pragma once
/// The keys of a case checked one by one against the schema (io/case_schema.cpp): unknown
/// sections and keys (with "did you mean"), the dimension, each value's type, length, range
/// and choice, required keys; defaults filled in; and each value stored in its field of
/// CaseConfig through its schema row. What keys say together is io/case_checks.cpp's.

#include "fddem/io/case_schema.hpp"
#include "fddem/simulation/case_config.hpp"

#include <vector>

namespace fddem {

class CaseDocument;

/// The case of `doc`, every key checked; fills the defaults into `doc` (the case as run).
[[nodiscard]] CaseConfig read_keys(CaseDocument& doc, const std::vector<KeySpec>& schema);

} // namespace fddem
