// SPDX-License-Identifier: MIT
// The library's driver called directly, without the fddem program: a small lid-driven cavity and
// a settling disk run into their run directories, whose files hold the documented columns, one
// row per step or output, and the physics (the lid drags the fluid along and the return flow
// carries as much back; a heavy disk sinks, no faster than in free fall); an interrupt from the
// monitor stops a run with a checkpoint, and continuing it gives the uninterrupted run's history.

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/run/run_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/csv_table.hpp"
#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;
using test::file_contents;
using test::read_csv_table;
using test::solver_rows_without_wall_time;

/// Unit square, lid speed 1 at y = 1, Re = 100, 16 × 16 cells, 20 steps to t = 1, and the
/// vertical centreline sampled at the end at the centres of its 16 u faces (x = 8 h).
const char* const cavity_case = R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[walls]
y_high = [1.0, 0.0]
[fluid]
density = 1.0
viscosity = 0.01
[time]
dt = 0.05
end = 1.0
[simple]
tolerance = 1e-4
[[output.lines]]
name = "centre"
from = [0.5, 0.03125]
to = [0.5, 0.96875]
points = 16
)";

/// A disk twice as dense as the fluid released at rest in a closed box, 10 steps.
const char* const settling_disk_case = R"([domain]
size = [1.0, 2.0]
cells = [16, 32]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -9.81]
[[bodies]]
diameter = 0.25
density = 2.0
position = [0.5, 1.2]
n_rings = 2
[time]
dt = 0.01
end = 0.1
[simple]
tolerance = 1e-3
fft_planning = "estimate"
)";

/// Keeps the messages; asks the run to stop (as SIGINT would) after step `stop_after`.
class TestMonitor final : public RunMonitor {
public:
    explicit TestMonitor(long stop_after = 0) : stop_after_(stop_after) {}
    void message(const std::string& text) override { messages.push_back(text); }
    void step_done(long step, double /*time*/, int /*outer_iterations*/) override
    {
        last_step = step;
    }
    [[nodiscard]] int pending_interrupt() override
    {
        return stop_after_ > 0 && last_step >= stop_after_ ? SIGINT : 0;
    }
    [[nodiscard]] bool has_message(const std::string& part) const
    {
        return std::any_of(messages.begin(), messages.end(), [&part](const std::string& m) {
            return m.find(part) != std::string::npos;
        });
    }

    std::vector<std::string> messages;
    long last_step = 0;

private:
    long stop_after_;
};

TEST(RunCase, TheLastLineCountsTheUnconvergedSteps)
{
    // One outer iteration a step cannot reach the tolerance: every step ends unconverged, and
    // the last line says so (the warnings name only the first 10).
    const fs::path run = test::fresh_test_directory("fddem_run_case_") / "cavity";
    TestMonitor monitor;
    const RunResult result =
        run_case(read_case_string(cavity_case, "test:cavity",
                                  {"simple.max_outer_iterations=1", "simple.tolerance=1e-8"}),
                 run, monitor);
    ASSERT_EQ(result.outcome, RunResult::Outcome::completed);
    EXPECT_TRUE(monitor.has_message("(20 of the 20 steps unconverged, largest Courant number "))
        << monitor.messages.back();
    // and a converged run's line does not
    TestMonitor clean;
    const fs::path clean_run = test::fresh_test_directory("fddem_run_case_") / "cavity";
    ASSERT_EQ(run_case(read_case_string(cavity_case, "test:cavity"), clean_run, clean).outcome,
              RunResult::Outcome::completed);
    EXPECT_FALSE(clean.has_message("unconverged, largest")) << clean.messages.back();
}

TEST(RunCase, ASteadyMarchsLastLineSaysWhetherItReachedTheSteadyState)
{
    // time.steady: the pseudo-time steps grow and need not converge on the way, so they get no
    // warning each; the last line says whether the steady test was met and the last step solved.
    const std::vector<std::string> steady = {"time.steady=true", "time.steady_tolerance=1e-6",
                                             "time.end=200", "simple.tolerance=1e-5"};
    TestMonitor reached;
    ASSERT_EQ(run_case(read_case_string(cavity_case, "test:cavity", steady),
                       test::fresh_test_directory("fddem_run_case_") / "cavity", reached)
                  .outcome,
              RunResult::Outcome::completed);
    EXPECT_TRUE(reached.has_message("pseudo-time steps to t = ")) << reached.messages.back();
    EXPECT_TRUE(reached.has_message("; steady: max|∂u/∂t| L/U² = ")) << reached.messages.back();
    EXPECT_FALSE(reached.has_message("NOT steady")) << reached.messages.back();
    EXPECT_FALSE(reached.has_message("Courant number")) << reached.messages.back();
    // Stopped after 3 steps, and each step cut to one outer iteration: not steady, and the last
    // step unconverged, both said as warnings on the last line.
    std::vector<std::string> cut = steady;
    cut.insert(cut.end(), {"time.max_steps=3", "simple.max_outer_iterations=1"});
    TestMonitor stopped;
    ASSERT_EQ(run_case(read_case_string(cavity_case, "test:cavity", cut),
                       test::fresh_test_directory("fddem_run_case_") / "cavity", stopped)
                  .outcome,
              RunResult::Outcome::completed);
    EXPECT_TRUE(stopped.has_message("warning: NOT steady: max|∂u/∂t| L/U² = "))
        << stopped.messages.back();
    EXPECT_TRUE(stopped.has_message("warning: the last step's outer iterations did not converge"))
        << stopped.messages.back();
    EXPECT_TRUE(stopped.has_message("2 of the earlier steps ended at simple.max_outer_iterations"))
        << stopped.messages.back();
    EXPECT_FALSE(stopped.has_message("SIMPLE not converged")) << stopped.messages.back();
}

TEST(RunCase, CavityRunDirectoryHoldsTheDocumentedFilesAndTheLidDrivenFlow)
{
    const fs::path run = test::fresh_test_directory("fddem_run_case_") / "cavity";
    TestMonitor monitor;
    const RunResult result = run_case(read_case_string(cavity_case, "test:cavity"), run, monitor);
    ASSERT_EQ(result.outcome, RunResult::Outcome::completed);
    EXPECT_TRUE(monitor.has_message("20 steps to t = 1 s")) << monitor.messages.back();

    const test::CsvTable solver = read_csv_table(run / "solver.csv");
    EXPECT_EQ(solver.columns,
              (std::vector<std::string>{"step", "time", "dt", "outer_iterations",
                                        "total_outer_iterations", "is_converged", "mass_residual",
                                        "momentum_residual", "courant", "rate_of_change", "retries",
                                        "wall_seconds"}));
    ASSERT_EQ(solver.rows.size(), 20U); // one row per step
    EXPECT_EQ(solver.column("step").back(), 20.0);
    EXPECT_DOUBLE_EQ(solver.column("time").back(), 1.0);
    EXPECT_EQ(solver.column("is_converged").back(), 1.0);
    EXPECT_LT(solver.column("mass_residual").back(), 1e-4); // simple.tolerance
    EXPECT_EQ(file_contents(run / "case.toml").find("[domain]") != std::string::npos, true);
    const std::string summary = file_contents(run / "summary.json");
    EXPECT_NE(summary.find("\"status\" : \"completed\""), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"steps\" : 20,"), std::string::npos) << summary;
    // No time.max_courant: no retries, so none of their limits.
    EXPECT_EQ(summary.find("retry"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("min_dt"), std::string::npos) << summary;
    // output.field_interval = 0: the initial and the final frame.
    EXPECT_TRUE(fs::exists(run / "fields/fields_000000.vtr"));
    EXPECT_TRUE(fs::exists(run / "fields/fields_000001.vtr"));
    EXPECT_FALSE(fs::exists(run / "fields/fields_000002.vtr"));
    EXPECT_TRUE(fs::exists(run / "checkpoints/checkpoint_0000000020.ckpt"));
    EXPECT_FALSE(fs::exists(run / "particles.csv")); // no bodies

    const test::CsvTable centre = read_csv_table(run / "samples/centre.csv");
    EXPECT_EQ(centre.columns, (std::vector<std::string>{"x", "y", "u", "v", "p"}));
    ASSERT_EQ(centre.rows.size(), 16U);
    const std::vector<double> u = centre.column("u");
    // The lid drags the fluid under it along; continuity sends it back lower down.
    EXPECT_GT(u.back(), 0.5);
    EXPECT_LT(*std::min_element(u.begin(), u.end()), -0.05);
    // Mass conservation: the flux through the centreline, h Σ u over its faces, is the sum of
    // the divergence of the cells left of it, which the pressure correction (eqs. (9)-(12),
    // solved directly by FFT here) leaves at round-off.
    double flux = 0.0;
    double magnitude = 0.0;
    for (const double face : u) {
        flux += face / 16.0;
        magnitude += std::abs(face) / 16.0;
    }
    EXPECT_GT(magnitude, 0.05);
    EXPECT_LT(std::abs(flux), 1e-12 * magnitude) << "flux " << flux << ", h Σ |u| " << magnitude;
}

TEST(RunCase, SummaryRecordsTheRetryLimitsTheRunApplied)
{
    std::string text = cavity_case;
    const std::string fixed_step = "dt = 0.05\n";
    text.replace(text.find(fixed_step), fixed_step.size(),
                 "dt = 0.05\nmax_courant = 0.5\nmax_retries = 3\nretry_mass_residual = 0.25\n");
    const fs::path run = test::fresh_test_directory("fddem_run_case_") / "retry";
    TestMonitor monitor;
    ASSERT_EQ(run_case(read_case_string(text, "test:retry"), run, monitor).outcome,
              RunResult::Outcome::completed);
    const std::string summary = file_contents(run / "summary.json");
    // time.retry_courant not given: 4 × time.max_courant (retry_courant_limit).
    EXPECT_NE(summary.find("\"retry_courant\" : 2.0,"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"retry_mass_residual\" : 0.25,"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"max_retries\" : 3,"), std::string::npos) << summary;
    // time.min_dt not given: 1e-6 time.dt (time_step_control.hpp).
    const std::string min_dt_key = "\"min_dt\" : ";
    const std::size_t at = summary.find(min_dt_key);
    ASSERT_NE(at, std::string::npos) << summary;
    EXPECT_DOUBLE_EQ(std::stod(summary.substr(at + min_dt_key.size())), 1e-6 * 0.05);
}

TEST(RunCase, SettlingDiskRowsFollowTheBodyDownNoFasterThanFreeFall)
{
    const fs::path run = test::fresh_test_directory("fddem_run_case_") / "disk";
    TestMonitor monitor;
    const RunResult result =
        run_case(read_case_string(settling_disk_case, "test:disk"), run, monitor);
    ASSERT_EQ(result.outcome, RunResult::Outcome::completed);

    const test::CsvTable particles = read_csv_table(run / "particles.csv");
    EXPECT_EQ(particles.columns, (std::vector<std::string>{
                                     "time", "id", "x", "y", "u", "v", "omega", "theta", "fx", "fy",
                                     "torque", "contact_fx", "contact_fy", "contact_torque",
                                     "lubrication_fx", "lubrication_fy", "lubrication_torque"}));
    // output.particle_interval = 0: the initial state, then every one of the 10 steps.
    ASSERT_EQ(particles.rows.size(), 11U);
    const std::vector<double> time = particles.column("time");
    const std::vector<double> v = particles.column("v");
    const std::vector<double> y = particles.column("y");
    EXPECT_EQ(time.front(), 0.0);
    EXPECT_EQ(v.front(), 0.0);
    EXPECT_EQ(y.front(), 1.2);
    const test::CsvTable solver = read_csv_table(run / "solver.csv");
    ASSERT_EQ(solver.rows.size(), 10U);
    EXPECT_EQ(time.back(), solver.column("time").back());
    // It sinks, and never faster than the buoyant free fall (1 − ρf/ρs) g t: the added mass and
    // the drag of the fluid only slow it.
    const double free_fall = (1.0 - 1.0 / 2.0) * 9.81;
    for (std::size_t k = 1; k < v.size(); ++k) {
        EXPECT_LT(v[k], v[k - 1]) << "row " << k;
        EXPECT_GT(v[k], -free_fall * time[k]) << "row " << k;
        EXPECT_LT(y[k], y[k - 1]) << "row " << k;
    }
    // The fluid pushes back: the hydrodynamic force on it points up.
    EXPECT_GT(particles.column("fy").back(), 0.0);
    EXPECT_TRUE(fs::exists(run / "particles/particles_000001.vtp"));
}

TEST(RunCase, InterruptedRunContinuesToTheUninterruptedHistory)
{
    const fs::path dir = test::fresh_test_directory("fddem_run_case_");
    const CaseConfig config = read_case_string(cavity_case, "test:cavity");
    TestMonitor whole;
    ASSERT_EQ(run_case(config, dir / "whole", whole).outcome, RunResult::Outcome::completed);

    TestMonitor stopping(7);
    const RunResult stopped = run_case(config, dir / "parts", stopping);
    EXPECT_EQ(stopped.outcome, RunResult::Outcome::interrupted);
    EXPECT_EQ(stopped.signal, SIGINT);
    EXPECT_EQ(stopping.last_step, 7);
    EXPECT_TRUE(fs::exists(dir / "parts/checkpoints/checkpoint_0000000007.ckpt"));
    EXPECT_NE(file_contents(dir / "parts/summary.json")
                  .find("\"status\" : \"interrupted by SIGINT at step 7\""),
              std::string::npos);

    TestMonitor continuing;
    const CaseConfig again = read_restart_case(dir / "parts", {});
    EXPECT_EQ(restart_run(again, dir / "parts", continuing).outcome, RunResult::Outcome::completed);
    EXPECT_TRUE(continuing.has_message("from step 7"));
    EXPECT_EQ(solver_rows_without_wall_time(dir / "parts"),
              solver_rows_without_wall_time(dir / "whole"));
    EXPECT_EQ(file_contents(dir / "parts/samples/centre.csv"),
              file_contents(dir / "whole/samples/centre.csv"));
    EXPECT_NE(file_contents(dir / "parts/summary.json").find("\"restarts\" : 1,"),
              std::string::npos);
}

TEST(RunCase, ExistingRunDirectoryIsRefusedUnlessOverwritten)
{
    const fs::path run = test::fresh_test_directory("fddem_run_case_");
    std::ofstream(run / "keep.txt") << "keep me";
    TestMonitor monitor;
    const CaseConfig config = read_case_string(cavity_case, "test:cavity");
    EXPECT_THROW((void)run_case(config, run, monitor), InputError);
    EXPECT_FALSE(fs::exists(run / "solver.csv"));
    EXPECT_EQ(run_case(config, run, monitor, true).outcome, RunResult::Outcome::completed);
    EXPECT_TRUE(fs::exists(run / "solver.csv"));
}

/// A fixed sphere of d = 8 h, one step.
const std::string fixed_sphere_case = R"(
[domain]
size = [1.0, 1.0, 1.0]
cells = [16, 16, 16]
[fluid]
density = 1.0
viscosity = 0.1
[[bodies]]
shape = "sphere"
diameter = 0.5
density = 2.0
position = [0.5, 0.5, 0.5]
motion = "fixed"
[time]
dt = 0.01
end = 0.01
)";

TEST(RunCase, ASphereWithThePaperLayoutIsWarnedOfItsOvershootingForcing)
{
    // ForcingOperator.ThePaperLayoutOfASphereOvershoots: the warning names the layout the 3D
    // cases use instead; a sphere with it, or a disk with the paper's, gets none.
    const std::string& sphere = fixed_sphere_case;
    const std::string warning = "warning: coupling.markers = \"paper\" on spheres";
    for (const bool is_paper : {true, false}) {
        const fs::path run = test::fresh_test_directory("fddem_run_case_") / "sphere";
        TestMonitor monitor;
        const CaseConfig config = read_case_string(
            sphere, "test:sphere",
            {is_paper ? "coupling.markers=\"paper\"" : "coupling.markers=\"retracted\""});
        ASSERT_EQ(run_case(config, run, monitor).outcome, RunResult::Outcome::completed);
        EXPECT_EQ(monitor.has_message(warning), is_paper);
        if (is_paper) {
            EXPECT_TRUE(monitor.has_message("use \"retracted\""));
        }
    }
    const fs::path run = test::fresh_test_directory("fddem_run_case_") / "disk";
    TestMonitor monitor;
    ASSERT_EQ(run_case(read_case_string(settling_disk_case, "test:disk"), run, monitor).outcome,
              RunResult::Outcome::completed);
    EXPECT_FALSE(monitor.has_message(warning));
}

TEST(RunCase, ASphereWithSparseSurfaceMarkersIsWarnedThatItsShellLeaks)
{
    // The shell 1.4 h apart let ten Cate's E4 sphere fall 6 % fast (docs/method.md §4, "The
    // fluid inside a body"); markers h apart are not warned of.
    const std::string warning = "warning: coupling.markers = \"surface\" on spheres";
    for (const bool is_sparse : {true, false}) {
        const fs::path run = test::fresh_test_directory("fddem_run_case_") / "sphere";
        TestMonitor monitor;
        const CaseConfig config = read_case_string(
            fixed_sphere_case, "test:sphere",
            {"coupling.markers=\"surface\"", is_sparse ? "coupling.marker_spacing_ratio=1.4"
                                                       : "coupling.marker_spacing_ratio=1.0"});
        ASSERT_EQ(run_case(config, run, monitor).outcome, RunResult::Outcome::completed);
        EXPECT_EQ(monitor.has_message(warning), is_sparse);
        if (is_sparse) {
            EXPECT_TRUE(monitor.has_message("set coupling.marker_spacing_ratio = 1.0"));
        }
    }
}

TEST(RunCase, AFineSphereWithThePaperForcingIsWarnedOfItsOvershoot)
{
    // ForcingOperator.TheRetractedMarkersOfASphereOvershootFromTwelveCellsPerDiameter: above
    // about 10 cells per diameter eq. (15) as the paper writes it overshoots; the warning names
    // coupling.normalised_forcing, which removes it. d/h = 8 and the option on get none.
    const std::string& sphere = fixed_sphere_case;
    const std::string warning = "warning: spheres of 16 cells per diameter";
    const auto warns = [&](std::vector<std::string> settings) {
        const fs::path run = test::fresh_test_directory("fddem_run_case_") / "sphere";
        TestMonitor monitor;
        settings.emplace_back("coupling.markers=\"retracted\"");
        const CaseConfig config = read_case_string(sphere, "test:sphere", settings);
        EXPECT_EQ(run_case(config, run, monitor).outcome, RunResult::Outcome::completed);
        return monitor.has_message(warning) && monitor.has_message("coupling.normalised_forcing");
    };
    EXPECT_TRUE(warns({"domain.cells=[32,32,32]"}));
    EXPECT_FALSE(warns({"domain.cells=[32,32,32]", "coupling.normalised_forcing=true"}));
    EXPECT_FALSE(warns({}));
}

} // namespace
} // namespace fddem
