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

/// The NumberOfComponents attribute, left out for one component (VTK's default).
std::string components_attribute(int n_components)
{
    return n_components == 1 ? std::string()
                             : fmt::format(" NumberOfComponents=\"{}\"", n_components);
}

/// Appends one named Float64 array to `data` and returns its XML tag.
std::string appended_array(Appended& data, const VtkArray& array, const std::vector<double>& values)
{
    return fmt::format("        <DataArray type=\"Float64\" Name=\"{}\"{} format=\"appended\" "
                       "offset=\"{}\"/>\n",
                       array.name, components_attribute(array.n_components), data.add(values));
}

/// The arrays of a parallel master file: each array's name, type and components, which its
/// pieces hold (the data stay in the pieces).
std::string master_arrays(const std::vector<VtkArray>& arrays)
{
    std::string text;
    for (const VtkArray& array : arrays) {
        text += fmt::format("      <PDataArray type=\"Float64\" Name=\"{}\"{}/>\n", array.name,
                            components_attribute(array.n_components));
    }
    return text;
}

/// An extent as VTK writes it: "x0 x1 y0 y1 z0 z1".
std::string extent_text(const VtkExtent& extent)
{
    return fmt::format("{} {} {} {} {} {}", extent[0], extent[1], extent[2], extent[3], extent[4],
                       extent[5]);
}

/// The first line and the VTKFile element of every file written here, of `type`.
std::string file_header(const std::string& type)
{
    return fmt::format("<?xml version=\"1.0\"?>\n<VTKFile type=\"{}\" version=\"1.0\" "
                       "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n",
                       type);
}

} // namespace

template <int Dim>
VtkExtent point_extent(const Box<Dim>& cells)
{
    VtkExtent extent{0, 0, 0, 0, 0, 0};
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        extent.at(2 * d) = cells.lo[d];
        extent.at(2 * d + 1) = cells.hi[d];
    }
    return extent;
}

template <int Dim>
std::vector<VtkArray> write_vtr(const std::filesystem::path& path, const MacGrid<Dim>& grid,
                                const FaceField<Dim>& u, const CellField<Dim>& p)
{
    const Box<Dim> cells = grid.owned_cells();
    // Cell values in VTK order (x fastest), gathered from the padded layout.
    const auto gather = [&](const CellField<Dim>& field) {
        std::vector<double> out;
        out.reserve(cells.size());
        for_each_cell_in_vtk_order(cells, [&](const Index<Dim>& c) { out.push_back(field(c)); });
        return out;
    };
    Appended data;
    std::string arrays;
    std::vector<VtkArray> written;
    const auto add = [&](const VtkArray& array, const std::vector<double>& values) {
        arrays += appended_array(data, array, values);
        written.push_back(array);
    };

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
    add({"velocity", 3}, interleaved);
    add({"p", 1}, gather(p));
    CellField<Dim> vorticity(grid);
    if constexpr (Dim == 2) {
        cell_centred_vorticity(grid, u, 0, 1, vorticity);
        add({"vorticity", 1}, gather(vorticity));
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
        add({"vorticity", 3}, vector_values);
    }

    // The nodes of the owned cells: a piece shares its boundary node planes with its
    // neighbours, while its cells, and their data, are its own.
    const VtkExtent extent = point_extent(cells);
    std::string coordinates;
    for (std::size_t d = 0; d < 3; ++d) {
        std::vector<double> nodes;
        if (d < static_cast<std::size_t>(Dim)) {
            const int axis = static_cast<int>(d);
            for (int i = extent.at(2 * d); i <= extent.at(2 * d + 1); ++i) {
                nodes.push_back(grid.origin()[axis] + i * grid.spacing(axis));
            }
        } else {
            nodes.push_back(0.0);
        }
        coordinates += appended_array(data, {std::string(1, "xyz"[d]), 1}, nodes);
    }
    std::string text = file_header("RectilinearGrid");
    text += fmt::format("  <RectilinearGrid WholeExtent=\"{}\">\n    <Piece Extent=\"{}\">\n",
                        extent_text(point_extent(grid.cell_box())), extent_text(extent));
    text += "      <CellData Scalars=\"p\" Vectors=\"velocity\">\n" + arrays +
            "      </CellData>\n      <Coordinates>\n" + coordinates +
            "      </Coordinates>\n    </Piece>\n  </RectilinearGrid>\n"
            "  <AppendedData encoding=\"raw\">\n   _";
    text += data.bytes;
    text += "\n  </AppendedData>\n</VTKFile>\n";
    write_file_atomically(path, text);
    return written;
}

void write_pvtr(const std::filesystem::path& path, const VtkExtent& whole,
                const std::vector<VtkArray>& cell_arrays, const std::vector<VtkPiece>& pieces)
{
    std::string text = file_header("PRectilinearGrid");
    text += fmt::format("  <PRectilinearGrid WholeExtent=\"{}\" GhostLevel=\"0\">\n",
                        extent_text(whole));
    text += "    <PCellData Scalars=\"p\" Vectors=\"velocity\">\n" + master_arrays(cell_arrays) +
            "    </PCellData>\n    <PCoordinates>\n" +
            master_arrays({{"x", 1}, {"y", 1}, {"z", 1}}) + "    </PCoordinates>\n";
    for (const VtkPiece& piece : pieces) {
        text += fmt::format("    <Piece Extent=\"{}\" Source=\"{}\"/>\n", extent_text(piece.extent),
                            piece.source);
    }
    text += "  </PRectilinearGrid>\n</VTKFile>\n";
    write_file_atomically(path, text);
}

std::vector<VtkArray> write_vtp(const std::filesystem::path& path, const ParticlePoints& bodies)
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
    std::string point_data;
    std::vector<VtkArray> written;
    const auto add = [&](const VtkArray& array, const std::vector<double>& values) {
        point_data += appended_array(data, array, values);
        written.push_back(array);
    };
    add({"id", 1}, bodies.ids);
    add({"radius", 1}, bodies.radii);
    add({"velocity", 3}, flatten(bodies.velocities));
    add({"angular_velocity", 3}, flatten(bodies.angular_velocities));
    add({"orientation", 4}, flatten(bodies.orientations));
    add({"body_axis", 3}, flatten(bodies.body_axes));
    for (const auto& [name, values] : bodies.vectors) {
        add({name, 3}, flatten(values));
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
    std::string text = file_header("PolyData") + "  <PolyData>\n";
    text += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" "
                        "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                        n, n);
    text += "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n" + point_data +
            "      </PointData>\n";
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
    return written;
}

void write_pvtp(const std::filesystem::path& path, const std::vector<VtkArray>& point_arrays,
                const std::vector<VtkPiece>& pieces)
{
    std::string text = file_header("PPolyData") + "  <PPolyData GhostLevel=\"0\">\n";
    text += "    <PPointData Scalars=\"radius\" Vectors=\"velocity\">\n" +
            master_arrays(point_arrays) +
            "    </PPointData>\n    <PPoints>\n"
            "      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (const VtkPiece& piece : pieces) {
        text += fmt::format("    <Piece Source=\"{}\"/>\n", piece.source);
    }
    text += "  </PPolyData>\n</VTKFile>\n";
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

template VtkExtent point_extent<2>(const Box<2>&);
template VtkExtent point_extent<3>(const Box<3>&);
template std::vector<VtkArray> write_vtr<2>(const std::filesystem::path&, const MacGrid<2>&,
                                            const FaceField<2>&, const CellField<2>&);
template std::vector<VtkArray> write_vtr<3>(const std::filesystem::path&, const MacGrid<3>&,
                                            const FaceField<3>&, const CellField<3>&);

} // namespace fddem
