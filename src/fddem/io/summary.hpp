// SPDX-License-Identifier: MIT
#pragma once
/// summary.json: what a run did (timings by phase, peak memory, counts, build), written
/// atomically; toml++'s JSON formatter does the encoding.

#include <filesystem>
#include <map>
#include <string>
#include <variant>

namespace fddem {

class RunSummary {
public:
    using Value = std::variant<double, long, std::string, bool>;
    void set(const std::string& key, Value value) { values_[key] = std::move(value); }
    void set_phase_seconds(const std::string& phase, double seconds) { phases_[phase] = seconds; }
    /// Writes the JSON document (keys sorted, phases under "wall_seconds_by_phase").
    void write(const std::filesystem::path& path) const;
    [[nodiscard]] std::string to_json() const;

private:
    std::map<std::string, Value> values_;
    std::map<std::string, double> phases_;
};

/// Peak resident memory of this process so far [MiB] (getrusage ru_maxrss).
[[nodiscard]] double peak_memory_mib();

} // namespace fddem
