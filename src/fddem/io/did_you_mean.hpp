// SPDX-License-Identifier: MIT
#pragma once
/// "Did you mean" suggestions for misspelt section names, keys and choices.

#include <string>
#include <string_view>
#include <vector>

namespace fddem {

/// Levenshtein distance, for "did you mean" suggestions (a dozen lines: no Debian library
/// offers it for C++).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// "; did you mean 'x'?" for the name in `valid` nearest to `wrong` (at most a third of it
/// changed, or a word added or left out), else "".
[[nodiscard]] std::string suggestion(const std::string& wrong,
                                     const std::vector<std::string>& valid);

} // namespace fddem
