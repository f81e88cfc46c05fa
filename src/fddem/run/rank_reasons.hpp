// SPDX-License-Identifier: MIT
#pragma once
/// Why a run cannot go on, agreed by every rank (issue 15): a check that each rank makes on its
/// own (a checkpoint's pieces, the memory of its machine) may fail on some ranks only, and
/// rank 0, which alone speaks for the run, must then say the reason of a rank that met it.

#include "fddem/grid/communicator.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace fddem {

/// The `reason` of the lowest rank that has one, on every rank (none if no rank has), followed
/// by "(<where> <rank>)" if that rank is not rank 0. Collective: one maximum, and one all-gather
/// of the texts (each cut to 400 bytes) only when some rank has a reason.
[[nodiscard]] std::optional<std::string> first_reason(const Communicator& ranks,
                                                      const std::optional<std::string>& reason,
                                                      std::string_view where);

} // namespace fddem
