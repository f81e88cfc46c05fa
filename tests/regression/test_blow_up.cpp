// SPDX-License-Identifier: MIT
// A run that fails numerically, as a user meets it: a disk pushed at a prescribed velocity
// through the floor with collisions off (contact.model = "none") until its markers leave the
// box. fddem must stop with exit status 3 and a message naming the step, the time and the body;
// roll the simulation back to the last good step; close the outputs there (solver.csv, the
// fields, the samples); and leave a checkpoint of that state from which `--restart` continues.
// The rollback is exact: the closing fields equal those of a run that simply ends at that step,
// and a restart from the failure checkpoint fails again at the same step with the same history.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "support/files_and_programs.hpp"

namespace {

namespace fs = std::filesystem;
using fddem::test::file_contents;
using fddem::test::lines_of;
using fddem::test::ProgramResult;
using fddem::test::solver_rows_without_wall_time;

// The disk's centre starts at y = 0.5 and moves down 0.1 per step: its lowest markers are
// below the floor from step 3 on and leave the kernel's storage a few steps later.
const char* const sinking_disk = R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[fluid]
density = 1.0
viscosity = 0.1
[[bodies]]
diameter = 0.25
density = 2.0
position = [0.5, 0.5]
velocity = [0.0, -10.0]
motion = "prescribed"
n_rings = 2
[contact]
model = "none"
[time]
dt = 0.01
end = 1.0
[simple]
tolerance = 1e-4
fft_planning = "estimate"
[output]
field_interval = 0.02
[[output.lines]]
name = "axis"
from = [0.5, 0.0]
to = [0.5, 1.0]
points = 17
)";

class BlowUp : public ::testing::Test {
protected:
    void SetUp() override
    {
        root_ = fddem::test::fresh_test_directory("fddem_blow_up_test_");
        case_file_ = root_ / "sinking_disk.toml";
        std::ofstream(case_file_) << sinking_disk;
    }
    void TearDown() override { fs::remove_all(root_); }

    [[nodiscard]] ProgramResult run(const std::string& arguments) const
    {
        return fddem::test::run_fddem(arguments, root_ / "fddem.log");
    }

    fs::path root_;
    fs::path case_file_;
};

/// The step named by "numerical failure at step N" (−1 if there is none).
long failed_step(const std::string& output)
{
    std::smatch m;
    const std::regex pattern(R"(numerical failure at step (\d+), t = ([0-9.e+-]+) s, in body 1:)");
    return std::regex_search(output, m, pattern) ? std::stol(m[1].str()) : -1;
}

std::string last_row(const fs::path& csv)
{
    const std::vector<std::string> rows = lines_of(file_contents(csv));
    return rows.empty() ? std::string() : rows.back();
}

TEST_F(BlowUp, StopsWithStatus3AndAMessageRollsBackAndCheckpointsTheLastGoodStep)
{
    const fs::path failed = root_ / "failed";
    const ProgramResult r = run("run " + case_file_.string() + " -o " + failed.string() + " -q");
    ASSERT_EQ(r.status, 3) << r.output;
    const long step = failed_step(r.output);
    ASSERT_GT(step, 3) << r.output; // markers below the floor are fine while they fit
    ASSERT_LT(step, 20) << r.output;
    EXPECT_NE(r.output.find("a marker of the body left the box"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("continue from it with: fddem run --restart"), std::string::npos);

    // The outputs end at the last good step, with a checkpoint of it.
    const std::string last = last_row(failed / "solver.csv");
    EXPECT_EQ(std::stol(last.substr(0, last.find(','))), step - 1);
    const fs::path checkpoint =
        failed / "checkpoints" /
        ("checkpoint_" + std::string(10 - std::to_string(step - 1).size(), '0') +
         std::to_string(step - 1) + ".ckpt");
    EXPECT_TRUE(fs::exists(checkpoint)) << checkpoint;
    const std::string summary = file_contents(failed / "summary.json");
    EXPECT_NE(summary.find("\"status\" : \"failed: step " + std::to_string(step)),
              std::string::npos)
        << summary;
    EXPECT_TRUE(fs::exists(failed / "samples" / "axis.csv"));

    // Exact rollback: a run that ends at the last good step closes with the same fields.
    const fs::path ended = root_ / "ended";
    const std::string end_time = std::to_string(0.01 * static_cast<double>(step - 1));
    const ProgramResult e = run("run " + case_file_.string() + " -o " + ended.string() +
                                " -q --set time.end=" + end_time);
    ASSERT_EQ(e.status, 0) << e.output;
    EXPECT_EQ(solver_rows_without_wall_time(ended), solver_rows_without_wall_time(failed));
    EXPECT_EQ(file_contents(ended / "fields.pvd"), file_contents(failed / "fields.pvd"));
    for (const auto& f : fs::directory_iterator(ended / "fields")) {
        EXPECT_EQ(file_contents(f.path()), file_contents(failed / "fields" / f.path().filename()))
            << f.path().filename();
    }
    EXPECT_EQ(file_contents(ended / "particles.csv"), file_contents(failed / "particles.csv"));
    EXPECT_EQ(file_contents(ended / "samples" / "axis.csv"),
              file_contents(failed / "samples" / "axis.csv"));

    // The failure checkpoint continues the run: it fails again at the same step, the same way.
    const ProgramResult again = run("run --restart " + failed.string() + " -q");
    ASSERT_EQ(again.status, 3) << again.output;
    EXPECT_EQ(failed_step(again.output), step) << again.output;
    EXPECT_EQ(solver_rows_without_wall_time(failed), solver_rows_without_wall_time(ended));
}

TEST_F(BlowUp, ASmallerTimeStepFromTheFailureCheckpointGoesOnFromTheLastGoodStep)
{
    const fs::path failed = root_ / "failed";
    const ProgramResult first =
        run("run " + case_file_.string() + " -o " + failed.string() + " -q");
    ASSERT_EQ(first.status, 3) << first.output;
    const long step = failed_step(first.output);
    const double good_time = 0.01 * static_cast<double>(step - 1);

    // The disk still leaves the box, but only after the steps of Δt = 0.001 from the last good
    // step take it to where the step of 0.01 took it (no later, no earlier than that step).
    const ProgramResult r = run("run --restart " + failed.string() + " -q --set time.dt=0.001");
    ASSERT_EQ(r.status, 3) << r.output;
    const long small_steps = failed_step(r.output) - (step - 1);
    EXPECT_GE(small_steps, 1) << r.output;
    EXPECT_LE(small_steps, 10) << r.output;
    const std::string last = last_row(failed / "solver.csv");
    const double time = std::stod(last.substr(last.find(',') + 1));
    EXPECT_NEAR(time, good_time + 0.001 * static_cast<double>(small_steps - 1), 1e-12);
}

} // namespace
