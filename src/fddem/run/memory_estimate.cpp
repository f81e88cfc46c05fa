// SPDX-License-Identifier: MIT
#include "fddem/run/memory_estimate.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/simulation/simulation_setup.hpp"

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
    return estimate_rank_memory(config, 1);
}

double estimate_rank_memory(const CaseConfig& config, int n_ranks)
{
    // The largest block: ⌈n/p⌉ cells along each axis; its storage grows by 1 + 2 ghost layers
    // per axis as the whole grid's does, which the per-cell figure was measured with.
    std::vector<int> ranks(config.domain.cells.size(), 1);
    if (n_ranks > 1 && config.domain.dimension == 2) {
        const Index<2> layout = rank_layout<2>(config, n_ranks);
        ranks.assign(layout.begin(), layout.end());
    } else if (n_ranks > 1) {
        const Index<3> layout = rank_layout<3>(config, n_ranks);
        ranks.assign(layout.begin(), layout.end());
    }
    constexpr int storage_extra = 1 + 2 * MacGrid<3>::n_ghost;
    double cells = 1.0;
    for (std::size_t d = 0; d < config.domain.cells.size(); ++d) {
        const int n = config.domain.cells[d];
        const int block = (n + ranks[d] - 1) / ranks[d];
        cells *= ranks[d] == 1
                     ? n
                     : static_cast<double>(block + storage_extra) * n / (n + storage_extra);
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

void check_run_memory(const CaseConfig& config, std::optional<double> limit, int n_ranks,
                      int ranks_on_node)
{
    const double estimate = ranks_on_node * estimate_rank_memory(config, n_ranks);
    if (!limit || estimate <= *limit) {
        return;
    }
    const std::string whose = config.run.max_memory
                                  ? fmt::format("run.max_memory = {:g} B", *config.run.max_memory)
                                  : "the memory of this machine";
    throw InputError(config.source_file, 0, "domain.cells",
                     fmt::format("a grid of {} cells needs about {} (estimate{}), more than {} "
                                 "({}); use fewer cells{}{}",
                                 cells_text(config), memory_text(estimate),
                                 n_ranks > 1 ? fmt::format(", for the {} of its {} ranks on this "
                                                           "machine",
                                                           ranks_on_node, n_ranks)
                                             : "",
                                 whose, memory_text(*limit), n_ranks > 1 ? " or more machines" : "",
                                 config.run.max_memory ? "" : ", or set run.max_memory"));
}

std::string memory_message(const CaseConfig& config, std::optional<double> limit, int n_ranks,
                           int ranks_on_node)
{
    const std::string split =
        n_ranks > 1
            ? fmt::format("; on {} ranks about {} for the largest block, {} for the {} "
                          "on this machine",
                          n_ranks, memory_text(estimate_rank_memory(config, n_ranks)),
                          memory_text(ranks_on_node * estimate_rank_memory(config, n_ranks)),
                          ranks_on_node)
            : "";
    return fmt::format("fddem: memory estimate {} for {} cells{}{}",
                       memory_text(estimate_run_memory(config)), cells_text(config), split,
                       limit ? fmt::format(" (limit {})", memory_text(*limit)) : "");
}

} // namespace fddem
