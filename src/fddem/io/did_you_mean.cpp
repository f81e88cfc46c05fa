// SPDX-License-Identifier: MIT
#include "fddem/io/did_you_mean.hpp"

#include <algorithm>

namespace fddem {

std::size_t edit_distance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] =
                std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string suggestion(const std::string& wrong, const std::vector<std::string>& valid)
{
    std::string best;
    std::size_t best_distance = std::string::npos;
    for (const auto& v : valid) {
        const std::size_t d = edit_distance(wrong, v);
        if (d < best_distance) {
            best_distance = d;
            best = v;
        }
    }
    // Suggest only near misses: at most a third of the name changed.
    if (best_distance <= std::max<std::size_t>(2, wrong.size() / 3)) {
        return "; did you mean '" + best + "'?";
    }
    // Or a valid name with a word added ("time.end_time" for "time.end").
    for (const auto& v : valid) {
        if (wrong.starts_with(v + "_") || v.starts_with(wrong + "_")) {
            return "; did you mean '" + v + "'?";
        }
    }
    return "";
}

} // namespace fddem
