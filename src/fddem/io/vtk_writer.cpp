// SPDX-License-Identifier: MIT
#include "fddem/io/vtk_writer.hpp"

#include "fddem/grid/loops.hpp"
#include "fddem/grid/sampling.hpp"
#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>

namespace fddem {
namespace {

static_assert(sizeof(double) == 8, "VTK Float64 output needs 8-byte doubles");

struct Appended {
    std::string bytes;
    std::uint64_t offset = 0;

    /// Adds one array (with its UInt64 byte count) and returns its offset.
    template <class T>
    std::uint64_t add(const std::vector<T>& values)
    {
        const std::uint64_t at = bytes.size();
        const std::uint64_t n_bytes = values.size() * sizeof(T);
        bytes.append(reinterpret_cast<const char*>(&n_bytes), sizeof(n_bytes));
        bytes.append(reinterpret_cast<const char*>(values.data()), n_bytes);
        return at;
    }
};

} // namespace

template <int Dim>
void write_vtr(const std::filesystem::path& path, const MacGrid<Dim>& grid, const FaceField<Dim>& u,
               const CellField<Dim>& p)
{
    const Box<Dim> cells = grid.cell_box();
    // Cell values in VTK order (x fastest), gathered from the padded layout.
    const auto gather = [&](const CellField<Dim>& field) {
        std::vector<double> out;
        out.reserve(cells.size());
        for_each_cell_in_vtk_order(cells, [&](const Index<Dim>& c) { out.push_back(field(c)); });
        return out;
    };
    Appended data;
    std::string arrays;

    std::array<CellField<Dim>, Dim> velocity;
    for (int a = 0; a < Dim; ++a) {
        velocity[static_cast<std::size_t>(a)] = CellField<Dim>(grid);
        cell_centred_velocity(grid, u, a, velocity[static_cast<std::size_t>(a)]);
    }
    std::vector<double> interleaved;
    interleaved.reserve(3 * cells.size());
    for_each_cell_in_vtk_order(cells, [&](const Index<Dim>& c) {
        for (int a = 0; a < 3; ++a) {
            interleaved.push_back(a < Dim ? velocity[static_cast<std::size_t>(a)](c) : 0.0);
        }
    });
    arrays += fmt::format("        <DataArray type=\"Float64\" Name=\"velocity\" "
                          "NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n",
                          data.add(interleaved));
    arrays += fmt::format("        <DataArray type=\"Float64\" Name=\"p\" format=\"appended\" "
                          "offset=\"{}\"/>\n",
                          data.add(gather(p)));
    CellField<Dim> vorticity(grid);
    if constexpr (Dim == 2) {
        cell_centred_vorticity(grid, u, 0, 1, vorticity);
        arrays += fmt::format("        <DataArray type=\"Float64\" Name=\"vorticity\" "
                              "format=\"appended\" offset=\"{}\"/>\n",
                              data.add(gather(vorticity)));
    } else {
        std::array<std::vector<double>, 3> components;
        const int pairs[3][2] = {{1, 2}, {2, 0}, {0, 1}};
        for (int c = 0; c < 3; ++c) {
            cell_centred_vorticity(grid, u, pairs[c][0], pairs[c][1], vorticity);
            components[static_cast<std::size_t>(c)] = gather(vorticity);
        }
        std::vector<double> vector_values;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            for (int c = 0; c < 3; ++c) {
                vector_values.push_back(components[static_cast<std::size_t>(c)][k]);
            }
        }
        arrays += fmt::format("        <DataArray type=\"Float64\" Name=\"vorticity\" "
                              "NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n",
                              data.add(vector_values));
    }

    std::string coordinates;
    std::array<int, 3> extent{0, 0, 0};
    for (int d = 0; d < 3; ++d) {
        std::vector<double> nodes;
        if (d < Dim) {
            extent[static_cast<std::size_t>(d)] = grid.cells(d);
            for (int i = 0; i <= grid.cells(d); ++i) {
                nodes.push_back(grid.origin()[d] + i * grid.spacing(d));
            }
        } else {
            nodes.push_back(0.0);
        }
        coordinates += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" "
                                   "format=\"appended\" offset=\"{}\"/>\n",
                                   "xyz"[d], data.add(nodes));
    }
    const std::string whole = fmt::format("0 {} 0 {} 0 {}", extent[0], extent[1], extent[2]);
    std::string text = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"RectilinearGrid\" version=\"1.0\" "
                       "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
    text += fmt::format("  <RectilinearGrid WholeExtent=\"{}\">\n    <Piece Extent=\"{}\">\n",
                        whole, whole);
    text += "      <CellData Scalars=\"p\" Vectors=\"velocity\">\n" + arrays +
            "      </CellData>\n      <Coordinates>\n" + coordinates +
            "      </Coordinates>\n    </Piece>\n  </RectilinearGrid>\n"
            "  <AppendedData encoding=\"raw\">\n   _";
    text += data.bytes;
    text += "\n  </AppendedData>\n</VTKFile>\n";
    write_file_atomically(path, text);
}

void write_vtp(const std::filesystem::path& path, const ParticlePoints& bodies)
{
    const std::size_t n = bodies.centres.size();
    const auto flatten = [](const auto& v) {
        std::vector<double> out;
        for (const auto& x : v) {
            out.insert(out.end(), x.begin(), x.end());
        }
        return out;
    };
    Appended data;
    const std::uint64_t points = data.add(flatten(bodies.centres));
    const std::uint64_t id = data.add(bodies.ids);
    const std::uint64_t radius = data.add(bodies.radii);
    const std::uint64_t velocity = data.add(flatten(bodies.velocities));
    const std::uint64_t omega = data.add(flatten(bodies.angular_velocities));
    const std::uint64_t orientation = data.add(flatten(bodies.orientations));
    const std::uint64_t axis = data.add(flatten(bodies.body_axes));
    std::string vectors;
    for (const auto& [name, values] : bodies.vectors) {
        vectors += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" "
                               "NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n",
                               name, data.add(flatten(values)));
    }
    // One vertex cell per body so ParaView draws the centres without a filter.
    std::vector<std::int64_t> ids(n);
    std::vector<std::int64_t> ends(n);
    for (std::size_t k = 0; k < n; ++k) {
        ids[k] = static_cast<std::int64_t>(k);
        ends[k] = static_cast<std::int64_t>(k + 1);
    }
    const std::uint64_t connectivity = data.add(ids);
    const std::uint64_t offsets = data.add(ends);
    std::string text = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                       "header_type=\"UInt64\">\n  <PolyData>\n";
    text += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" "
                        "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                        n, n);
    text += fmt::format(
        "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n"
        "        <DataArray type=\"Float64\" Name=\"id\" format=\"appended\" offset=\"{}\"/>\n"
        "        <DataArray type=\"Float64\" Name=\"radius\" format=\"appended\" "
        "offset=\"{}\"/>\n"
        "        <DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
        "format=\"appended\" offset=\"{}\"/>\n"
        "        <DataArray type=\"Float64\" Name=\"angular_velocity\" "
        "NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n"
        "        <DataArray type=\"Float64\" Name=\"orientation\" "
        "NumberOfComponents=\"4\" format=\"appended\" offset=\"{}\"/>\n"
        "        <DataArray type=\"Float64\" Name=\"body_axis\" "
        "NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n"
        "{}"
        "      </PointData>\n",
        id, radius, velocity, omega, orientation, axis, vectors);
    text +=
        fmt::format("      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                    "format=\"appended\" offset=\"{}\"/>\n      </Points>\n",
                    points);
    text += fmt::format("      <Verts>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
                        "format=\"appended\" offset=\"{}\"/>\n        <DataArray type=\"Int64\" "
                        "Name=\"offsets\" format=\"appended\" offset=\"{}\"/>\n      </Verts>\n",
                        connectivity, offsets);
    text += "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
    text += data.bytes;
    text += "\n  </AppendedData>\n</VTKFile>\n";
    write_file_atomically(path, text);
}

void PvdCollection::add(double time, const std::string& relative_file)
{
    entries_.emplace_back(time, relative_file);
    write();
}

void PvdCollection::assign(std::vector<std::pair<double, std::string>> entries)
{
    entries_ = std::move(entries);
    write();
}

void PvdCollection::write() const
{
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n"
                       "  <Collection>\n";
    for (const auto& [t, file] : entries_) {
        text += fmt::format("    <DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", t, file);
    }
    text += "  </Collection>\n</VTKFile>\n";
    write_file_atomically(path_, text);
}

template void write_vtr<2>(const std::filesystem::path&, const MacGrid<2>&, const FaceField<2>&,
                           const CellField<2>&);
template void write_vtr<3>(const std::filesystem::path&, const MacGrid<3>&, const FaceField<3>&,
                           const CellField<3>&);

} // namespace fddem
