// SPDX-License-Identifier: MIT
#include "fddem/run/line_samples.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/grid/sampling.hpp"
#include "fddem/io/csv_history.hpp"
#include "fddem/run/csv_columns.hpp"

#include <fmt/format.h>

#include <numeric>
#include <span>

namespace fddem {

template <int Dim>
std::vector<std::string> sample_columns()
{
    std::vector<std::string> columns;
    for (const auto& names : {axis_names, velocity_names}) {
        for (int d = 0; d < Dim; ++d) {
            columns.emplace_back(names.at(static_cast<std::size_t>(d)));
        }
    }
    columns.emplace_back("p");
    return columns;
}

template <int Dim>
void write_line_samples(const Simulation<Dim>& sim, const std::vector<LineSample>& lines,
                        const std::filesystem::path& directory)
{
    const std::vector<std::string> columns = sample_columns<Dim>();
    for (const LineSample& line : lines) {
        Vec<Dim> from;
        Vec<Dim> to;
        for (int d = 0; d < Dim; ++d) {
            from[d] = line.from[static_cast<std::size_t>(d)];
            to[d] = line.to[static_cast<std::size_t>(d)];
        }
        const MacGrid<Dim>& grid = sim.grid();
        std::vector<double> mine;
        for (const std::vector<double>& row :
             sample_line_owned(grid, sim.fluid().u, sim.fluid().p, from, to, line.n_points)) {
            mine.insert(mine.end(), row.begin(), row.end());
        }
        const Communicator& ranks = grid.communicator();
        const int count = static_cast<int>(mine.size());
        const std::vector<int> counts = ranks.all_gather(std::span<const int>(&count, 1));
        std::vector<double> all(static_cast<std::size_t>(line.n_points) * (columns.size() + 1));
        if (std::accumulate(counts.begin(), counts.end(), std::size_t{0}) != all.size()) {
            throw InternalError(
                fmt::format("line sample {}: the ranks sampled {} values of {}", line.name,
                            std::accumulate(counts.begin(), counts.end(), 0), all.size()));
        }
        ranks.all_gather(mine, counts, all);
        if (ranks.rank() != 0) {
            continue;
        }
        // Every point once, each rank's in order: put them in the line's order.
        std::vector<std::vector<double>> rows(static_cast<std::size_t>(line.n_points));
        const std::size_t width = columns.size() + 1;
        for (std::size_t at = 0; at < all.size(); at += width) {
            rows[static_cast<std::size_t>(all[at])].assign(
                all.begin() + static_cast<std::ptrdiff_t>(at + 1),
                all.begin() + static_cast<std::ptrdiff_t>(at + width));
        }
        write_csv(directory / "samples" / (line.name + ".csv"), columns, rows);
    }
}

template std::vector<std::string> sample_columns<2>();
template std::vector<std::string> sample_columns<3>();
template void write_line_samples(const Simulation<2>&, const std::vector<LineSample>&,
                                 const std::filesystem::path&);
template void write_line_samples(const Simulation<3>&, const std::vector<LineSample>&,
                                 const std::filesystem::path&);

} // namespace fddem
