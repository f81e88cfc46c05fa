// SPDX-License-Identifier: MIT
// The case reader: a valid case reads to the expected values with defaults filled in, and
// every kind of bad input stops with an InputError naming the file, the line and the key.

#include "fddem/contact/hertz_mindlin.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/io/case_names.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/case_schema.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/case_text.hpp"
#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

using test::replace;

const std::string valid_case = R"([case]
title = "cavity"
[domain]
size = [1.0, 2.0]
cells = [16, 32]
[walls]
y_high = [1.0, 0.0]
[fluid]
density = 1.0
viscosity = 0.01
[time]
dt = 0.01
end = 1.0
[[output.lines]]
name = "vertical"
from = [0.5, 0.0]
to = [0.5, 2.0]
)";

TEST(CaseReader, ValidCaseReadsWithDefaultsFilledIn)
{
    const CaseConfig c = read_case_string(valid_case, "valid.toml");
    EXPECT_EQ(c.domain.dimension, 2);
    EXPECT_EQ(c.domain.cells, (std::vector<int>{16, 32}));
    EXPECT_EQ(c.domain.size, (std::vector<double>{1.0, 2.0}));
    EXPECT_EQ(c.domain.origin, (std::vector<double>{0.0, 0.0}));
    EXPECT_EQ(c.domain.periodic, (std::vector<bool>{false, false}));
    EXPECT_DOUBLE_EQ(c.walls.velocity[1][1][0], 1.0);
    EXPECT_DOUBLE_EQ(c.walls.velocity[0][0][1], 0.0);
    EXPECT_DOUBLE_EQ(c.fluid.viscosity, 0.01);
    ASSERT_TRUE(c.time.end.has_value());
    EXPECT_DOUBLE_EQ(*c.time.end, 1.0);
    EXPECT_FALSE(c.time.steady_tolerance.has_value());
    EXPECT_DOUBLE_EQ(c.simple.tolerance, 1e-5);
    EXPECT_EQ(c.simple.momentum_sweeps, 4);
    EXPECT_EQ(c.simple.momentum_cycles, 1);
    EXPECT_EQ(name_of(c.simple.momentum_solver), "auto");
    EXPECT_EQ(name_of(c.simple.convection), "central");
    EXPECT_FALSE(c.lubrication.is_enabled);
    EXPECT_EQ(name_of(c.lubrication.in_contact), "off"); // the schema's documented default
    EXPECT_EQ(name_of(c.lubrication.resolved), "range");
    EXPECT_EQ(name_of(c.lubrication.coupling), "implicit");
    EXPECT_EQ(c.simple.min_outer_iterations_dem, 2); // the schema's documented defaults
    EXPECT_FALSE(c.simple.is_mass_residual_held);
    EXPECT_TRUE(c.coupling.is_adjoint_at_walls);
    EXPECT_FALSE(c.coupling.is_wall_marker_off);
    EXPECT_FALSE(c.coupling.wall_marker_reach.has_value()); // the kernel's support + 0.5 h
    ASSERT_EQ(c.output.lines.size(), 1U);
    EXPECT_EQ(c.output.lines[0].n_points, 101);
}

TEST(CaseReader, CaseAsRunReadsBackToTheSameCase)
{
    const CaseConfig first = read_case_string(valid_case, "valid.toml", {"time.dt=0.02"});
    const CaseConfig second = read_case_string(first.as_run, "case.toml");
    EXPECT_DOUBLE_EQ(second.time.dt, 0.02);
    EXPECT_EQ(second.domain.cells, first.domain.cells);
    EXPECT_EQ(second.as_run.substr(second.as_run.find("\n\n")),
              first.as_run.substr(first.as_run.find("\n\n")));
}

TEST(CaseReader, OverridesSetAndAddKeys)
{
    const CaseConfig c = read_case_string(
        valid_case, "valid.toml",
        {"domain.cells=[8,8]", "simple.convection=upwind", "time.steady_tolerance=1e-6"});
    EXPECT_EQ(c.domain.cells, (std::vector<int>{8, 8}));
    EXPECT_EQ(name_of(c.simple.convection), "upwind");
    ASSERT_TRUE(c.time.steady_tolerance.has_value());
    EXPECT_DOUBLE_EQ(*c.time.steady_tolerance, 1e-6);
    const CaseConfig off =
        read_case_string(valid_case, "valid.toml",
                         {"coupling.markers_off_at_walls=true", "coupling.markers_off_reach=1.0"});
    EXPECT_TRUE(off.coupling.is_wall_marker_off);
    ASSERT_TRUE(off.coupling.wall_marker_reach.has_value());
    EXPECT_DOUBLE_EQ(*off.coupling.wall_marker_reach, 1.0);
    EXPECT_FALSE(off.coupling.is_body_marker_off);
    // the reach serves coupling.markers_off_between_bodies alone as well
    const CaseConfig between = read_case_string(
        valid_case, "valid.toml",
        {"coupling.markers_off_between_bodies=true", "coupling.markers_off_reach=2.0"});
    EXPECT_TRUE(between.coupling.is_body_marker_off);
    EXPECT_FALSE(between.coupling.is_wall_marker_off);
    ASSERT_TRUE(between.coupling.wall_marker_reach.has_value());
    EXPECT_DOUBLE_EQ(*between.coupling.wall_marker_reach, 2.0);
}

TEST(CaseReader, OverridesReachOneOrEveryEntryOfATableArray)
{
    const std::string bodies = valid_case +
                               "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.5, 0.5]\n"
                               "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.5, 1.5]\n";
    const CaseConfig one = read_case_string(bodies, "valid.toml", {"bodies.2.n_rings=13"});
    ASSERT_EQ(one.bodies.size(), 2U);
    EXPECT_EQ(one.bodies[0].n_rings, 0);
    EXPECT_EQ(one.bodies[1].n_rings, 13);
    const CaseConfig every =
        read_case_string(bodies, "valid.toml", {"bodies.density=3.5", "output.lines.1.points=7"});
    EXPECT_DOUBLE_EQ(every.bodies[0].density, 3.5);
    EXPECT_DOUBLE_EQ(every.bodies[1].density, 3.5);
    EXPECT_EQ(every.output.lines[0].n_points, 7);
}

TEST(CaseReader, ThreeDimensionalCaseNeedsThreeEntriesEverywhere)
{
    const std::string text = R"([domain]
size = [1.0, 1.0, 1.0]
cells = [8, 8, 8]
periodic = [true, false, true]
[fluid]
density = 1.0
viscosity = 1.0
[time]
dt = 0.1
end = 1.0
)";
    const CaseConfig c = read_case_string(text, "3d.toml");
    EXPECT_EQ(c.domain.dimension, 3);
    EXPECT_EQ(c.domain.periodic, (std::vector<bool>{true, false, true}));
    EXPECT_EQ(c.walls.velocity.size(), 3U);
}

/// A closed 3D box with one resolved sphere (h = 1/32, d = 0.25), for the 3D reading tests.
const std::string sphere_in_a_box = R"([domain]
size = [1.0, 1.0, 1.0]
cells = [32, 32, 32]
[fluid]
density = 1000.0
viscosity = 1.0
[time]
dt = 0.1
end = 1.0
[[bodies]]
shape = "sphere"
diameter = 0.25
density = 1500.0
position = [0.5, 0.5, 0.5]
)";

TEST(CaseReader, ThreeDimensionalCaseRefusesThe2DSettlingScalesButTakesAReynoldsNumber)
{
    const std::string text = replace(sphere_in_a_box, "viscosity = 1.0\n",
                                     "[nondimensional]\nreynolds = 40.0\nvelocity = 0.5\n");
    // μ = ρ U D / Re holds in any dimension.
    EXPECT_DOUBLE_EQ(read_case_string(text, "3d.toml").fluid.viscosity, 1000.0 * 0.5 * 0.25 / 40);
    const std::string settling =
        replace(replace(text, "density = 1500.0\n", ""), "velocity = 0.5\n",
                "velocity = 0.5\ndensity_ratio = 1.5\n");
    try {
        (void)read_case_string(settling, "3d.toml");
        FAIL() << "a 3D case took the 2D settling scales";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "nondimensional.density_ratio") << e.formatted();
        EXPECT_EQ(e.line(), 9) << e.formatted();
        EXPECT_NE(std::string(e.what()).find("in 3D give fluid.gravity and bodies.density"),
                  std::string::npos)
            << e.formatted();
    }
}

TEST(CaseReader, AngularVelocityIsANumberIn2DAndAVectorIn3D)
{
    const std::string sphere =
        replace(sphere_in_a_box, "position = [0.5, 0.5, 0.5]\n",
                "position = [0.5, 0.5, 0.5]\nomega = [1.0, -2.0, 3.5]\n[[bodies]]\n"
                "shape = \"sphere\"\ndiameter = 0.25\ndensity = 2.0\n"
                "position = [0.5, 0.5, 0.15]\n");
    const CaseConfig c = read_case_string(sphere, "3d.toml");
    EXPECT_EQ(c.bodies[0].omega, (std::vector<double>{1.0, -2.0, 3.5}));
    EXPECT_EQ(c.bodies[1].omega, (std::vector<double>{0.0, 0.0, 0.0})); // the default
    const CaseConfig disk = read_case_string(valid_case + "[[bodies]]\ndiameter = 0.5\n"
                                                          "density = 2.0\nposition = [0.5, 1.0]\n",
                                             "2d.toml");
    EXPECT_EQ(disk.bodies[0].omega, (std::vector<double>{0.0})); // the default
}

struct BadCase {
    const char* name;
    std::string text;                   ///< the case text
    std::vector<std::string> overrides; ///< --set values
    std::string file;                   ///< expected file in the message
    int line;                           ///< expected line (0: none)
    std::string key;                    ///< expected key
    std::string message;                ///< expected substring
};

std::vector<BadCase> bad_cases()
{
    const std::string v = valid_case;
    const std::string f = "bad.toml";
    const std::string body = "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.5, 1.0]\n";
    return {
        {"omega_vector_in_2d",
         v + body + "omega = [1.0, 2.0]\n",
         {},
         f,
         22,
         "bodies.omega",
         "a 2D case turns about z only: give one number"},
        {"release_of_a_free_body",
         v + body + "release_time = 0.1\n",
         {},
         f,
         22,
         "bodies.release_time",
         "body 1 is free: bodies.release_time lets go of a prescribed body"},
        {"release_between_fixed_steps",
         v + body + "motion = \"prescribed\"\nrelease_time = 0.125\n",
         {},
         f,
         23,
         "bodies.release_time",
         "0.125 s is not a whole number of time steps of 0.01 s"},
        {"negative_release_time",
         v + body + "motion = \"prescribed\"\nrelease_time = -1.0\n",
         {},
         f,
         23,
         "bodies.release_time",
         "out of range"},
        {"omega_text",
         v + body + "omega = \"fast\"\n",
         {},
         f,
         22,
         "bodies.omega",
         "expected a number"},
        {"syntax",
         replace(v, "density = 1.0", "density = = 1.0"),
         {},
         f,
         9,
         "",
         "TOML syntax error"},
        {"unknown_section", v + "[fluids]\nx = 1\n", {}, f, 18, "fluids", "did you mean 'fluid'"},
        {"misspelt_key",
         replace(v, "viscosity = 0.01", "viscosty = 0.01"),
         {},
         f,
         10,
         "fluid.viscosty",
         "did you mean 'fluid.viscosity'"},
        {"unknown_key_far",
         replace(v, "viscosity = 0.01", "viscosity = 0.01\ncolour = 3"),
         {},
         f,
         11,
         "fluid.colour",
         "unknown key"},
        {"missing_required",
         replace(v, "viscosity = 0.01\n", ""),
         {},
         f,
         8,
         "fluid.viscosity",
         "missing required key"},
        {"missing_size",
         replace(v, "size = [1.0, 2.0]\n", ""),
         {},
         f,
         3,
         "domain.size",
         "missing required key"},
        {"string_for_number",
         replace(v, "density = 1.0", "density = \"one\""),
         {},
         f,
         9,
         "fluid.density",
         "expected number"},
        {"zero_viscosity",
         replace(v, "viscosity = 0.01", "viscosity = 0.0"),
         {},
         f,
         10,
         "fluid.viscosity",
         "out of range: must be > 0"},
        {"negative_density",
         replace(v, "density = 1.0", "density = -1.0"),
         {},
         f,
         9,
         "fluid.density",
         "out of range"},
        {"negative_dt",
         replace(v, "dt = 0.01", "dt = -0.01"),
         {},
         f,
         12,
         "time.dt",
         "out of range"},
        {"nan_dt", replace(v, "dt = 0.01", "dt = nan"), {}, f, 12, "time.dt", "finite"},
        {"float_cells",
         replace(v, "cells = [16, 32]", "cells = [16.5, 32]"),
         {},
         f,
         5,
         "domain.cells",
         "expected [integer; dim]"},
        {"too_few_cells",
         replace(v, "cells = [16, 32]", "cells = [2, 32]"),
         {},
         f,
         5,
         "domain.cells",
         "out of range"},
        {"wrong_length",
         replace(v, "cells = [16, 32]", "cells = [16, 32, 8]"),
         {},
         f,
         5,
         "domain.cells",
         "this 2D case needs 2"},
        {"four_dimensions",
         replace(v, "size = [1.0, 2.0]", "size = [1.0, 2.0, 1.0, 1.0]"),
         {},
         f,
         4,
         "domain.size",
         "2 (2D) or 3 (3D)"},
        {"bad_choice",
         v + "[simple]\nconvection = \"centrall\"\n",
         {},
         f,
         19,
         "simple.convection",
         "did you mean 'central'"},
        {"relaxation_above_one",
         v + "[simple]\nvelocity_relaxation = 1.5\n",
         {},
         f,
         19,
         "simple.velocity_relaxation",
         "out of range"},
        {"too_many_momentum_cycles",
         v + "[simple]\nmomentum_cycles = 21\n",
         {},
         f,
         19,
         "simple.momentum_cycles",
         "out of range"},
        {"misspelt_algorithm",
         v + "[simple]\nalgorithm = \"projektion\"\n",
         {},
         f,
         19,
         "simple.algorithm",
         "did you mean 'projection'"},
        {"projection_with_a_light_body",
         v + replace(body, "density = 2.0", "density = 0.5") +
             "[simple]\nalgorithm = \"projection\"\n",
         {},
         f,
         23,
         "simple.algorithm",
         "takes none lighter than the fluid, and body 1 has ρs/ρf = 0.5"},
        {"projection_with_a_body_and_the_paper_forcing",
         v + body + "[simple]\nalgorithm = \"projection\"\n",
         {},
         f,
         23,
         "simple.algorithm",
         "with bodies, \"projection\" needs coupling.normalised_forcing = true"},
        {"projection_with_bdf2_and_a_body",
         v + body + "[simple]\nalgorithm = \"projection\"\n",
         {"time.scheme=bdf2", "coupling.normalised_forcing=true"},
         f,
         23,
         "simple.algorithm",
         "with bodies, \"projection\" blew up under time.scheme = \"bdf2\""},
        {"surface_markers_on_a_free_body",
         v + body + "[coupling]\nmarkers = \"surface\"\n",
         {},
         f,
         23,
         "coupling.markers",
         "set coupling.inner_fluid = \"volume\""},
        {"inner_fluid_from_the_cells_with_bdf2",
         v + body + "[coupling]\ninner_fluid = \"volume\"\n",
         {"time.scheme=bdf2"},
         f,
         23,
         "coupling.inner_fluid",
         "use time.scheme = \"euler\" with it"},
        {"inner_fluid_from_the_cells_with_markers_off_at_walls",
         v + body + "[coupling]\ninner_fluid = \"volume\"\nmarkers_off_at_walls = true\n",
         {},
         f,
         23,
         "coupling.inner_fluid",
         "use one option or the other"},
        {"markers_off_reach_without_markers_off_at_walls",
         v + body + "[coupling]\nmarkers_off_reach = 1.0\n",
         {},
         f,
         23,
         "coupling.markers_off_reach",
         "coupling.markers_off_at_walls and coupling.markers_off_between_bodies are off, so "
         "the reach would be ignored"},
        {"inner_fluid_from_the_cells_with_markers_off_between_bodies",
         v + body + "[coupling]\ninner_fluid = \"volume\"\nmarkers_off_between_bodies = true\n",
         {},
         f,
         23,
         "coupling.inner_fluid",
         "the markers coupling.markers_off_between_bodies silences"},
        {"markers_off_between_bodies_not_a_boolean",
         v + body + "[coupling]\nmarkers_off_between_bodies = 1\n",
         {},
         f,
         23,
         "coupling.markers_off_between_bodies",
         "boolean"},
        {"markers_off_reach_of_zero",
         v + body + "[coupling]\nmarkers_off_at_walls = true\nmarkers_off_reach = 0.0\n",
         {},
         f,
         24,
         "coupling.markers_off_reach",
         "out of range"},
        {"misspelt_inner_fluid",
         v + body + "[coupling]\ninner_fluid = \"volumes\"\n",
         {},
         f,
         23,
         "coupling.inner_fluid",
         "did you mean 'volume'"},
        {"projection_relaxed",
         v + "[simple]\nalgorithm = \"projection\"\npressure_relaxation = 0.8\n",
         {},
         f,
         19,
         "simple.algorithm",
         "set simple.velocity_relaxation and simple.pressure_relaxation to 1"},
        {"misspelt_momentum_solver",
         v + "[simple]\nmomentum_solver = \"multigird\"\n",
         {},
         f,
         19,
         "simple.momentum_solver",
         "did you mean 'multigrid'"},
        {"no_way_to_stop",
         replace(v, "end = 1.0\n", ""),
         {},
         f,
         11,
         "time.end",
         "the run needs a way to stop"},
        {"rest_speed_without_free_body",
         replace(v, "end = 1.0\n", "end = 1.0\nrest_speed = 0.01\n"),
         {},
         f,
         14,
         "time.rest_speed",
         "no free body to come to rest"},
        {"negative_rest_duration",
         v + body,
         {"time.rest_speed=0.01", "time.rest_duration=-1"},
         "--set",
         0,
         "time.rest_duration",
         "must be > 0"},
        {"min_end_after_end",
         replace(v, "end = 1.0\n", "end = 1.0\nmin_end = 2.0\nsteady_tolerance = 1e-6\n"),
         {},
         f,
         14,
         "time.min_end",
         "after the end time"},
        {"unknown_time_scheme",
         replace(v, "end = 1.0\n", "end = 1.0\nscheme = \"bdf3\"\n"),
         {},
         f,
         14,
         "time.scheme",
         "did you mean 'bdf2'"},
        {"misspelt_pressure_update",
         v + "[simple]\npressure_update = \"rotation\"\n",
         {},
         f,
         19,
         "simple.pressure_update",
         "did you mean 'rotational'"},
        {"misspelt_lubrication_in_contact",
         v + "[lubrication]\nenabled = true\nin_contact = \"saturate\"\n",
         {},
         f,
         20,
         "lubrication.in_contact",
         "did you mean 'saturated'"},
        {"misspelt_lubrication_resolved",
         v + "[lubrication]\nenabled = true\nresolved = \"shell\"\n",
         {},
         f,
         20,
         "lubrication.resolved",
         "did you mean 'shells'"},
        {"misspelt_lubrication_coupling",
         v + "[lubrication]\nenabled = true\ncoupling = \"implict\"\n",
         {},
         f,
         20,
         "lubrication.coupling",
         "did you mean 'implicit'"},
        {"misspelt_lubrication_film_solve",
         v + "[lubrication]\nenabled = true\nfilm_solve = \"jont\"\n",
         {},
         f,
         20,
         "lubrication.film_solve",
         "did you mean 'joint'"},
        {"lubrication_in_contact_not_a_word",
         v + "[lubrication]\nin_contact = false\n",
         {},
         f,
         19,
         "lubrication.in_contact",
         "string"},
        {"too_deep_acceleration",
         v + "[simple]\nacceleration_depth = 11\n",
         {},
         f,
         19,
         "simple.acceleration_depth",
         "out of range"},
        {"weight_bits_beyond_a_double",
         v + "[simple]\nacceleration_weight_bits = 53\n",
         {},
         f,
         19,
         "simple.acceleration_weight_bits",
         "out of range"},
        {"negative_acceleration_step",
         v + "[simple]\nacceleration_max_step = -1.0\n",
         {},
         f,
         19,
         "simple.acceleration_max_step",
         "out of range"},
        {"dt_longer_than_end",
         replace(v, "dt = 0.01", "dt = 2.0"),
         {},
         f,
         12,
         "time.dt",
         "longer than the end time"},
        {"normal_wall_velocity",
         replace(v, "y_high = [1.0, 0.0]", "y_high = [1.0, 0.5]"),
         {},
         f,
         7,
         "walls.y_high",
         "wall-normal component"},
        {"wall_on_periodic_axis",
         replace(v, "cells = [16, 32]", "cells = [16, 32]\nperiodic = [false, true]"),
         {},
         f,
         8,
         "walls.y_high",
         "is periodic"},
        {"z_wall_in_2d",
         replace(v, "y_high = [1.0, 0.0]", "z_low = [0.0, 0.0]"),
         {},
         f,
         7,
         "walls.z_low",
         "no z walls"},
        {"line_outside",
         replace(v, "to = [0.5, 2.0]", "to = [0.5, 2.5]"),
         {},
         f,
         17,
         "output.lines.to",
         "outside the box"},
        {"line_bad_name",
         replace(v, "name = \"vertical\"", "name = \"a b\""),
         {},
         f,
         15,
         "output.lines.name",
         "not a valid sample name"},
        {"line_duplicate_name",
         v + "[[output.lines]]\nname = \"vertical\"\nfrom = [0.0, 0.0]\nto = [1.0, 0.0]\n",
         {},
         f,
         19,
         "output.lines.name",
         "used twice"},
        {"line_missing_from",
         replace(v, "from = [0.5, 0.0]\n", ""),
         {},
         f,
         14,
         "output.lines.from",
         "missing required key"},
        {"line_unknown_key",
         replace(v, "from = [0.5, 0.0]", "from = [0.5, 0.0]\nstep = 1"),
         {},
         f,
         17,
         "output.lines.step",
         "unknown key"},
        {"section_not_table",
         "case = 3\n" + v.substr(v.find("[domain]")),
         {},
         f,
         1,
         "case",
         "must be a section"},
        // [contact] (one body: lines 18-21; the [contact] section starts on line 22)
        {"contact_stiffness_and_duration",
         v + body + "[contact]\nstiffness = 100.0\nduration = 0.01\n",
         {},
         f,
         24,
         "contact.duration",
         "not both"},
        {"contact_damping_without_stiffness",
         v + body + "[contact]\ndamping = 1.0\n",
         {},
         f,
         23,
         "contact.damping",
         "needs contact.stiffness"},
        {"contact_too_few_substeps",
         v + body + "[contact]\nstiffness = 1e6\nsubsteps = 1\n",
         {},
         f,
         24,
         "contact.substeps",
         "at least 10 are needed"},
        {"contact_overdamped",
         v + body + "[contact]\nstiffness = 1.0\ndamping = 100.0\n",
         {},
         f,
         24,
         "contact.damping",
         "overdamped"},
        // Bodies (issue 5): overlapping, outside the box, too small for the grid, non-physical.
        {"bodies_overlap",
         v + body + "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.6, 1.2]\n",
         {},
         f,
         25,
         "bodies.position",
         "body 2 overlaps body 1"},
        {"body_outside_box",
         v + replace(body, "position = [0.5, 1.0]", "position = [0.9, 1.0]"),
         {},
         f,
         21,
         "bodies.position",
         "body 1 reaches outside the box"},
        {"body_too_small_for_markers",
         v + replace(body, "diameter = 0.5", "diameter = 0.1"),
         {},
         f,
         19,
         "bodies.diameter",
         "cells across"},
        {"zero_diameter",
         v + replace(body, "diameter = 0.5", "diameter = 0.0"),
         {},
         f,
         19,
         "bodies.diameter",
         "out of range"},
        {"negative_body_density",
         v + replace(body, "density = 2.0", "density = -2.0"),
         {},
         f,
         20,
         "bodies.density",
         "out of range"},
        {"contact_zero_restitution",
         v + body + "[contact]\nrestitution = 0.0\nduration = 0.001\n",
         {},
         f,
         23,
         "contact.restitution",
         "out of range"},
        // Contact models and surfaces (issue 4): keys of the other model, missing or
        // out-of-range material values, a misspelt model.
        {"hertz_without_young_modulus",
         v + body + "[contact]\nmodel = \"hertz_mindlin\"\n",
         {},
         f,
         18,
         "contact.young_modulus",
         "needs a Young's modulus"},
        {"hertz_walls_without_young_modulus",
         v + body + "young_modulus = 1e9\n[contact]\nmodel = \"hertz_mindlin\"\n",
         {},
         f,
         6,
         "contact.young_modulus",
         "needs a Young's modulus"},
        {"young_modulus_with_linear",
         v + body + "[contact]\nyoung_modulus = 1e9\n",
         {},
         f,
         23,
         "contact.young_modulus",
         "only contact.model = \"hertz_mindlin\" takes this key"},
        {"stiffness_with_hertz",
         v + body + "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e9\nstiffness = 1e6\n",
         {},
         f,
         25,
         "contact.stiffness",
         "only contact.model = \"linear\" takes this key"},
        {"body_restitution_with_linear",
         v + body + "restitution = 0.5\n",
         {},
         f,
         22,
         "bodies.restitution",
         "only contact.model = \"hertz_mindlin\" takes this key"},
        // The adaptive collision model (issue 16): e_dry in (0, 1], N_c >= 1, a floor for slow
        // impacts, and its keys given to another model.
        {"adaptive_zero_restitution",
         v + body + "[contact]\nmodel = \"adaptive\"\nrestitution = 0.0\n",
         {},
         f,
         24,
         "contact.restitution",
         "out of range"},
        {"adaptive_restitution_above_one",
         v + body + "[contact]\nmodel = \"adaptive\"\nrestitution = 1.5\n",
         {},
         f,
         24,
         "contact.restitution",
         "out of range"},
        {"adaptive_zero_collision_steps",
         v + body + "[contact]\nmodel = \"adaptive\"\ncollision_steps = 0\n",
         {},
         f,
         24,
         "contact.collision_steps",
         "out of range"},
        {"adaptive_without_gravity_or_floor",
         v + body + "[contact]\nmodel = \"adaptive\"\nrestitution = 0.9\n",
         {},
         f,
         22,
         "contact.minimum_impact_velocity",
         "the adaptive model needs a finite floor for slow impacts"},
        {"collision_steps_with_linear",
         v + body + "[contact]\ncollision_steps = 5\n",
         {},
         f,
         23,
         "contact.collision_steps",
         "only contact.model = \"adaptive\" takes this key (the case uses \"linear\")"},
        {"tangential_ratio_with_hertz",
         v + body +
             "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e9\n"
             "tangential_stiffness_ratio = 0.5\n",
         {},
         f,
         25,
         "contact.tangential_stiffness_ratio",
         "only contact.model = \"linear\" or \"adaptive\" takes this key"},
        {"poisson_ratio_out_of_range",
         v + body +
             "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e9\npoisson_ratio = 0.5\n",
         {},
         f,
         25,
         "contact.poisson_ratio",
         "out of range"},
        {"negative_wall_friction",
         replace(v, "y_high = [1.0, 0.0]", "y_high = [1.0, 0.0]\nfriction = -0.1"),
         {},
         f,
         8,
         "walls.friction",
         "out of range"},
        {"body_friction_not_a_number",
         v + body + "friction = \"high\"\n",
         {},
         f,
         22,
         "bodies.friction",
         "expected number"},
        {"negative_rolling_friction",
         v + body + "[contact]\nrolling_friction = -1.0\n",
         {},
         f,
         23,
         "contact.rolling_friction",
         "out of range"},
        {"misspelt_contact_model",
         v + body + "[contact]\nmodel = \"hertz\"\n",
         {},
         f,
         23,
         "contact.model",
         "did you mean 'hertz_mindlin'"},
        {"hertz_no_impact_speed",
         replace(v, "y_high = [1.0, 0.0]", "y_high = [0.0, 0.0]") + body +
             "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e9\n",
         {},
         f,
         22,
         "contact.impact_velocity",
         "give contact.impact_velocity"},
        {"negative_contact_margin",
         v + body + "[contact]\nmargin = -0.01\n",
         {},
         f,
         23,
         "contact.margin",
         "out of range"},
        {"set_hertz_on_a_linear_case",
         v + body + "[contact]\nstiffness = 1e6\n",
         {"contact.model=hertz_mindlin"},
         f,
         23,
         "contact.stiffness",
         "only contact.model = \"linear\" takes this key"},
        {"set_syntax", v, {"time.dt"}, "--set", 0, "time.dt", "expected section.key=value"},
        {"set_no_outer_iteration_for_dem_steps",
         v,
         {"simple.min_outer_iterations_dem=0"},
         "--set",
         0,
         "simple.min_outer_iterations_dem",
         "out of range: must be [1, 10]"},
        {"set_min_dt_not_positive",
         v,
         {"time.min_dt=-1"},
         "--set",
         0,
         "time.min_dt",
         "out of range: must be > 0"},
        {"set_max_retries_negative",
         v,
         {"time.max_retries=-1"},
         "--set",
         0,
         "time.max_retries",
         "out of range: must be [0, 60]"},
        {"set_retry_mass_residual_not_positive",
         v,
         {"time.retry_mass_residual=0"},
         "--set",
         0,
         "time.retry_mass_residual",
         "out of range: must be > 0"},
        {"set_retry_courant_not_positive",
         v,
         {"time.retry_courant=-2"},
         "--set",
         0,
         "time.retry_courant",
         "out of range: must be > 0"},
        {"set_hold_mass_residual_not_a_boolean",
         v,
         {"simple.hold_mass_residual=maybe"},
         "--set",
         0,
         "simple.hold_mass_residual",
         "expected boolean"},
        {"set_unknown_key", v, {"time.dtt=1"}, "--set", 0, "time.dtt", "did you mean 'time.dt'"},
        {"set_key_with_word_added",
         v,
         {"time.end_time=1"},
         "--set",
         0,
         "time.end_time",
         "did you mean 'time.end'"},
        {"inflow_without_outflow",
         v + "[boundaries]\nx_low = \"inflow\"\n[inflow]\nvelocity = 1.0\n",
         {},
         f,
         19,
         "boundaries",
         "an inflow needs an outflow side"},
        {"inflow_without_speed",
         v + "[boundaries]\nx_low = \"inflow\"\nx_high = \"outflow\"\n",
         {},
         f,
         19,
         "inflow.velocity",
         "give its speed"},
        {"inflow_speed_without_inflow",
         v + "[inflow]\nvelocity = 1.0\n",
         {},
         f,
         19,
         "inflow.velocity",
         "no side is an inflow"},
        {"unknown_boundary_kind",
         v + "[boundaries]\nx_low = \"inlet\"\n",
         {},
         f,
         19,
         "boundaries.x_low",
         "one of"},
        {"wall_velocity_on_outflow",
         v + "[boundaries]\ny_high = \"outflow\"\n",
         {},
         f,
         7,
         "walls.y_high",
         "not a wall"},
        {"side_kind_on_periodic_axis",
         v + "[boundaries]\nx_low = \"outflow\"\n",
         {"domain.periodic=[true,false]"},
         f,
         19,
         "boundaries.x_low",
         "is periodic"},
        {"set_out_of_range", v, {"time.dt=0"}, "--set", 0, "time.dt", "out of range"},
        {"unknown_body_sweep",
         v,
         {"coupling.body_sweep=jacobi"},
         "--set",
         0,
         "coupling.body_sweep",
         "one of"},
        {"unknown_fluid_force",
         v,
         {"contact.fluid_force=yes"},
         "--set",
         0,
         "contact.fluid_force",
         "one of"},
        {"set_body_past_the_last",
         v + body,
         {"bodies.2.density=3"},
         "--set",
         0,
         "bodies.2.density",
         "the case has 1 [[bodies]] entry (counted from 1), there is no 2"},
        {"set_body_zero",
         v + body,
         {"bodies.0.density=3"},
         "--set",
         0,
         "bodies.0.density",
         "there is no 0"},
        {"set_body_without_bodies",
         v,
         {"bodies.density=3"},
         "--set",
         0,
         "bodies.density",
         "the case has no [[bodies]] entry to set it in"},
        {"set_body_out_of_range",
         v + body,
         {"bodies.1.n_rings=-1"},
         "--set",
         0,
         "bodies.n_rings",
         "out of range"},
        {"set_body_misspelt",
         v + body,
         {"bodies.1.n_ring=3"},
         "--set",
         0,
         "bodies.n_ring",
         "did you mean 'bodies.n_rings'"},
        {"set_three_parts",
         v,
         {"time.dt.x=1"},
         "--set",
         0,
         "time.dt.x",
         "expected section.key=value"},
        {"set_wrong_type",
         v,
         {"domain.cells=[1.5,2]"},
         "--set",
         0,
         "domain.cells",
         "expected [integer; dim]"},
        // Extreme values whose derived quantities overflow (found while fuzzing the reader,
        // docs/testing.md): before, a float-to-int overflow in the DEM sub-step count (undefined
        // behaviour), a run with an infinite viscosity or collision time, or a NaN damping
        // reported against a key the case does not give.
        {"contact_too_stiff_to_resolve",
         v + body + "[contact]\nstiffness = 1e300\n",
         {},
         f,
         22,
         "contact",
         "the contact parameters give a shortest collision of 1.39e-150 s and a "
         "contact_duration of 1.97e-150 s; 10 sub-steps per collision need a finite duration of "
         "at least 1e-08 s (time.dt / 10000000, the most DEM sub-steps allowed): change the "
         "contact parameters (contact.stiffness, or contact.restitution and duration) or time.dt"},
        {"contact_duration_underflow",
         v + body + "[contact]\nrestitution = 0.5\nduration = 1e-300\n",
         {},
         f,
         22,
         "contact",
         "the derived contact stiffness is inf, not a finite positive number: the contact "
         "parameters and the lightest free body's mass (0.392699 kg) are out of any usable range"},
        {"hertz_impact_velocity_overflow",
         v + body +
             "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e9\nimpact_velocity = 1e300\n",
         {},
         f,
         22,
         "contact",
         "the contact parameters give a shortest collision of inf s and a contact_duration of inf "
         "s; 10 sub-steps per collision need a finite duration of at least 1e-08 s (time.dt / "
         "10000000, the most DEM sub-steps allowed): change the contact parameters "
         "(young_modulus, contact.impact_velocity) or time.dt"},
        {"nondimensional_viscosity_overflow",
         replace(v, "viscosity = 0.01\n", "") + body +
             "[nondimensional]\nreynolds = 1e-300\nvelocity = 1e300\n",
         {},
         f,
         21,
         "nondimensional",
         "the derived viscosity is inf, not a finite positive number: the values of "
         "[nondimensional] with fluid.density and the first body's diameter are out of any "
         "usable range"},
        {"nondimensional_body_mass_overflow",
         replace(replace(v, "viscosity = 0.01\n", ""), "y_high = [1.0, 0.0]",
                 "y_high = [0.0, 0.0]") +
             replace(body, "density = 2.0\n", "") +
             "[nondimensional]\nreynolds = 0.1\ndensity_ratio = 1e300\n",
         {},
         f,
         0, // no [contact] section: every contact value is a default
         "contact",
         "not a finite positive number: the contact parameters and the lightest free body's mass "
         "(1.9635e+299 kg) are out of any usable range"},
        // Issue 17: integers beyond 2^53 read as 0, a box of zero floating-point width, an
        // end time between steps, 10^12 steps, and --set values that hid their fault.
        {"integer_without_exact_double",
         replace(v, "density = 1.0", "density = 9007199254740993"),
         {},
         f,
         9,
         "fluid.density",
         "the integer 9007199254740993 has no exact floating-point value"},
        {"integer_without_exact_double_in_a_vector",
         replace(v, "cells = [16, 32]", "cells = [16, 32]\norigin = [9007199254740993, 0]"),
         {},
         f,
         6,
         "domain.origin",
         "the integer 9007199254740993 has no exact floating-point value"},
        {"box_cells_not_representable",
         replace(v, "cells = [16, 32]", "cells = [16, 32]\norigin = [1e308, 0]"),
         {},
         f,
         6,
         "domain.origin",
         "the box spans [1e+308, 1e+308] on axis 0 in cells 0.0625 wide, where doubles are "
         "2e+292 apart"},
        {"end_between_steps",
         replace(v, "end = 1.0", "end = 1.005"),
         {},
         f,
         13,
         "time.end",
         "1.005 s is not a whole number of time steps of 0.01 s (100.5 steps)"},
        {"more_steps_than_max_steps",
         replace(v, "dt = 0.01", "dt = 1e-12"),
         {},
         f,
         12,
         "time.dt",
         "time.end / time.dt = 1 / 1e-12 = 1e+12 steps, more than time.max_steps = 100000000"},
        {"set_with_a_newline",
         v,
         {"time.dt=0.004\ntime.end=5"},
         "--set",
         0,
         "time.dt",
         "'time.dt=0.004\\ntime.end=5' holds a control character (byte 14 of it, 0x0a)"},
        {"set_unknown_section",
         v,
         {"nosuch.key=1"},
         "--set",
         0,
         "nosuch",
         "unknown section 'nosuch'"},
        {"set_number_out_of_range",
         v,
         {"time.dt=1e400"},
         "--set",
         0,
         "time.dt",
         "cannot read the value '1e400'"},
    };
}

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, StopsWithOneClearMessage)
{
    const BadCase& bad = GetParam();
    try {
        (void)read_case_string(bad.text, "bad.toml", bad.overrides);
        FAIL() << "no error for " << bad.name;
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), bad.file);
        EXPECT_EQ(e.line(), bad.line) << e.formatted();
        EXPECT_EQ(e.key(), bad.key) << e.formatted();
        EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.formatted();
    }
}

INSTANTIATE_TEST_SUITE_P(CaseReader, BadInput, ::testing::ValuesIn(bad_cases()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

/// The case after its two header lines (which name the source file).
std::string case_body(const std::string& as_run)
{
    return as_run.substr(as_run.find("\n\n"));
}

/// The case as run (each run directory's case.toml, which `fddem run --restart` reads) reads
/// back to itself. Found by fuzzing (fuzz/fuzz_case_reader.cpp): the zero defaults filled in
/// for the walls of a periodic axis, and for fluid.gravity beside [nondimensional], read back
/// as given keys ("axis 0 is periodic", "fluid.gravity is derived from [nondimensional]").
void expect_reads_back(const std::string& text, const std::string& name)
{
    SCOPED_TRACE(name);
    const CaseConfig first = read_case_string(text, name);
    CaseConfig second;
    try {
        second = read_case_string(first.as_run, "case.toml");
    } catch (const InputError& e) {
        FAIL() << "the case as run does not read back: " << e.formatted();
    }
    EXPECT_EQ(case_body(second.as_run), case_body(first.as_run));
    EXPECT_EQ(second.domain.periodic, first.domain.periodic);
    EXPECT_EQ(second.fluid.gravity, first.fluid.gravity);
    EXPECT_EQ(second.walls.velocity, first.walls.velocity);
}

TEST(CaseReader, PeriodicCaseAsRunReadsBack)
{
    // The fuzzer's input: this 3D case, periodic in x and z.
    expect_reads_back(R"([domain]
size = [1.0, 1.0, 1.0]
cells = [8, 8, 8]
periodic = [true, false, true]
[fluid]
density = 1.0
viscosity = 1.0
[time]
dt = 0.1
end = 1.0
)",
                      "periodic.toml");
    expect_reads_back(
        replace(valid_case, "cells = [16, 32]", "cells = [16, 32]\nperiodic = [true, false]"),
        "periodic_x.toml");
}

TEST(CaseReader, NondimensionalCaseAsRunReadsBack)
{
    // The fuzzer's input (the paper's Fig. 3 and 4 cases failed the same way).
    expect_reads_back(R"([domain]
size = [4.0, 8.0]
cells = [64, 128]
[fluid]
density = 1.0
[nondimensional]
reynolds = 0.1
density_ratio = 1.5
[time]
dt = 0.01
end = 1.0
[[bodies]]
diameter = 1.0
position = [2.0, 6.0]
)",
                      "nondimensional.toml");
}

TEST(CaseReader, EveryRepositoryCaseAsRunReadsBack)
{
    int n_cases = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::string(FDDEM_SOURCE_DIR) + "/cases")) {
        if (entry.path().filename() == "case.toml") {
            expect_reads_back(test::file_contents(entry.path()), entry.path().string());
            ++n_cases;
        }
    }
    EXPECT_GE(n_cases, 10); // cases/ held 10 case files when this test was written
}

TEST(CaseReader, ContactStiffnessAndSubstepsAreDerivedFromRestitutionAndDuration)
{
    const std::string text = valid_case + "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\n"
                                          "position = [0.5, 1.0]\n[contact]\nrestitution = 0.5\n"
                                          "duration = 0.001\n";
    const CaseConfig c = read_case_string(text, "contact.toml", {});
    const double mass = 2.0 * 3.141592653589793 * 0.0625; // ρs π r²
    // e = exp(−ζπ/√(1−ζ²)), t_c = π/(ω₀√(1−ζ²)), k = m ω₀², c = 2ζ√(k m)
    const double zeta = -std::log(0.5) / std::sqrt(M_PI * M_PI + std::log(0.5) * std::log(0.5));
    const double omega_0 = M_PI / 0.001 / std::sqrt(1.0 - zeta * zeta);
    EXPECT_NEAR(c.contact.derived.stiffness, mass * omega_0 * omega_0,
                1e-9 * c.contact.derived.stiffness);
    EXPECT_NEAR(c.contact.derived.damping,
                2.0 * zeta * std::sqrt(c.contact.derived.stiffness * mass),
                1e-9 * c.contact.derived.damping);
    EXPECT_NEAR(c.contact.derived.duration, 0.001, 1e-15);
    EXPECT_NEAR(c.contact.derived.restitution, 0.5, 1e-12);
    // 80 sub-steps per collision of two such bodies (reduced mass m/2, undamped duration).
    const double pair = M_PI * std::sqrt(0.5 * mass / c.contact.derived.stiffness);
    EXPECT_EQ(c.contact.derived.substeps, static_cast<int>(std::ceil(80.0 * 0.01 / pair)));
    EXPECT_NE(c.as_run.find("contact_substeps"), std::string::npos);
}

TEST(CaseReader, HertzMindlinSurfacesImpactSpeedAndSubstepsAreDerived)
{
    const std::string text =
        replace(valid_case, "viscosity = 0.01", "viscosity = 0.01\ngravity = [0.0, -10.0]") +
        "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.5, 1.0]\nfriction = 0.4\n"
        "[contact]\nmodel = \"hertz_mindlin\"\nyoung_modulus = 1e6\nfriction = 0.1\n"
        "restitution = 0.5\nrolling_friction = 0.01\n";
    const CaseConfig c = read_case_string(text, "hertz.toml", {});
    // Surfaces: a body's own value, else [contact]'s; ν defaults to 0.3.
    EXPECT_EQ(c.bodies[0].material.friction, 0.4);
    EXPECT_EQ(c.walls.material.friction, 0.1);
    EXPECT_EQ(c.bodies[0].material.rolling_friction, 0.01);
    EXPECT_EQ(c.bodies[0].material.restitution, 0.5);
    EXPECT_EQ(c.walls.material.young_modulus, 1e6);
    EXPECT_EQ(c.walls.material.poisson_ratio, 0.3);
    // Impact speed: √(2 |g| L) + 2 · 0 (bodies at rest) + 1 (the lid), L = 2.
    EXPECT_NEAR(c.contact.derived.impact_velocity, std::sqrt(40.0) + 1.0, 1e-12);
    // The shortest collision is two such bodies (m* = m/2, R* = R/2) rather than one and a
    // wall (m, R): t_c ∝ (m*²/R*)^{1/5}. 80 sub-steps in it.
    const double mass = 2.0 * M_PI * 0.0625;
    const Material& surface = c.bodies[0].material;
    const PairSide body = ball_side(mass, 0.5 * mass * 0.0625, 0.25, surface, true);
    const HertzMindlin hertz;
    const double pair = hertz.elastic_collision_time(make_contact_pair(body, body),
                                                     c.contact.derived.impact_velocity);
    const double wall = hertz.elastic_collision_time(
        make_contact_pair(body, wall_side(c.walls.material)), c.contact.derived.impact_velocity);
    EXPECT_LT(pair, wall);
    EXPECT_EQ(c.contact.derived.substeps, static_cast<int>(std::ceil(80.0 * 0.01 / pair)));
    EXPECT_NEAR(c.contact.derived.duration, wall, 1e-15); // recorded: the wall collision
    EXPECT_NEAR(c.contact.derived.restitution, 0.5, 1e-15);
    for (const char* key : {"contact_impact_velocity", "contact_damping_constant",
                            "contact_duration", "contact_substeps"}) {
        EXPECT_NE(c.as_run.find(key), std::string::npos) << key;
    }
    // The case as run reads back to the same case.
    EXPECT_EQ(read_case_string(c.as_run, "case.toml", {}).contact.derived.substeps,
              c.contact.derived.substeps);
}

TEST(CaseReader, AdaptiveCollisionDurationFloorAndSubstepsAreDerived)
{
    const std::string text =
        replace(valid_case, "viscosity = 0.01", "viscosity = 0.01\ngravity = [0.0, -10.0]") +
        "[[bodies]]\ndiameter = 0.5\ndensity = 2.0\nposition = [0.5, 1.0]\n"
        "[contact]\nmodel = \"adaptive\"\nrestitution = 0.9\ncollision_steps = 5\n";
    const CaseConfig c = read_case_string(text, "adaptive.toml", {});
    EXPECT_EQ(c.contact.model, ContactModelKind::adaptive);
    // T_c = N_c Δt = 5 · 0.01; v_min = |g| T_c / 1000 = 5e-4 m/s; 80 sub-steps per collision:
    // ceil(80 Δt / T_c) = 16 per step.
    EXPECT_NEAR(c.contact.derived.duration, 0.05, 1e-15);
    EXPECT_NEAR(c.contact.derived.minimum_impact_velocity, 5e-4, 1e-18);
    EXPECT_EQ(c.contact.derived.restitution, 0.9);
    EXPECT_EQ(c.contact.derived.substeps, 16);
    EXPECT_NE(c.as_run.find("contact_minimum_impact_velocity"), std::string::npos);
    // Given sub-steps must give at least 10 per collision: 2 per step is 10.
    EXPECT_EQ(
        read_case_string(text + "substeps = 2\n", "adaptive.toml", {}).contact.derived.substeps, 2);
    EXPECT_THROW((void)read_case_string(text + "substeps = 1\n", "adaptive.toml", {}), InputError);
    // A floor given replaces the default, and the case as run reads back to the same case.
    const CaseConfig floored =
        read_case_string(text + "minimum_impact_velocity = 0.02\n", "adaptive.toml", {});
    EXPECT_EQ(floored.contact.derived.minimum_impact_velocity, 0.02);
    const CaseConfig again = read_case_string(floored.as_run, "case.toml", {});
    EXPECT_EQ(again.contact.derived.minimum_impact_velocity, 0.02);
    EXPECT_EQ(again.contact.collision_steps, 5);
    EXPECT_EQ(again.contact.derived.substeps, 16);
}

TEST(CaseReader, MissingFileIsAnInputError)
{
    EXPECT_THROW((void)read_case("/nonexistent/case.toml"), InputError);
}

TEST(CaseReader, ADirectoryIsNotACaseFile)
{
    // Issue 17: a directory read as an empty case and was reported as "missing domain.size".
    try {
        (void)read_case("/tmp");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), "/tmp: is a directory, not a case file (give the case's .toml)");
    }
}

TEST(CaseReader, ACaseFileNameWithANewlineStaysOnItsSourceLine)
{
    // Issue 17: the name broke the case as run's "# Source:" comment, and --restart read the
    // rest of it as TOML.
    const CaseConfig c = read_case_string(valid_case, "runs/a\nb\\c\x01.toml");
    EXPECT_EQ(fddem::test::lines_of(c.as_run).at(1), "# Source: runs/a\\nb\\\\c\\x01.toml");
    EXPECT_EQ(case_body(read_case_string(c.as_run, "case.toml").as_run), case_body(c.as_run));
}

TEST(CaseReader, EditDistanceCountsSingleEdits)
{
    EXPECT_EQ(edit_distance("viscosity", "viscosty"), 1U);
    EXPECT_EQ(edit_distance("", "abc"), 3U);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3U);
}

TEST(CaseSchema, EveryKeyIsDocumentedOnceWithARange)
{
    const auto schema = case_schema();
    for (std::size_t i = 0; i < schema.size(); ++i) {
        EXPECT_FALSE(schema[i].doc.empty()) << schema[i].full_name();
        for (std::size_t j = i + 1; j < schema.size(); ++j) {
            EXPECT_NE(schema[i].full_name(), schema[j].full_name());
        }
    }
}

TEST(CaseSchema, EveryKeyButTheDerivedOnesSetsAField)
{
    for (const KeySpec& spec : case_schema()) {
        EXPECT_EQ(static_cast<bool>(spec.set), spec.section != "derived") << spec.full_name();
    }
}

/// Each key lands in its own field: a case giving keys values other than their defaults reads
/// back to those values (a key bound to the wrong field, or to none, fails here).
TEST(CaseSchema, EachKeySetsItsOwnField)
{
    const std::string text = replace(valid_case, "[time]\n", R"([inflow]
profile = "parabolic"
velocity = 0.7
[boundaries]
x_low = "inflow"
x_high = "outflow"
[simple]
tolerance = 1e-4
max_outer_iterations = 12
velocity_relaxation = 0.8
pressure_relaxation = 0.6
pressure_update = "standard"
acceleration_depth = 3
acceleration_weight_bits = 10
acceleration_max_step = 30
momentum_sweeps = 6
momentum_cycles = 2
momentum_solver = "gauss_seidel"
convection = "upwind"
pressure_solver = "hypre"
fft_planning = "measure"
linear_tolerance = 1e-7
linear_max_iterations = 33
min_outer_iterations_dem = 3
hold_mass_residual = true
[coupling]
kernel = "roma3"
marker_spacing_ratio = 1.2
adjoint_at_walls = false
[lubrication]
enabled = true
range = 1.5
roughness = 0.01
in_contact = "saturated"
[output]
directory = "somewhere"
field_interval = 0.25
particle_interval = 0.125
log_interval = 9
[checkpoint]
step_interval = 5
time_interval = 0.5
keep = 4
[time]
rest_duration = 0.3
min_end = 0.2
max_steps = 77
max_courant = 0.4
min_dt = 1e-7
max_retries = 5
retry_mass_residual = 0.3
retry_courant = 0.9
scheme = "bdf2"
)");
    const CaseConfig c = read_case_string(text, "every.toml");
    EXPECT_EQ(c.title, "cavity");
    EXPECT_EQ(c.inflow.profile, InflowShape::parabolic);
    EXPECT_EQ(c.inflow.velocity, 0.7);
    EXPECT_EQ(c.boundaries[0][0], BoundaryKind::inflow);
    EXPECT_EQ(c.boundaries[0][1], BoundaryKind::outflow);
    EXPECT_EQ(c.boundaries[1][0], BoundaryKind::wall);
    EXPECT_EQ(c.time.rest_duration, 0.3);
    EXPECT_EQ(c.time.min_end, 0.2);
    EXPECT_EQ(c.time.max_steps, 77);
    EXPECT_EQ(c.time.max_courant, 0.4);
    EXPECT_EQ(c.time.min_dt, 1e-7);
    EXPECT_EQ(c.time.max_retries, 5);
    EXPECT_EQ(c.time.retry_mass_residual, 0.3);
    EXPECT_EQ(c.time.retry_courant, 0.9);
    EXPECT_EQ(c.time.scheme, TimeScheme::bdf2);
    EXPECT_TRUE(c.lubrication.is_enabled);
    EXPECT_EQ(c.lubrication.range, 1.5);
    EXPECT_EQ(c.lubrication.roughness, 0.01);
    EXPECT_EQ(c.lubrication.in_contact, LubricationInContact::saturated);
    const SimpleConfig& simple = c.simple;
    EXPECT_EQ(simple.tolerance, 1e-4);
    EXPECT_EQ(simple.max_outer_iterations, 12);
    EXPECT_EQ(simple.velocity_relaxation, 0.8);
    EXPECT_EQ(simple.pressure_relaxation, 0.6);
    EXPECT_EQ(simple.pressure_update, PressureUpdate::standard);
    EXPECT_EQ(simple.acceleration_depth, 3);
    EXPECT_EQ(simple.acceleration_weight_bits, 10);
    EXPECT_EQ(simple.acceleration_max_step, 30.0);
    EXPECT_EQ(simple.momentum_sweeps, 6);
    EXPECT_EQ(simple.momentum_cycles, 2);
    EXPECT_EQ(simple.momentum_solver, MomentumSolver::gauss_seidel);
    EXPECT_EQ(simple.convection, ConvectionScheme::upwind);
    EXPECT_EQ(simple.pressure_solver, PoissonSolverKind::hypre);
    EXPECT_EQ(simple.fft_planning, FftPlanning::measure);
    EXPECT_EQ(simple.linear_tolerance, 1e-7);
    EXPECT_EQ(simple.linear_max_iterations, 33);
    EXPECT_EQ(simple.min_outer_iterations_dem, 3);
    EXPECT_TRUE(simple.is_mass_residual_held);
    EXPECT_EQ(c.coupling.kernel, KernelKind::roma3);
    EXPECT_FALSE(c.coupling.is_adjoint_at_walls);
    EXPECT_EQ(c.coupling.marker_spacing_ratio, 1.2);
    EXPECT_EQ(c.output.directory, "somewhere");
    EXPECT_EQ(c.output.field_interval, 0.25);
    EXPECT_EQ(c.output.particle_interval, 0.125);
    EXPECT_EQ(c.output.log_interval, 9);
    EXPECT_EQ(c.checkpoint.step_interval, 5);
    EXPECT_EQ(c.checkpoint.time_interval, 0.5);
    EXPECT_EQ(c.checkpoint.keep, 4);
}

TEST(CaseSchema, EachBodyAndContactKeySetsItsOwnField)
{
    const std::string walls = R"(y_high = [1.0, 0.0]
young_modulus = 3e6
poisson_ratio = 0.2
friction = 0.3
rolling_friction = 0.02
restitution = 0.8
)";
    const std::string text = replace(valid_case, "y_high = [1.0, 0.0]\n", walls) + R"([[bodies]]
shape = "disk"
diameter = 0.5
density = 2.0
position = [0.5, 1.0]
velocity = [0.1, -0.2]
omega = 0.3
motion = "prescribed"
n_rings = 5
friction = 0.4
rolling_friction = 0.05
young_modulus = 2e6
poisson_ratio = 0.25
restitution = 0.9
[[bodies]]
diameter = 0.5
density = 3.0
position = [0.5, 1.6]
[contact]
model = "hertz_mindlin"
coupling = "additive"
young_modulus = 1e6
impact_velocity = 2.0
velocity_damping = 0.5
margin = 0.01
substeps = 400
)";
    const CaseConfig c = read_case_string(text, "bodies.toml");
    ASSERT_EQ(c.bodies.size(), 2U);
    const BodyConfig& b = c.bodies[0];
    EXPECT_EQ(b.shape, BodyShape::disk);
    EXPECT_EQ(b.diameter, 0.5);
    EXPECT_EQ(b.density, 2.0);
    EXPECT_EQ(b.position, (std::vector<double>{0.5, 1.0}));
    EXPECT_EQ(b.velocity, (std::vector<double>{0.1, -0.2}));
    EXPECT_EQ(b.omega, (std::vector<double>{0.3}));
    EXPECT_EQ(b.motion, Motion::prescribed);
    EXPECT_EQ(b.n_rings, 5);
    EXPECT_EQ(b.material.friction, 0.4);
    EXPECT_EQ(b.material.rolling_friction, 0.05);
    EXPECT_EQ(b.material.young_modulus, 2e6);
    EXPECT_EQ(b.material.poisson_ratio, 0.25);
    EXPECT_EQ(b.material.restitution, 0.9);
    EXPECT_EQ(c.bodies[1].density, 3.0);
    EXPECT_EQ(c.bodies[1].material.young_modulus, 1e6); // [contact]'s
    EXPECT_EQ(c.walls.material.young_modulus, 3e6);
    EXPECT_EQ(c.walls.material.poisson_ratio, 0.2);
    EXPECT_EQ(c.walls.material.friction, 0.3);
    EXPECT_EQ(c.walls.material.rolling_friction, 0.02);
    EXPECT_EQ(c.walls.material.restitution, 0.8);
    EXPECT_EQ(c.contact.model, ContactModelKind::hertz_mindlin);
    EXPECT_EQ(c.contact.coupling, ContactCoupling::additive);
    EXPECT_EQ(c.contact.impact_velocity, 2.0);
    EXPECT_EQ(c.contact.derived.impact_velocity, 2.0);
    EXPECT_EQ(c.contact.velocity_damping, 0.5);
    EXPECT_EQ(c.contact.margin, 0.01);
    EXPECT_EQ(c.contact.derived.substeps, 400);
}

TEST(CaseSchema, DocsCaseFileIsUpToDate)
{
    std::ifstream in(std::string(FDDEM_SOURCE_DIR) + "/docs/case-file.md");
    ASSERT_TRUE(in)
        << "docs/case-file.md is missing: fddem info --keys --markdown > docs/case-file.md";
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), describe_keys(true))
        << "regenerate with: fddem info --keys --markdown > docs/case-file.md";
}

} // namespace
} // namespace fddem
