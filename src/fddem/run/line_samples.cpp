// SPDX-License-Identifier: MIT
#include "fddem/run/line_samples.hpp"

#include "fddem/grid/sampling.hpp"
#include "fddem/io/csv_history.hpp"
#include "fddem/run/csv_columns.hpp"

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
        write_csv(directory / "samples" / (line.name + ".csv"), columns,
                  sample_line(sim.grid(), sim.fluid().u, sim.fluid().p, from, to, line.n_points));
    }
}

template std::vector<std::string> sample_columns<2>();
template std::vector<std::string> sample_columns<3>();
template void write_line_samples(const Simulation<2>&, const std::vector<LineSample>&,
                                 const std::filesystem::path&);
template void write_line_samples(const Simulation<3>&, const std::vector<LineSample>&,
                                 const std::filesystem::path&);

} // namespace fddem
