// SPDX-License-Identifier: MIT
// The bodies of [[bodies]] entries (io/body_entries.hpp, io/body_file.hpp): read from a CSV file
// in 2D and 3D, inserted at random, mixed with bodies given one by one; and every kind of bad
// body file or entry stops with one InputError naming the file, the line and the column (key).

#include "fddem/bodies/ball.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

#include "support/case_text.hpp"
#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

using test::replace;

namespace fs = std::filesystem;

/// A 3D box of 16³ cells (h = 1/16: bodies of diameter ≥ 0.25 are resolved), walls all round.
const std::string box_3d = R"([domain]
size = [1.0, 1.0, 1.0]
cells = [16, 16, 16]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, 0.0, -9.81]
[time]
dt = 0.01
end = 0.1
)";

const std::string box_2d = R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -9.81]
[time]
dt = 0.01
end = 0.1
)";

/// Line 13 of the case: `file = "spheres.csv"`.
const std::string file_entry_3d = box_3d + R"([[bodies]]
shape = "sphere"
file = "spheres.csv"
friction = 0.3
)";

const std::string spheres_csv = R"(# three spheres, x y z in m
id, x, y, z, diameter, density, u, v, w
3, 0.25, 0.25, 0.25, 0.25, 2.5, 0.1, 0.0, 0.0
7, 0.75, 0.25, 0.25, 0.3, 2.0, 0.0, 0.0, -0.1
1, 0.5, 0.7, 0.6, 0.25, 3.0, 0, 0, 0
)";

class BodyEntries : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::fresh_test_directory("fddem_body_entries_"); }
    void TearDown() override { fs::remove_all(dir_); }

    /// Writes the case (and the body file, if any) and reads the case.
    CaseConfig read(const std::string& case_text, const std::string& csv = "",
                    const std::vector<std::string>& overrides = {}) const
    {
        std::ofstream(dir_ / "case.toml") << case_text;
        if (!csv.empty()) {
            std::ofstream(dir_ / "spheres.csv") << csv;
        }
        return read_case((dir_ / "case.toml").string(), overrides);
    }

    fs::path dir_;
};

TEST_F(BodyEntries, ThreeDimensionalFileGivesItsBodiesWithTheEntrysKeys)
{
    const CaseConfig c = read(file_entry_3d, spheres_csv);
    ASSERT_EQ(c.bodies.size(), 3U);
    const BodyConfig& b = c.bodies[1];
    EXPECT_EQ(b.id, 7);
    EXPECT_EQ(b.position, (std::vector<double>{0.75, 0.25, 0.25}));
    EXPECT_EQ(b.diameter, 0.3);
    EXPECT_EQ(b.density, 2.0);
    EXPECT_EQ(b.velocity, (std::vector<double>{0.0, 0.0, -0.1}));
    EXPECT_EQ(b.shape, BodyShape::sphere);
    EXPECT_EQ(b.material.friction, 0.3); // the entry's surface key, for every row
    EXPECT_EQ(b.file_line, 4);
    EXPECT_EQ(c.bodies[0].id, 3);
    EXPECT_EQ(c.bodies[0].velocity, (std::vector<double>{0.1, 0.0, 0.0}));
    EXPECT_EQ(c.bodies[2].id, 1);
    EXPECT_EQ(c.bodies[2].density, 3.0);
    // The DEM reference is the lightest free body: 3 of 0.25 at ρ = 2.5 (m = ρ π D³/6).
    EXPECT_NEAR(c.contact.derived.reference_mass, 2.5 * std::numbers::pi * std::pow(0.25, 3) / 6,
                1e-15);
}

TEST_F(BodyEntries, TwoDimensionalFileInAnyColumnOrderTakesTheEntrysVelocity)
{
    const std::string text = box_2d + R"([[bodies]]
diameter = 0.3
density = 1.5
position = [0.2, 0.8]
[[bodies]]
file = "spheres.csv"
velocity = [0.0, -0.5]
motion = "prescribed"
)";
    const CaseConfig c = read(text, "x,y,id,diameter,density\r\n0.7,0.3,10,0.25,1.2\r\n"
                                    "0.3,0.3,4,0.28,1.1\r\n");
    ASSERT_EQ(c.bodies.size(), 3U);
    EXPECT_EQ(c.bodies[0].id, 0); // given one by one: numbered from 0
    EXPECT_EQ(c.bodies[1].id, 10);
    EXPECT_EQ(c.bodies[1].position, (std::vector<double>{0.7, 0.3}));
    EXPECT_EQ(c.bodies[1].diameter, 0.25);
    EXPECT_EQ(c.bodies[1].density, 1.2);
    EXPECT_EQ(c.bodies[1].velocity, (std::vector<double>{0.0, -0.5}));
    EXPECT_EQ(c.bodies[1].motion, Motion::prescribed);
    EXPECT_EQ(c.bodies[2].id, 4);
    EXPECT_EQ(c.bodies[2].shape, BodyShape::disk);
}

TEST_F(BodyEntries, EntriesAfterAFileNumberOnFromItsLargestId)
{
    const std::string text = file_entry_3d + R"([[bodies]]
shape = "sphere"
diameter = 0.25
density = 2.0
position = [0.25, 0.75, 0.75]
)";
    const CaseConfig c = read(text, spheres_csv);
    ASSERT_EQ(c.bodies.size(), 4U);
    EXPECT_EQ(c.bodies[3].id, 8);
}

TEST_F(BodyEntries, CaseAsRunNamesTheFileAbsolutelyAndReadsBackAnywhere)
{
    const CaseConfig first = read(file_entry_3d, spheres_csv);
    EXPECT_NE(first.as_run.find((dir_ / "spheres.csv").string()), std::string::npos)
        << first.as_run;
    fs::create_directories(dir_ / "run");
    std::ofstream(dir_ / "run" / "case.toml") << first.as_run;
    const CaseConfig second = read_case((dir_ / "run" / "case.toml").string());
    ASSERT_EQ(second.bodies.size(), 3U);
    EXPECT_EQ(second.bodies[2].position, first.bodies[2].position);
    EXPECT_EQ(second.bodies[2].id, 1);
}

// ---- random insertion

/// A 3D random insertion of spheres of diameter 0.25 in the region [0,1]×[0,1]×[0.25,1].
std::string random_entry(const std::string& keys)
{
    return box_3d + R"([[bodies]]
shape = "sphere"
diameter = 0.25
density = 2.0
position = [0.5, 0.5, 0.125]
motion = "fixed"
[[bodies]]
shape = "sphere"
diameter = 0.25
density = 2.0
region_low = [0.0, 0.0, 0.25]
)" + keys;
}

TEST_F(BodyEntries, RandomInsertionFillsTheVolumeFractionClearOfOthersAndReproducibly)
{
    const double gap = 0.01;
    const std::string text = random_entry("volume_fraction = 0.2\nseed = 7\ngap = 0.01\n");
    const CaseConfig c = read(text);
    const double region = 0.75;
    const double body = Ball<3>{0.25}.volume();
    const auto n = static_cast<double>(c.bodies.size() - 1);
    // Within half a body's volume of the fraction asked (it rounds to whole bodies).
    EXPECT_LE(std::abs(n * body - 0.2 * region), 0.5 * body);
    EXPECT_EQ(n, 18.0); // 0.2 · 0.75 / 0.00818 = 18.3
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t a = 1; a < c.bodies.size(); ++a) {
        const BodyConfig& b = c.bodies[a];
        EXPECT_EQ(b.id, static_cast<int>(a)); // after the fixed body's 0
        for (std::size_t d = 0; d < 3; ++d) {
            EXPECT_GE(b.position[d] - 0.125, (d == 2 ? 0.25 : 0.0) + gap);
            EXPECT_LE(b.position[d] + 0.125, 1.0 - gap);
        }
        for (std::size_t o = 0; o < a; ++o) {
            double distance2 = 0.0;
            for (std::size_t d = 0; d < 3; ++d) {
                distance2 += std::pow(b.position[d] - c.bodies[o].position[d], 2);
            }
            least = std::min(least, std::sqrt(distance2));
        }
    }
    EXPECT_GE(least, 0.25 + gap * (1.0 - 1e-12)); // also clear of the fixed body
    const CaseConfig again = read(text);
    EXPECT_EQ(again.bodies.back().position, c.bodies.back().position);
    const CaseConfig back = read_case_string(c.as_run, "case.toml");
    EXPECT_EQ(back.bodies.back().position, c.bodies.back().position);
    const CaseConfig other = read(text, "", {"bodies.2.seed=8"});
    EXPECT_NE(other.bodies.back().position, c.bodies.back().position);
}

TEST_F(BodyEntries, RandomInsertionWithoutSeedRecordsSeedZero)
{
    const CaseConfig c = read(random_entry("count = 3\n"));
    EXPECT_EQ(c.bodies.size(), 4U);
    EXPECT_NE(c.as_run.find("seed = 0"), std::string::npos) << c.as_run;
}

// ---- bad input

struct BadBodies {
    const char* name;
    std::string case_text;
    std::string csv;     ///< "" : no body file written
    std::string file;    ///< the expected file name (case.toml or spheres.csv)
    int line;            ///< expected line (0: none)
    std::string key;     ///< expected key or column
    std::string message; ///< expected substring
};

const std::string header_3d = "id, x, y, z, diameter, density\n";

std::vector<BadBodies> bad_bodies()
{
    const std::string f = file_entry_3d;
    const std::string csv = "spheres.csv";
    const std::string row = "1, 0.5, 0.5, 0.5, 0.25, 2.0\n";
    return {
        {"missing_file", replace(f, "spheres.csv", "nope.csv"), "", "case.toml", 13, "bodies.file",
         "no such file"},
        {"file_is_a_directory", replace(f, "spheres.csv", "."), "", "case.toml", 13, "bodies.file",
         "is a directory"},
        {"empty_file", f, "\n# nothing\n", csv, 0, "", "has no header line"},
        {"header_only", f, header_3d, csv, 0, "", "has a header but no bodies"},
        {"unknown_column", f, "id, x, y, z, radius, density\n" + row, csv, 1, "",
         "column 5: unknown column 'radius'"},
        {"missing_column", f, "id, x, y, z, density\n1, 0.5, 0.5, 0.5, 2.0\n", csv, 1, "",
         "no 'diameter' column"},
        {"column_twice", f, "id, x, y, z, x, diameter, density\n" + row, csv, 1, "",
         "column 5: 'x' is named twice"},
        {"some_velocity_columns", f, "id, x, y, z, diameter, density, u, v\n" + row, csv, 1, "",
         "the velocity columns come all or none"},
        {"z_in_2d", box_2d + "[[bodies]]\nfile = \"spheres.csv\"\n",
         "id, x, y, z, diameter, density\n1, 0.5, 0.5, 0.5, 0.3, 2.0\n", csv, 1, "",
         "column 4: unknown column 'z'"},
        {"too_few_values", f, header_3d + row + "2, 0.5, 0.5, 0.25, 2.0\n", csv, 3, "",
         "has 5 values; the header has 6 columns"},
        {"not_a_number", f, header_3d + "1, 0.5, abc, 0.5, 0.25, 2.0\n", csv, 2, "y",
         "'abc' is not a number"},
        {"empty_value", f, header_3d + "1, 0.5, 0.5, 0.5, , 2.0\n", csv, 2, "diameter",
         "empty value"},
        {"nan", f, header_3d + "1, 0.5, 0.5, nan, 0.25, 2.0\n", csv, 2, "z",
         "must be a finite number, got 'nan'"},
        {"infinity", f, header_3d + "1, inf, 0.5, 0.5, 0.25, 2.0\n", csv, 2, "x",
         "must be a finite number, got 'inf'"},
        {"beyond_double", f, header_3d + "1, 0.5, 0.5, 0.5, 1e400, 2.0\n", csv, 2, "diameter",
         "'1e400' is out of the range of a double"},
        {"negative_diameter", f, header_3d + "1, 0.5, 0.5, 0.5, -0.25, 2.0\n", csv, 2, "diameter",
         "-0.25 is out of range: must be > 0"},
        {"zero_density", f, header_3d + "1, 0.5, 0.5, 0.5, 0.25, 0\n", csv, 2, "density",
         "0 is out of range: must be > 0"},
        {"negative_id", f, header_3d + "-1, 0.5, 0.5, 0.5, 0.25, 2.0\n", csv, 2, "id",
         "'-1' is not a valid id"},
        {"fractional_id", f, header_3d + "2.5, 0.5, 0.5, 0.5, 0.25, 2.0\n", csv, 2, "id",
         "'2.5' is not a valid id"},
        {"duplicate_id", f, header_3d + row + "# another\n1, 0.2, 0.2, 0.2, 0.25, 2.0\n", csv, 4,
         "id", "the id 1 is taken by the body of line 2"},
        {"id_of_an_earlier_entry",
         replace(f, "[[bodies]]\n",
                 "[[bodies]]\nshape = \"sphere\"\ndiameter = 0.25\ndensity = 2.0\nposition = "
                 "[0.2, 0.2, 0.2]\n[[bodies]]\n"),
         header_3d + "0, 0.7, 0.7, 0.7, 0.25, 2.0\n", csv, 2, "id",
         "the id 0 is taken by a body of an earlier [[bodies]] entry"},
        {"outside_the_box", f, header_3d + row + "2, 0.5, 0.9, 0.5, 0.25, 2.0\n", csv, 3, "y",
         "body id 2 reaches outside the box on axis 1 (centre 0.9, radius 0.125"},
        {"overlapping", f, header_3d + row + "# near\n2, 0.6, 0.6, 0.5, 0.25, 2.0\n", csv, 4,
         "x, y, z", "body id 2 overlaps body id 1 (line 2)"},
        {"too_small_for_the_grid", f, header_3d + "1, 0.5, 0.5, 0.5, 0.1, 2.0\n", csv, 2,
         "diameter", "body id 1 is 1.6 cells across"},
        {"position_with_a_file", replace(f, "friction", "position = [0.5, 0.5, 0.5]\nfriction"),
         header_3d + row, "case.toml", 14, "bodies.position",
         "the file gives each body's position, diameter and density"},
        {"file_with_density_ratio",
         replace(f, "viscosity = 0.01\n", "") +
             "[nondimensional]\nreynolds = 10.0\ndensity_ratio = 2.0\n",
         header_3d + row, "case.toml", 12, "bodies.file", "a file gives its bodies' densities"},
        {"file_and_count", replace(f, "friction", "count = 3\nfriction"), "", "case.toml", 13,
         "bodies.file", "from a file or at random"},
        {"position_missing",
         box_3d + "[[bodies]]\nshape = \"sphere\"\ndiameter = 0.25\ndensity = 2.0\n", "",
         "case.toml", 11, "bodies.position", "missing required key 'position' in [[bodies]]"},
        {"seed_without_random_insertion",
         box_3d + "[[bodies]]\nshape = \"sphere\"\ndiameter = 0.25\ndensity = 2.0\nposition = "
                  "[0.5, 0.5, 0.5]\nseed = 3\n",
         "", "case.toml", 16, "bodies.seed", "only a random insertion"},
        {"random_jammed_beyond_the_limit", random_entry("volume_fraction = 0.6\n"), "", "case.toml",
         22, "bodies.volume_fraction", "random sequential addition of spheres jams near 38.4 %"},
        {"random_jammed_in_a_small_region", random_entry("volume_fraction = 0.37\n"), "",
         "case.toml", 22, "bodies.volume_fraction", "then jammed"},
        {"random_region_outside_the_box",
         random_entry("count = 3\nregion_high = [1.0, 1.5, 1.0]\n"), "", "case.toml", 23,
         "bodies.region_high", "the region's upper corner is outside the box on axis 1"},
        {"random_region_too_thin", random_entry("count = 3\nregion_high = [1.0, 1.0, 0.4]\n"), "",
         "case.toml", 23, "bodies.region_high", "less than a body's diameter 0.25"},
        {"random_with_position", random_entry("count = 3\nposition = [0.5, 0.5, 0.5]\n"), "",
         "case.toml", 23, "bodies.position", "places its bodies itself"},
        {"random_count_and_fraction", random_entry("count = 3\nvolume_fraction = 0.1\n"), "",
         "case.toml", 23, "bodies.volume_fraction", "not both"},
        {"random_fraction_of_no_body", random_entry("volume_fraction = 0.001\n"), "", "case.toml",
         22, "bodies.volume_fraction", "holds no body"},
        // Refused before the insertion: a million bodies too small for the grid took 70 s and
        // 14 GB to place only to be refused by check_bodies.
        {"random_too_small_for_the_grid",
         replace(random_entry("count = 3\n"), "diameter = 0.25\ndensity = 2.0\nregion_low",
                 "diameter = 0.05\ndensity = 2.0\nregion_low"),
         "", "case.toml", 19, "bodies.diameter",
         "the spheres of a random insertion are 0.8 cells across; at least 4"},
        {"random_fraction_beyond_the_insertion_limit",
         "[domain]\nsize = [1.0, 1.0]\ncells = [8192, 8192]\n[fluid]\ndensity = 1.0\n"
         "viscosity = 0.01\n[time]\ndt = 0.001\nend = 0.01\n[[bodies]]\nshape = \"disk\"\n"
         "diameter = 0.0005\ndensity = 2.0\nvolume_fraction = 0.3\n",
         "", "case.toml", 14, "bodies.volume_fraction",
         "one random insertion places at most 1000000"},
    };
}

class BadBodyInput : public BodyEntries, public ::testing::WithParamInterface<BadBodies> {};

TEST_P(BadBodyInput, StopsWithOneClearMessage)
{
    const BadBodies& bad = GetParam();
    try {
        (void)read(bad.case_text, bad.csv);
        FAIL() << "no error for " << bad.name;
    } catch (const InputError& e) {
        EXPECT_EQ(fs::path(e.file()).filename().string(), bad.file) << e.formatted();
        EXPECT_EQ(e.line(), bad.line) << e.formatted();
        EXPECT_EQ(e.key(), bad.key) << e.formatted();
        EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.formatted();
    }
}

INSTANTIATE_TEST_SUITE_P(BodyEntries, BadBodyInput, ::testing::ValuesIn(bad_bodies()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST_F(BodyEntries, UnreadableFileNamesTheKey)
{
    if (::geteuid() == 0) {
        GTEST_SKIP() << "root reads any file";
    }
    std::ofstream(dir_ / "spheres.csv") << spheres_csv;
    fs::permissions(dir_ / "spheres.csv", fs::perms::none);
    try {
        (void)read(file_entry_3d);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "bodies.file") << e.formatted();
        EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos) << e.formatted();
    }
}

} // namespace
} // namespace fddem
