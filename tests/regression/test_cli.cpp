// SPDX-License-Identifier: MIT
// The fddem program as a user meets it: a small run writes every documented output; bad input
// of every class ends with one message, exit status 2, and nothing written.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "support/case_builders.hpp"
#include "support/files_and_programs.hpp"

namespace {

namespace fs = std::filesystem;

using Result = fddem::test::ProgramResult;

Result run(const std::string& arguments)
{
    const fs::path log = fs::temp_directory_path() / ("fddem_cli_" + std::to_string(::getpid()));
    Result result = fddem::test::run_fddem(arguments, log);
    fs::remove(log);
    return result;
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override
    {
        root_ = fddem::test::fresh_test_directory("fddem_cli_test_");
        case_file_ = root_ / "cavity.toml";
        std::ofstream(case_file_) << fddem::test::small_cavity_case;
    }
    void TearDown() override { fs::remove_all(root_); }

    fs::path root_;
    fs::path case_file_;
};

TEST_F(Cli, ValidateOnlyThatMatchesNoCheckIsExitTwoAndWritesNothing)
{
    // Before: "0 failing" for a filter that ran nothing.
    const fs::path out = root_ / "report";
    const Result r = run("validate --only 'no such check' -o " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(r.output,
              "validate: --only: no check of the full set has 'no such check' in its name\n");
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, SmallRunWritesEveryDocumentedOutput)
{
    const fs::path out = root_ / "run";
    const Result r = run("run " + case_file_.string() + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* file :
         {"case.toml", "solver.csv", "summary.json", "fields.pvd", "fields/fields_000000.vtr",
          "open_in_paraview.py", "fields/fields_000002.vtr", "samples/vertical_centerline.csv"}) {
        EXPECT_TRUE(fs::exists(out / file)) << file;
    }
    std::ifstream solver(out / "solver.csv");
    std::string header;
    std::getline(solver, header);
    EXPECT_EQ(header, "step,time,dt,outer_iterations,total_outer_iterations,is_converged,"
                      "mass_residual,momentum_residual,courant,rate_of_change,retries,"
                      "wall_seconds");
    int rows = 0;
    for (std::string line; std::getline(solver, line);) {
        ++rows;
    }
    EXPECT_EQ(rows, 8); // 0.5 / 0.0625 steps
    std::ifstream samples(out / "samples/vertical_centerline.csv");
    std::getline(samples, header);
    EXPECT_EQ(header, "x,y,u,v,p");
}

/// The numbers of a CSV file's rows after its header, row by row.
std::vector<std::vector<double>> csv_numbers(const fs::path& csv)
{
    std::vector<std::vector<double>> rows;
    const std::vector<std::string> lines = fddem::test::lines_of(fddem::test::file_contents(csv));
    for (std::size_t k = 1; k < lines.size(); ++k) {
        std::vector<double>& row = rows.emplace_back();
        std::istringstream in(lines[k]);
        for (std::string field; std::getline(in, field, ',');) {
            row.push_back(std::stod(field));
        }
    }
    return rows;
}

// MPI starts only when a hypre solver is built (fddem/linsolve/mpi_runtime.hpp): a hypre run
// must still work from the plain program, on one process, and agree with the FFTW run.
TEST_F(Cli, HyprePressureSolverStartsMpiOnDemandAndAgreesWithFftw)
{
    const fs::path fft = root_ / "fft";
    const fs::path hypre = root_ / "hypre";
    ASSERT_EQ(run("run " + case_file_.string() + " -q -o " + fft.string()).status, 0);
    const Result r = run("run " + case_file_.string() +
                         " -q --set simple.pressure_solver=hypre -o " + hypre.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string summary = fddem::test::file_contents(hypre / "summary.json");
    EXPECT_NE(summary.find("\"pressure_solver\" : \"hypre"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"build_mpi_processes\" : \"1\""), std::string::npos) << summary;
    const auto a = csv_numbers(fft / "samples/vertical_centerline.csv");
    const auto b = csv_numbers(hypre / "samples/vertical_centerline.csv");
    ASSERT_EQ(a.size(), 17U);
    ASSERT_EQ(b.size(), a.size());
    double largest = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        largest = std::max(largest, std::abs(a[k][2] - b[k][2])); // u
    }
    // Both solve the same pressure equation, hypre to a relative residual of 1e-10.
    EXPECT_LT(largest, 1e-7);
}

TEST_F(Cli, SettledRunStopsAndTellsHowToGoOn)
{
    // A neutrally buoyant disk rests from the first step: time.rest_speed ends the run at
    // time.min_end, not time.end; the continuation says to raise time.min_end, and doing so
    // runs on.
    const fs::path case_file = root_ / "resting.toml";
    std::ofstream(case_file) << R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[fluid]
density = 1.0
viscosity = 0.1
gravity = [0.0, -10.0]
[time]
dt = 0.02
end = 5.0
rest_speed = 1e-6
rest_duration = 0.04
min_end = 0.1
[[bodies]]
diameter = 0.25
density = 1.0
position = [0.5, 0.5]
)";
    const fs::path out = root_ / "resting";
    const Result first = run("run " + case_file.string() + " -o " + out.string());
    ASSERT_EQ(first.status, 0) << first.output;
    EXPECT_NE(first.output.find("every free body slower than time.rest_speed"), std::string::npos)
        << first.output;
    const std::string summary = fddem::test::file_contents(out / "summary.json");
    EXPECT_NE(summary.find("\"steps\" : 5,"), std::string::npos) << summary; // t = 0.1
    EXPECT_NE(summary.find("\"at_rest_since\" : 0.02"), std::string::npos) << summary;

    const Result again = run("run --restart " + out.string());
    ASSERT_EQ(again.status, 0) << again.output;
    EXPECT_NE(again.output.find("nothing to do"), std::string::npos) << again.output;
    EXPECT_NE(again.output.find("--set time.min_end="), std::string::npos) << again.output;

    const Result further = run("run --restart " + out.string() + " --set time.min_end=0.2");
    ASSERT_EQ(further.status, 0) << further.output;
    const std::string extended = fddem::test::file_contents(out / "summary.json");
    EXPECT_NE(extended.find("\"steps\" : 10,"), std::string::npos) << extended;
}

TEST_F(Cli, ExistingRunDirectoryIsKeptWithoutForce)
{
    const fs::path out = root_ / "run";
    fs::create_directories(out);
    std::ofstream(out / "precious.txt") << "keep me";
    const Result r = run("run " + case_file_.string() + " -o " + out.string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("use --force"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "solver.csv"));
    std::ifstream kept(out / "precious.txt");
    std::string text;
    std::getline(kept, text);
    EXPECT_EQ(text, "keep me");
}

struct BadRun {
    const char* name;
    std::string extra;   ///< arguments after the case file
    std::string message; ///< expected in the one error line
};

class CliBadInput : public Cli, public ::testing::WithParamInterface<BadRun> {};

TEST_P(CliBadInput, ExitsWithStatusTwoAndWritesNothing)
{
    const BadRun& bad = GetParam();
    const fs::path out = root_ / "run";
    std::string arguments = "run " + case_file_.string() + " " + bad.extra;
    if (bad.extra.find("-o ") == std::string::npos) {
        arguments += " -o " + out.string();
    }
    const Result r = run(arguments);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out)) << "something was written for " << bad.name;
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInput,
    ::testing::Values(
        BadRun{"misspelt_override", "--set fluid.viscosty=0.1", "did you mean 'fluid.viscosity'"},
        BadRun{"negative_viscosity", "--set fluid.viscosity=-1",
               "fluid.viscosity: -1 Pa·s is out of range"},
        BadRun{"zero_dt", "--set time.dt=0", "time.dt: 0 s is out of range"},
        BadRun{"unknown_time_scheme", "--set time.scheme=crank_nicolson",
               "time.scheme: 'crank_nicolson' is not valid: must be one of: euler, bdf2"},
        BadRun{"bad_solver", "--set simple.pressure_solver=petsc",
               "must be one of: auto, fft, hypre"},
        BadRun{"unwritable_output", "-o /proc/fddem/run", "cannot create the run directory"},
        BadRun{"unknown_option", "--frobnicate", "frobnicate"},
        // Issue 17: each of these ran (or failed with exit 1) or blamed the wrong thing.
        BadRun{"unknown_section_override", "--set nosuch.key=1",
               "fddem: --set: nosuch: unknown section 'nosuch'"},
        BadRun{"overflowing_override", "--set time.dt=1e400",
               "--set: time.dt: cannot read the value '1e400'"},
        BadRun{"newline_in_override", "--set \"$(printf 'time.dt=0.004\\ntime.end=5')\"",
               "--set: time.dt: 'time.dt=0.004\\ntime.end=5' holds a control character"},
        BadRun{"integer_without_exact_double", "--set fluid.density=9007199254740993",
               "fluid.density: the integer 9007199254740993 has no exact floating-point value"},
        BadRun{"box_far_from_origin", "--set domain.origin=[1e308,0]",
               "domain.origin: the box spans [1e+308, 1e+308] on axis 0"},
        BadRun{"end_between_steps", "--set time.end=0.55",
               "time.end: 0.55 s is not a whole number of time steps of 0.0625 s"},
        BadRun{"too_many_steps", "--set time.dt=1e-12 --set time.end=1",
               "more than time.max_steps = 100000000"},
        BadRun{"grid_beyond_the_machine", "--set domain.cells=[100000,100000]",
               "domain.cells: a grid of 100000 × 100000 cells needs about 7.92e+03 GiB "
               "(estimate), more than the memory of this machine"},
        BadRun{"grid_beyond_max_memory", "--set run.max_memory=1e6",
               "domain.cells: a grid of 16 × 16 cells needs about 48.2 MiB (estimate), more "
               "than run.max_memory = 1e+06 B (0.954 MiB); use fewer cells"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST_F(Cli, MissingCaseFileIsBadInput)
{
    const Result r = run("run " + (root_ / "nope.toml").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("cannot open the case file"), std::string::npos) << r.output;
}

TEST_F(Cli, BadCommandLinesNameTheirFault)
{
    // Issue 17: `fddem bogus` said only "A subcommand is required", and a directory given as
    // the case file read as an empty case ("missing required key 'domain.size'").
    const std::vector<std::pair<std::string, std::string>> bad{
        {"bogus", "unknown subcommand 'bogus' (the subcommands are run, info, validate, plot)"},
        {"run " + root_.string(), root_.string() + ": is a directory, not a case file"}};
    for (const auto& [arguments, message] : bad) {
        const Result r = run(arguments);
        EXPECT_EQ(r.status, 2) << arguments;
        EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}

TEST_F(Cli, InfoListsKeysAndLibraries)
{
    const Result keys = run("info --keys");
    EXPECT_EQ(keys.status, 0);
    EXPECT_NE(keys.output.find("viscosity"), std::string::npos);
    const Result info = run("info");
    EXPECT_EQ(info.status, 0);
    EXPECT_NE(info.output.find("hypre"), std::string::npos);
    EXPECT_NE(info.output.find("fftw"), std::string::npos);
}

} // namespace
