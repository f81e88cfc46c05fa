// SPDX-License-Identifier: MIT
// The VTK RectilinearGrid file reads back: extents, coordinates and the raw appended data.

#include "fddem/grid/loops.hpp"
#include "fddem/io/vtk_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <utility>

namespace fddem {
namespace {

namespace fs = std::filesystem;

/// The Float64 array stored at `offset` in the appended block of a .vtr file.
std::vector<double> appended_array(const std::string& file, std::uint64_t offset)
{
    const std::size_t start = file.find("<AppendedData encoding=\"raw\">");
    const std::size_t underscore = file.find('_', start);
    const char* base = file.data() + underscore + 1 + offset;
    std::uint64_t n_bytes = 0;
    std::memcpy(&n_bytes, base, sizeof n_bytes);
    std::vector<double> values(n_bytes / sizeof(double));
    std::memcpy(values.data(), base + sizeof n_bytes, n_bytes);
    return values;
}

std::uint64_t offset_of(const std::string& file, const std::string& name)
{
    const std::regex pattern("Name=\"" + name + "\"[^>]*offset=\"([0-9]+)\"");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(file, match, pattern)) << name;
    return std::stoull(match[1].str());
}

TEST(VtkWriter, RectilinearGridReadsBackExactly)
{
    const MacGrid<2> grid({4, 3}, Vec<2>(1.0, -1.0), Vec<2>(2.0, 1.5));
    FaceField<2> u(grid);
    CellField<2> p(grid);
    for_each_index(grid.storage_box(), [&](const Index<2>& c) {
        u[0](c) = 1.0 + c[0];
        u[1](c) = -2.0;
        p(c) = 10.0 * c[0] + c[1];
    });
    const fs::path path = fs::temp_directory_path() / "fddem_test_fields.vtr";
    write_vtr(path, grid, u, p);
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string file = buffer.str();
    fs::remove(path);

    EXPECT_NE(file.find("WholeExtent=\"0 4 0 3 0 0\""), std::string::npos);
    const std::vector<double> x = appended_array(file, offset_of(file, "x"));
    ASSERT_EQ(x.size(), 5U);
    EXPECT_DOUBLE_EQ(x.front(), 1.0);
    EXPECT_DOUBLE_EQ(x.back(), 3.0);
    const std::vector<double> pressure = appended_array(file, offset_of(file, "p"));
    ASSERT_EQ(pressure.size(), 12U);
    EXPECT_DOUBLE_EQ(pressure[1 + 4 * 2], 12.0); // cell (1, 2), x fastest
    const std::vector<double> velocity = appended_array(file, offset_of(file, "velocity"));
    ASSERT_EQ(velocity.size(), 36U);
    EXPECT_DOUBLE_EQ(velocity[3 * 1 + 0], 2.5); // cell (1, 0): mean of u faces 2 and 3
    EXPECT_DOUBLE_EQ(velocity[3 * 1 + 1], -2.0);
    EXPECT_DOUBLE_EQ(velocity[3 * 1 + 2], 0.0);
}

/// The text of the file at `path`, which is removed.
std::string read_and_remove(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    in.close();
    fs::remove(path);
    return buffer.str();
}

/// u and p of `grid` over its whole storage (ghosts too) from the global index alone, so a
/// block's arrays hold what the whole grid's hold at the same indices.
void fill_by_index(const MacGrid<2>& grid, FaceField<2>& u, CellField<2>& p)
{
    for_each_index(grid.storage_box(), [&](const Index<2>& c) {
        u[0](c) = 1.0 + c[0] * c[0] - 0.5 * c[1];
        u[1](c) = 0.25 * c[0] * c[1] - 2.0;
        p(c) = 10.0 * c[0] + c[1];
    });
}

/// The .vtr of `grid` with fill_by_index's fields (the cells the grid owns): its text, and the
/// arrays write_vtr says it wrote.
std::pair<std::string, std::vector<VtkArray>> filled_vtr(const MacGrid<2>& grid)
{
    FaceField<2> u(grid);
    CellField<2> p(grid);
    fill_by_index(grid, u, p);
    const fs::path path = fs::temp_directory_path() / "fddem_test_piece.vtr";
    std::vector<VtkArray> arrays = write_vtr(path, grid, u, p);
    return {read_and_remove(path), std::move(arrays)};
}

/// The named Float64 arrays of a .vtr, in file order, with their components.
std::vector<std::pair<std::string, std::string>> cell_data_arrays(const std::string& file)
{
    const std::string cell_data =
        file.substr(file.find("<CellData"), file.find("</CellData>") - file.find("<CellData"));
    const std::regex array("Name=\"(\\w+)\"( NumberOfComponents=\"[0-9]\")?");
    std::vector<std::pair<std::string, std::string>> arrays;
    for (auto it = std::sregex_iterator(cell_data.begin(), cell_data.end(), array);
         it != std::sregex_iterator(); ++it) {
        arrays.emplace_back((*it)[1].str(), (*it)[2].str());
    }
    return arrays;
}

TEST(VtkWriter, PointExtentOfCellsSharesTheNodePlanesOfNeighbours)
{
    // Cells [2, 5) × [0, 3) lie between nodes 2..5 and 0..3; the block above along x,
    // cells [5, 9), starts at node 5: the node plane between them is in both extents, no cell.
    EXPECT_EQ(point_extent<2>(Box<2>{{2, 0}, {5, 3}}), (VtkExtent{2, 5, 0, 3, 0, 0}));
    EXPECT_EQ(point_extent<2>(Box<2>{{5, 0}, {9, 3}}), (VtkExtent{5, 9, 0, 3, 0, 0}));
    EXPECT_EQ(point_extent<3>(Box<3>{{0, 1, 2}, {4, 5, 6}}), (VtkExtent{0, 4, 1, 5, 2, 6}));
}

TEST(VtkWriter, BlockPiecesTileTheWholeGridWithItsValues)
{
    // The 2 × 2 blocks a split run on four ranks writes (the block of each rank, made here on
    // one process): each piece holds its block's cells with the values the whole file has
    // there, its node coordinates, the whole grid's WholeExtent, and the arrays of the whole
    // file; the pieces' cells cover the grid once.
    const Index<2> cells{7, 5};
    const Vec<2> origin(1.0, -1.0);
    const Vec<2> length(3.5, 1.5);
    const MacGrid<2> whole(cells, origin, length);
    const auto [whole_file, whole_arrays] = filled_vtr(whole);
    const std::vector<double> p_all = appended_array(whole_file, offset_of(whole_file, "p"));
    const std::vector<double> w_all =
        appended_array(whole_file, offset_of(whole_file, "vorticity"));

    std::vector<int> covered(whole.n_cells(), 0);
    std::vector<VtkPiece> pieces;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            GridPartition<2> partition{.communicator = Communicator::self(),
                                       .ranks = {2, 2},
                                       .coords = {i, j},
                                       .block = {},
                                       .neighbours = {}};
            const auto [x_lo, x_hi] = block_range(cells[0], 2, i);
            const auto [y_lo, y_hi] = block_range(cells[1], 2, j);
            partition.block = Box<2>{{x_lo, y_lo}, {x_hi, y_hi}};
            const MacGrid<2> block(cells, origin, length, {false, false}, partition);
            const auto [file, arrays] = filled_vtr(block);

            const VtkExtent extent{x_lo, x_hi, y_lo, y_hi, 0, 0};
            EXPECT_NE(file.find("<RectilinearGrid WholeExtent=\"0 7 0 5 0 0\">"),
                      std::string::npos);
            EXPECT_NE(file.find(fmt::format("<Piece Extent=\"{} {} {} {} 0 0\">", x_lo, x_hi, y_lo,
                                            y_hi)),
                      std::string::npos);
            EXPECT_EQ(cell_data_arrays(file), cell_data_arrays(whole_file));
            ASSERT_EQ(arrays.size(), whole_arrays.size());
            const std::vector<double> x = appended_array(file, offset_of(file, "x"));
            ASSERT_EQ(x.size(), static_cast<std::size_t>(x_hi - x_lo + 1));
            EXPECT_DOUBLE_EQ(x.front(), origin[0] + x_lo * 0.5);
            EXPECT_DOUBLE_EQ(x.back(), origin[0] + x_hi * 0.5);
            const std::vector<double> piece_p = appended_array(file, offset_of(file, "p"));
            const std::vector<double> piece_w = appended_array(file, offset_of(file, "vorticity"));
            ASSERT_EQ(piece_p.size(), partition.block.size());
            std::size_t k = 0;
            for_each_cell_in_vtk_order(partition.block, [&](const Index<2>& c) {
                const auto at = static_cast<std::size_t>(c[0] + cells[0] * c[1]);
                EXPECT_EQ(piece_p[k], p_all[at]);
                EXPECT_EQ(piece_w[k], w_all[at]) << "vorticity reads ghosts across the block";
                ++covered[at];
                ++k;
            });
            pieces.push_back({extent, fmt::format("piece_{}.vtr", pieces.size())});
        }
    }
    EXPECT_EQ(std::count(covered.begin(), covered.end(), 1),
              static_cast<std::ptrdiff_t>(covered.size()));

    // The master lists the whole extent, the whole file's arrays and each piece's extent.
    const fs::path master = fs::temp_directory_path() / "fddem_test_fields.pvtr";
    write_pvtr(master, point_extent(whole.cell_box()), whole_arrays, pieces);
    const std::string text = read_and_remove(master);
    EXPECT_NE(text.find("<VTKFile type=\"PRectilinearGrid\""), std::string::npos);
    EXPECT_NE(text.find("<PRectilinearGrid WholeExtent=\"0 7 0 5 0 0\" GhostLevel=\"0\">"),
              std::string::npos);
    EXPECT_NE(text.find("<PDataArray type=\"Float64\" Name=\"velocity\" "
                        "NumberOfComponents=\"3\"/>\n      <PDataArray type=\"Float64\" "
                        "Name=\"p\"/>\n      <PDataArray type=\"Float64\" Name=\"vorticity\"/>"),
              std::string::npos);
    EXPECT_NE(text.find("<Piece Extent=\"0 4 0 3 0 0\" Source=\"piece_0.vtr\"/>"),
              std::string::npos);
    EXPECT_NE(text.find("<Piece Extent=\"4 7 3 5 0 0\" Source=\"piece_3.vtr\"/>"),
              std::string::npos);
}

TEST(VtkWriter, ParticleMasterListsTheArraysOfItsPieces)
{
    const fs::path piece = fs::temp_directory_path() / "fddem_test_piece.vtp";
    ParticlePoints rankless; // a rank whose block holds no body centre
    rankless.vectors = {{"contact_force", {}}};
    const std::vector<VtkArray> arrays = write_vtp(piece, rankless);
    const std::string file = read_and_remove(piece);
    EXPECT_NE(file.find("NumberOfPoints=\"0\""), std::string::npos); // a rank without bodies
    const fs::path master = fs::temp_directory_path() / "fddem_test_particles.pvtp";
    write_pvtp(master, arrays, {{{}, "a/a_0000.vtp"}, {{}, "a/a_0001.vtp"}});
    const std::string text = read_and_remove(master);
    for (const VtkArray& array : arrays) {
        EXPECT_NE(file.find(fmt::format("Name=\"{}\"", array.name)), std::string::npos);
    }
    for (const char* expected :
         {"<VTKFile type=\"PPolyData\"", "<PDataArray type=\"Float64\" Name=\"id\"/>",
          "<PDataArray type=\"Float64\" Name=\"orientation\" NumberOfComponents=\"4\"/>",
          "<PDataArray type=\"Float64\" Name=\"contact_force\" NumberOfComponents=\"3\"/>",
          "<PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>",
          "<Piece Source=\"a/a_0000.vtp\"/>\n    <Piece Source=\"a/a_0001.vtp\"/>"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << expected;
    }
}

TEST(VtkWriter, ParticlePolyDataReadsBackExactly)
{
    const fs::path path = fs::temp_directory_path() / "fddem_test_particles.vtp";
    write_vtp(
        path,
        ParticlePoints{.ids = {4.0, 9.0},
                       .centres = {{1.0, 2.0, 0.0}, {3.0, 4.5, 0.0}},
                       .radii = {0.125, 0.25},
                       .velocities = {{0.5, -1.0, 0.0}, {0.0, 2.0, 0.0}},
                       .angular_velocities = {{0.0, 0.0, 3.0}, {0.0, 0.0, -1.0}},
                       .orientations = {{1.0, 0.0, 0.0, 0.0}, {0.5, 0.5, 0.5, 0.5}},
                       .body_axes = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}},
                       .vectors = {{"contact_force", {{1.5, 0.0, -2.0}, {0.0, 0.0, 0.0}}},
                                   {"lubrication_force", {{0.0, 0.25, 0.0}, {-0.5, 0.0, 0.125}}}}});
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string file = buffer.str();
    fs::remove(path);

    EXPECT_NE(file.find("NumberOfPoints=\"2\" NumberOfVerts=\"2\""), std::string::npos);
    const std::regex points("<Points>\\s*<DataArray[^>]*offset=\"([0-9]+)\"");
    std::smatch match;
    ASSERT_TRUE(std::regex_search(file, match, points));
    const std::vector<double> centres = appended_array(file, std::stoull(match[1].str()));
    EXPECT_EQ(centres, (std::vector<double>{1.0, 2.0, 0.0, 3.0, 4.5, 0.0}));
    EXPECT_EQ(appended_array(file, offset_of(file, "radius")), (std::vector<double>{0.125, 0.25}));
    const std::vector<double> velocity = appended_array(file, offset_of(file, "velocity"));
    EXPECT_EQ(velocity, (std::vector<double>{0.5, -1.0, 0.0, 0.0, 2.0, 0.0}));
    const std::vector<double> spin = appended_array(file, offset_of(file, "angular_velocity"));
    EXPECT_DOUBLE_EQ(spin[2], 3.0);
    EXPECT_DOUBLE_EQ(spin[5], -1.0);
    EXPECT_EQ(appended_array(file, offset_of(file, "id")), (std::vector<double>{4.0, 9.0}));
    EXPECT_EQ(appended_array(file, offset_of(file, "orientation")),
              (std::vector<double>{1.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5}));
    EXPECT_EQ(appended_array(file, offset_of(file, "body_axis")),
              (std::vector<double>{1.0, 0.0, 0.0, 0.0, 1.0, 0.0}));
    EXPECT_EQ(appended_array(file, offset_of(file, "contact_force")),
              (std::vector<double>{1.5, 0.0, -2.0, 0.0, 0.0, 0.0}));
    EXPECT_EQ(appended_array(file, offset_of(file, "lubrication_force")),
              (std::vector<double>{0.0, 0.25, 0.0, -0.5, 0.0, 0.125}));
    // Vertex cells: Int64 connectivity 0, 1 and offsets 1, 2 (read as raw bytes).
    const std::uint64_t at = offset_of(file, "offsets");
    const char* base = file.data() + file.find('_', file.find("<AppendedData")) + 1 + at;
    std::int64_t second_end = 0;
    std::memcpy(&second_end, base + sizeof(std::uint64_t) + sizeof(std::int64_t),
                sizeof second_end);
    EXPECT_EQ(second_end, 2);
}

TEST(VtkWriter, CollectionListsFramesInOrder)
{
    const fs::path path = fs::temp_directory_path() / "fddem_test_fields.pvd";
    PvdCollection pvd(path);
    pvd.add(0.0, "fields/fields_000000.vtr");
    pvd.add(0.5, "fields/fields_000001.vtr");
    std::ifstream in(path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    fs::remove(path);
    const auto first = text.find("timestep=\"0\" part=\"0\" file=\"fields/fields_000000.vtr\"");
    const auto second = text.find("timestep=\"0.5\" part=\"0\" file=\"fields/fields_000001.vtr\"");
    EXPECT_NE(first, std::string::npos);
    EXPECT_NE(second, std::string::npos);
    EXPECT_LT(first, second);
}

} // namespace
} // namespace fddem
