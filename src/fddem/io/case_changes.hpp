// SPDX-License-Identifier: MIT
#pragma once
/// What differs between two cases as run (case.toml texts): the restart says which keys a
/// `--set` or an edited case.toml changed since the checkpoint was written.

#include <string>
#include <string_view>
#include <vector>

namespace fddem {

/// One line per key whose value differs, "section.key: old → new" (a key one side lacks shows
/// as "(none)"), in key order; [[bodies]] entries are numbered (bodies.1.density). Empty if
/// the cases agree or either text does not parse.
[[nodiscard]] std::vector<std::string> case_changes(std::string_view before,
                                                    std::string_view after);

} // namespace fddem
