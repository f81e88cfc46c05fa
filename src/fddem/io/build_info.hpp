// SPDX-License-Identifier: MIT
#pragma once
/// What this fddem is: version, commit, build, linked library versions, parallelism.

#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// (name, value) pairs, in a fixed order, for `fddem info` and each run's summary.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> build_info();

} // namespace fddem
