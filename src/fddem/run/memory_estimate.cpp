// SPDX-License-Identifier: MIT
#include "fddem/run/memory_estimate.hpp"

#include "fddem/core/errors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <unistd.h>

namespace fddem {
namespace {

/// Fitted above the peak resident memory (maximum RSS, /usr/bin/time) of `fddem run` on
/// lid-driven cavities of one step, FFT and hypre pressure solvers (docs/testing.md, "Memory
/// estimate"): 2D 128², 512², 1024² took 28, 195 (hypre 241), 775 MiB; 3D 32³, 64³, 96³ took 84,
/// 400, 1327 MiB. The fixed part is the program, its libraries and MPI; every cell adds its
/// fields with their ghosts, the momentum and pressure systems, the outer iterations' history,
/// the FFT plans or hypre's hierarchy, and its share of the checkpoint written at the end. The
/// estimate is 3–70 % above those peaks (the most for small grids, where the fixed part rules).
constexpr double fixed_bytes = 48.0 * 1024 * 1024;
constexpr double bytes_per_cell_2d = 850.0;
constexpr double bytes_per_cell_3d = 1700.0;
/// A marker's position, offset, volume, λ, λ*, interpolated velocity and kernel weights.
constexpr double bytes_per_marker = 1024.0;

/// The markers of one body: about its volume over h^Dim (the layouts place one per cell or so).
double estimated_markers(const CaseConfig& config, const BodyConfig& body)
{
    const auto dimension = static_cast<std::size_t>(config.domain.dimension);
    double cell_volume = 1.0;
    for (std::size_t d = 0; d < dimension; ++d) {
        cell_volume *= config.domain.size[d] / config.domain.cells[d];
    }
    const double r = 0.5 * body.diameter;
    const double volume =
        dimension == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
    return volume / cell_volume + 1.0;
}

/// The smaller of the machine's memory and a cgroup v2 limit ("max": none).
std::optional<double> cgroup_limit()
{
    std::ifstream in("/sys/fs/cgroup/memory.max");
    double limit = 0.0;
    if (in >> limit && limit > 0.0) {
        return limit;
    }
    return std::nullopt;
}

/// "512 × 512": the grid's cells for messages.
std::string cells_text(const CaseConfig& config)
{
    return fmt::format("{}", fmt::join(config.domain.cells, " × "));
}

} // namespace

double estimate_run_memory(const CaseConfig& config)
{
    double cells = 1.0;
    for (const int n : config.domain.cells) {
        cells *= n;
    }
    double markers = 0.0;
    for (const BodyConfig& body : config.bodies) {
        markers += estimated_markers(config, body);
    }
    const double per_cell = config.domain.dimension == 2 ? bytes_per_cell_2d : bytes_per_cell_3d;
    return fixed_bytes + per_cell * cells + bytes_per_marker * markers;
}

std::optional<double> available_memory()
{
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long page_size = ::sysconf(_SC_PAGE_SIZE);
    std::optional<double> memory;
    if (pages > 0 && page_size > 0) {
        memory = static_cast<double>(pages) * static_cast<double>(page_size);
    }
    if (const std::optional<double> limit = cgroup_limit()) {
        memory = memory ? std::min(*memory, *limit) : *limit;
    }
    return memory;
}

std::optional<double> run_memory_limit(const CaseConfig& config)
{
    return config.run.max_memory ? config.run.max_memory : available_memory();
}

std::string memory_text(double bytes)
{
    constexpr double mib = 1024.0 * 1024.0;
    constexpr double gib = 1024.0 * mib;
    return bytes >= gib ? fmt::format("{:.3g} GiB", bytes / gib)
                        : fmt::format("{:.3g} MiB", bytes / mib);
}

void check_run_memory(const CaseConfig& config, std::optional<double> limit)
{
    const double estimate = estimate_run_memory(config);
    if (!limit || estimate <= *limit) {
        return;
    }
    const std::string whose = config.run.max_memory
                                  ? fmt::format("run.max_memory = {:g} B", *config.run.max_memory)
                                  : "the memory of this machine";
    throw InputError(config.source_file, 0, "domain.cells",
                     fmt::format("a grid of {} cells needs about {} (estimate), more than {} "
                                 "({}); use fewer cells{}",
                                 cells_text(config), memory_text(estimate), whose,
                                 memory_text(*limit),
                                 config.run.max_memory ? "" : ", or set run.max_memory"));
}

std::string memory_message(const CaseConfig& config, std::optional<double> limit)
{
    return fmt::format("fddem: memory estimate {} for {} cells{}",
                       memory_text(estimate_run_memory(config)), cells_text(config),
                       limit ? fmt::format(" (limit {})", memory_text(*limit)) : "");
}

} // namespace fddem
