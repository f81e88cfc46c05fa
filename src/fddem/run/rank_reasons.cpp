// SPDX-License-Identifier: MIT
#include "fddem/run/rank_reasons.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace fddem {

std::optional<std::string> first_reason(const Communicator& ranks,
                                        const std::optional<std::string>& reason,
                                        std::string_view where)
{
    if (ranks.max(reason ? 1.0 : 0.0) == 0.0) {
        return std::nullopt;
    }
    // Each rank's text, cut to `width` bytes, as integers: one all-gather, only when some rank
    // has a reason.
    constexpr std::size_t width = 400;
    std::vector<int> mine(width + 1, 0);
    mine[0] = reason ? 1 : 0;
    const std::string text = reason.value_or("");
    for (std::size_t k = 0; k < std::min(width, text.size()); ++k) {
        mine[k + 1] = static_cast<unsigned char>(text[k]);
    }
    const std::vector<int> all = ranks.all_gather(mine);
    for (int rank = 0; rank < ranks.size(); ++rank) {
        const auto at = static_cast<std::size_t>(rank) * (width + 1);
        if (all[at] == 0) {
            continue;
        }
        std::string said;
        for (std::size_t k = 1; k <= width && all[at + k] != 0; ++k) {
            said.push_back(static_cast<char>(all[at + k]));
        }
        return rank == 0 ? said : fmt::format("{} ({} {})", said, where, rank);
    }
    return std::nullopt;
}

} // namespace fddem
