// SPDX-License-Identifier: MIT
// The VTK RectilinearGrid file reads back: extents, coordinates and the raw appended data.

#include "fddem/grid/loops.hpp"
#include "fddem/io/vtk_writer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

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
