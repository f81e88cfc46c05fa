// SPDX-License-Identifier: MIT
#include "fddem/io/summary.hpp"

#include "fddem/io/atomic_file.hpp"

#include <toml++/toml.h>

#include <sstream>
#include <sys/resource.h>

namespace fddem {

std::string RunSummary::to_json() const
{
    toml::table root;
    for (const auto& entry : values_) {
        // Not a structured binding: clang 14 cannot capture one in a lambda (C++20 P1091).
        const std::string& key = entry.first;
        std::visit(
            [&](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, long>) {
                    root.insert(key, static_cast<std::int64_t>(v));
                } else {
                    root.insert(key, v);
                }
            },
            entry.second);
    }
    toml::table phases;
    for (const auto& [phase, seconds] : phases_) {
        phases.insert(phase, seconds);
    }
    root.insert("wall_seconds_by_phase", std::move(phases));
    std::ostringstream out;
    out << toml::json_formatter{root} << "\n";
    return out.str();
}

void RunSummary::write(const std::filesystem::path& path) const
{
    write_file_atomically(path, to_json());
}

double peak_memory_mib()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

} // namespace fddem
