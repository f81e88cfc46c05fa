// SPDX-License-Identifier: MIT
// `fddem run --restart` as a user meets it. Three disks collide with each other and the floor
// (32 × 64 cells, Δt = 0.01 s, 60 steps, a checkpoint every 5 steps). A run continued from a
// checkpoint — a copy with the later checkpoints removed, a run stopped by time.max_steps, a run
// killed with SIGKILL at a random moment, a run stopped by SIGTERM, a run whose newest
// checkpoint is damaged — writes solver.csv (but for its wall_seconds column), particles.csv,
// every field and particle frame, the line samples and the .pvd collections byte for byte as
// the uninterrupted run; so does a finished fluid-only run extended to a later end. Bad restart
// input ends with one message, exit status 2, and changes nothing. A BDF2 run continued from a
// checkpoint is the uninterrupted one as well. A body let go by bodies.release_time is the run
// stopped at the release and continued with the body made free.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "support/files_and_programs.hpp"

namespace {

namespace fs = std::filesystem;

const char* const three_disks =
    R"(# Three disks: the lower one lands on the floor (step 8); the third, thrown to the left,
# hits the upper one (steps 10-11) and lands (step 30); the upper one comes to rest on the
# other two (steps 34-48) while they slide apart on the floor.
[domain]
size = [1.0, 2.0]
cells = [32, 64]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -9.81]
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.5, 0.14]
n_rings = 3
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.53, 0.45]
n_rings = 3
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.8, 0.3]
velocity = [-2.0, 0.0]
n_rings = 3
[contact]
restitution = 0.5
[coupling]
markers = "paper"   # the layout the contacts at steps 10 and 40 were timed with
[time]
dt = 0.01
end = 0.6
[simple]
tolerance = 1e-3
max_outer_iterations = 20
fft_planning = "estimate"   # the same FFT plans in every process: runs compare bit for bit
[output]
field_interval = 0.1
particle_interval = 0.0
[[output.lines]]
name = "centre"
from = [0.5, 0.0]
to = [0.5, 2.0]
points = 33
[checkpoint]
step_interval = 5
keep = 100
)";

constexpr int checkpoint_interval = 5;

using Result = fddem::test::ProgramResult;
using fddem::test::file_contents;
using fddem::test::lines_of;
using fddem::test::solver_rows_without_wall_time;

/// Every file under `root` (relative path → contents).
std::map<std::string, std::string> snapshot(const fs::path& root)
{
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (entry.is_regular_file()) {
            files[fs::relative(entry.path(), root).string()] = file_contents(entry.path());
        }
    }
    return files;
}

long step_of_last_row(const fs::path& solver_csv)
{
    const std::vector<std::string> rows = lines_of(file_contents(solver_csv));
    return rows.size() < 2 ? 0 : std::stol(rows.back().substr(0, rows.back().find(',')));
}

class Restart : public ::testing::Test {
protected:
    void SetUp() override
    {
        root_ = fddem::test::fresh_test_directory("fddem_restart_test_");
        case_file_ = root_ / "three_disks.toml";
        std::ofstream(case_file_) << three_disks;
        log_ = root_ / "fddem.log";
    }
    void TearDown() override { fs::remove_all(root_); }

    /// Runs fddem to its end.
    Result run(const std::string& arguments) const
    {
        return fddem::test::run_fddem(arguments, log_);
    }

    /// Starts `fddem run -q` of the case into `directory` without waiting.
    pid_t start(const fs::path& directory) const
    {
        return fddem::test::start_fddem(
            {"run", case_file_.string(), "-o", directory.string(), "-q"}, log_);
    }

    /// Waits until `directory` holds `n` checkpoints (or 120 s pass).
    static void wait_for_checkpoints(const fs::path& directory, int n)
    {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < deadline) {
            std::error_code error;
            int count = 0;
            for (const auto& f : fs::directory_iterator(directory / "checkpoints", error)) {
                count += f.path().extension() == ".ckpt" ? 1 : 0;
            }
            if (count >= n) {
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        ADD_FAILURE() << "no " << n << " checkpoints in " << directory;
    }

    /// The uninterrupted run (`overrides`: --set options, each with its leading space).
    fs::path reference(const std::string& overrides = "")
    {
        const fs::path directory = root_ / "reference";
        const Result r =
            run("run " + case_file_.string() + " -o " + directory.string() + " -q" + overrides);
        EXPECT_EQ(r.status, 0) << r.output;
        return directory;
    }

    /// A copy of `reference` as if the run had been stopped right after `step`: the
    /// checkpoints of later steps removed (the outputs beyond it stay, for the restart to cut).
    fs::path copy_stopped_at(const fs::path& reference, long step, const std::string& name)
    {
        const fs::path directory = root_ / name;
        fs::copy(reference, directory, fs::copy_options::recursive);
        for (const auto& f : fs::directory_iterator(directory / "checkpoints")) {
            const std::string stem = f.path().stem().string();
            if (std::stol(stem.substr(stem.find('_') + 1)) > step) {
                fs::remove(f.path());
            }
        }
        return directory;
    }

    fs::path root_;
    fs::path case_file_;
    fs::path log_;
};

/// The continued run's outputs are the uninterrupted run's, byte for byte.
void expect_same_outputs(const fs::path& reference, const fs::path& continued)
{
    EXPECT_EQ(solver_rows_without_wall_time(reference), solver_rows_without_wall_time(continued))
        << continued;
    EXPECT_TRUE(file_contents(reference / "particles.csv") ==
                file_contents(continued / "particles.csv"))
        << continued;
    for (const char* folder : {"fields", "particles", "samples"}) {
        std::vector<std::string> a;
        std::vector<std::string> b;
        for (const auto& f : fs::directory_iterator(reference / folder)) {
            a.push_back(f.path().filename().string());
            EXPECT_TRUE(file_contents(f.path()) ==
                        file_contents(continued / folder / f.path().filename()))
                << continued / folder / f.path().filename();
        }
        for (const auto& f : fs::directory_iterator(continued / folder)) {
            b.push_back(f.path().filename().string());
        }
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_EQ(a, b) << folder;
    }
    for (const char* file : {"fields.pvd", "particles.pvd"}) {
        EXPECT_EQ(file_contents(reference / file), file_contents(continued / file)) << file;
    }
}

/// Does particles.csv show a contact force on some body in the step ending at `step`?
bool has_contact_at(const fs::path& run, long step)
{
    const std::vector<std::string> rows = lines_of(file_contents(run / "particles.csv"));
    // One row per body per step (particle_interval 0): 3 rows per step after the initial ones.
    bool contact = false;
    for (std::size_t k = 1; k < rows.size(); ++k) {
        std::vector<std::string> cells;
        std::istringstream row(rows[k]);
        for (std::string cell; std::getline(row, cell, ',');) {
            cells.push_back(cell);
        }
        const double time = std::stod(cells[0]);
        if (std::lround(time / 0.01) == step) {
            contact = contact || std::stod(cells[11]) != 0.0 || std::stod(cells[12]) != 0.0;
        }
    }
    return contact;
}

TEST_F(Restart, ContinuedFromCheckpointsTheRunIsBitIdentical)
{
    const fs::path ref = reference();
    // Step 5: nothing touches. Step 10: two disks collide (a contact in flight). Step 40: one
    // disk rests on the other two, which touch the floor.
    ASSERT_FALSE(has_contact_at(ref, 5));
    ASSERT_TRUE(has_contact_at(ref, 10));
    ASSERT_TRUE(has_contact_at(ref, 40));
    for (const long step : {5L, 10L, 40L}) {
        const fs::path copy = copy_stopped_at(ref, step, "stopped_at_" + std::to_string(step));
        const Result r = run("run --restart " + copy.string() + " -q");
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(
            r.output.find("restarting " + copy.string() + " from step " + std::to_string(step)),
            std::string::npos)
            << r.output;
        expect_same_outputs(ref, copy);
    }
}

TEST_F(Restart, ContinuedBdf2RunIsBitIdentical)
{
    // time.scheme = "bdf2" reads u^{n−1}, U^{n−1}, ω^{n−1} and the last Δt besides the level-n
    // state: the checkpoint must carry them (format version 6). Step 1 is Euler, so step 5
    // (before any contact) and step 10 (a contact in flight) both continue BDF2 steps.
    const fs::path ref = reference(" --set time.scheme=bdf2");
    ASSERT_NE(file_contents(ref / "case.toml").find("scheme = 'bdf2'"), std::string::npos);
    for (const long step : {5L, 10L}) {
        const fs::path copy = copy_stopped_at(ref, step, "bdf2_stopped_at_" + std::to_string(step));
        const Result r = run("run --restart " + copy.string() + " -q");
        ASSERT_EQ(r.status, 0) << r.output;
        expect_same_outputs(ref, copy);
    }
}

TEST_F(Restart, ContinuedImplicitFilmRunIsBitIdentical)
{
    // lubrication.coupling = "implicit" keeps the collisions under way (ContactHistory::
    // rebounds): a gap leaving one within the range is the DEM's. The checkpoint must carry them
    // (format version 7): restarted from every checkpoint through the collisions and the
    // rebounds after them, the run is the uninterrupted one, byte for byte.
    const fs::path ref =
        reference(" --set lubrication.enabled=true --set lubrication.coupling=implicit");
    // The checkpoints the restarts start from hold collisions under way: the archive writes
    // each value under its name, so a recorded rebound shows as "rebound.first".
    int with_rebounds = 0;
    for (const long step : {10L, 15L, 20L, 30L, 35L, 40L}) {
        for (const auto& f : fs::directory_iterator(ref / "checkpoints")) {
            const std::string stem = f.path().stem().string();
            if (std::stol(stem.substr(stem.find('_') + 1)) == step &&
                file_contents(f.path()).find("rebound.first") != std::string::npos) {
                ++with_rebounds;
            }
        }
    }
    EXPECT_GE(with_rebounds, 1);
    for (const long step : {10L, 15L, 20L, 30L, 35L, 40L}) {
        const fs::path copy =
            copy_stopped_at(ref, step, "implicit_stopped_at_" + std::to_string(step));
        const Result r = run("run --restart " + copy.string() + " -q");
        ASSERT_EQ(r.status, 0) << r.output;
        expect_same_outputs(ref, copy);
    }
}

TEST_F(Restart, RunStoppedByStepLimitIsExtendedToTheSameResults)
{
    const fs::path ref = reference();
    const fs::path part = root_ / "part";
    // 23 steps: the stopped run writes an end-of-run field frame at t = 0.23 s, outside the
    // field_interval series; the continued run drops it again.
    Result r =
        run("run " + case_file_.string() + " -o " + part.string() + " -q --set time.max_steps=23");
    ASSERT_EQ(r.status, 0) << r.output;
    r = run("run --restart " + part.string() + " -q --set time.max_steps=100000000");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("changed since the checkpoint: time.max_steps: 23 → 100000000"),
              std::string::npos)
        << r.output;
    expect_same_outputs(ref, part);
    EXPECT_NE(file_contents(part / "case.toml").find("max_steps = 100000000"), std::string::npos);
}

TEST_F(Restart, FinishedFluidRunExtendedToALaterEndIsTheLongerRun)
{
    // Without bodies a step reuses the momentum systems the last one assembled; the end-of-run
    // outputs of the shorter run must not change that.
    const fs::path cavity = root_ / "cavity.toml";
    std::ofstream(cavity) << R"([domain]
size = [1.0, 1.0]
cells = [16, 16]
[walls]
y_high = [1.0, 0.0]
[fluid]
density = 1.0
viscosity = 0.01
[time]
dt = 0.0625
end = 2.0
[simple]
fft_planning = "estimate"
[output]
field_interval = 0.25
[[output.lines]]
name = "centre"
from = [0.5, 0.0]
to = [0.5, 1.0]
points = 17
)";
    // Both steps of the fluid: SIMPLE's, and the projection step, which reads u^{n−1} and the
    // last Δt to linearise about (simple.algorithm; docs/method.md §1).
    for (const std::string algorithm : {"simple", "projection"}) {
        SCOPED_TRACE(algorithm);
        const std::string set = " --set simple.algorithm=" + algorithm;
        const fs::path longer = root_ / ("longer_" + algorithm);
        const fs::path extended = root_ / ("extended_" + algorithm);
        Result r = run("run " + cavity.string() + " -o " + longer.string() + " -q" + set);
        ASSERT_EQ(r.status, 0) << r.output;
        // Stopped at step 17, between two field frames: its end-of-run frame is not the
        // series'.
        r = run("run " + cavity.string() + " -o " + extended.string() +
                " -q --set time.end=1.0625" + set);
        ASSERT_EQ(r.status, 0) << r.output;
        r = run("run --restart " + extended.string() + " -q --set time.end=2.0");
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(solver_rows_without_wall_time(longer), solver_rows_without_wall_time(extended));
        for (const auto& f : fs::directory_iterator(longer / "fields")) {
            EXPECT_TRUE(file_contents(f.path()) ==
                        file_contents(extended / "fields" / f.path().filename()))
                << f.path().filename();
        }
        EXPECT_EQ(file_contents(longer / "fields.pvd"), file_contents(extended / "fields.pvd"));
        EXPECT_EQ(file_contents(longer / "samples/centre.csv"),
                  file_contents(extended / "samples/centre.csv"));
    }
}

/// The numbers of the last row of a 2D run's particles.csv (time, id, x, y, u, v, …).
std::vector<double> last_particle_row(const fs::path& run)
{
    const std::vector<std::string> rows = lines_of(file_contents(run / "particles.csv"));
    std::vector<double> cells;
    if (rows.size() < 2) {
        ADD_FAILURE() << "no rows in " << run / "particles.csv";
        return cells;
    }
    std::istringstream last(rows.back());
    for (std::string cell; std::getline(last, cell, ',');) {
        cells.push_back(std::stod(cell));
    }
    return cells;
}

/// One disk (d = 0.25, ρs = 4; the three disks' box, fluid and gravity) on `cells`, with
/// `body_keys` for the rest of its [[bodies]] entry: the head of the release cases below.
std::string one_disk_case(const std::string& cells, const std::string& body_keys)
{
    return "[domain]\nsize = [1.0, 2.0]\ncells = " + cells +
           "\n[fluid]\ndensity = 1.0\nviscosity = 0.01\ngravity = [0.0, -9.81]\n"
           "[[bodies]]\ndiameter = 0.25\ndensity = 4.0\n" +
           body_keys;
}

/// The same FFT plans in every process, and particles.csv every step without field frames.
const std::string quiet_output =
    "fft_planning = \"estimate\"\n[output]\nfield_interval = 0.0\nparticle_interval = 0.0\n";

/// A disk towed down at 1 m/s and let go at t = 0.1 s by bodies.release_time, as one run, and
/// as the two runs a user would otherwise make: the towed part to t = 0.1 s, then a restart with
/// the disk made free. `time_keys`: the [time] table's lines besides the end.
void expect_release_is_the_two_stage_run(const fs::path& root, const fs::path& log,
                                         const std::string& time_keys)
{
    const std::string head = one_disk_case("[32, 64]", "position = [0.5, 1.6]\n"
                                                       "velocity = [0.0, -1.0]\n"
                                                       "motion = \"prescribed\"\n"
                                                       "n_rings = 3\n");
    const std::string tail = "[time]\n" + time_keys +
                             "end = 0.3\n[simple]\ntolerance = 1e-3\nmax_outer_iterations = 20\n" +
                             quiet_output;
    const auto write = [&](const std::string& name, const std::string& release) {
        std::ofstream(root / name) << head + release + tail;
        return (root / name).string();
    };
    const fs::path one = root / "released";
    const fs::path two = root / "two_stages";
    Result r = fddem::test::run_fddem("run " + write("released.toml", "release_time = 0.1\n") +
                                          " -o " + one.string() + " -q",
                                      log);
    ASSERT_EQ(r.status, 0) << r.output;
    r = fddem::test::run_fddem(
        "run " + write("towed.toml", "") + " -o " + two.string() + " -q --set time.end=0.1", log);
    ASSERT_EQ(r.status, 0) << r.output;
    r = fddem::test::run_fddem(
        "run --restart " + two.string() + " -q --set bodies.1.motion=free --set time.end=0.3", log);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(solver_rows_without_wall_time(one), solver_rows_without_wall_time(two));
    EXPECT_TRUE(file_contents(one / "particles.csv") == file_contents(two / "particles.csv"));
    // It was let go: the last row's speed is past the 1 m/s it was towed at.
    EXPECT_LT(last_particle_row(one).at(5), -1.5); // v [m/s]
}

TEST_F(Restart, ReleasedBodyIsTheTwoStageRunAtAFixedStep)
{
    expect_release_is_the_two_stage_run(root_, log_, "dt = 0.01\n");
}

TEST_F(Restart, ReleasedBodyIsTheTwoStageRunWithTheCourantLimit)
{
    // The controlled step lands on the release (0.1 s is not a multiple of its steps).
    expect_release_is_the_two_stage_run(root_, log_, "dt = 0.013\nmax_courant = 0.4\n");
}

TEST_F(Restart, AHeldBodyIsNotAtRestBeforeItsRelease)
{
    // Held still (prescribed at zero velocity) until t = 0.05 s: the rest criterion must not end
    // the run while it waits, though every free body "is below the rest speed".
    const fs::path held = root_ / "held.toml";
    std::ofstream(held)
        << one_disk_case("[16, 32]", "position = [0.5, 1.5]\n"
                                     "motion = \"prescribed\"\n"
                                     "release_time = 0.05\n"
                                     "n_rings = 2\n")
        << "[time]\ndt = 0.01\nend = 0.15\nrest_speed = 0.01\nrest_duration = 0.02\n"
           "[simple]\ntolerance = 1e-3\n"
        << quiet_output;
    const fs::path directory = root_ / "held";
    const Result r = run("run " + held.string() + " -o " + directory.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::vector<double> last = last_particle_row(directory);
    EXPECT_NEAR(last.at(0), 0.15, 1e-9); // ran to its end
    EXPECT_LT(last.at(5), -0.2);         // and fell once let go
}

TEST_F(Restart, KilledRunRestartsToTheSameResults)
{
    const fs::path ref = reference();
    const fs::path killed = root_ / "killed";
    const pid_t pid = start(killed);
    wait_for_checkpoints(killed, 2);
    // A random moment after the second checkpoint: mid-step, mid-row or mid-checkpoint.
    std::mt19937 random(static_cast<unsigned>(::getpid()));
    std::this_thread::sleep_for(
        std::chrono::microseconds(std::uniform_int_distribution<int>(0, 20000)(random)));
    ::kill(pid, SIGKILL);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    ASSERT_TRUE(WIFSIGNALED(raw)) << "the run ended before it was killed";
    std::printf("killed after step %ld\n", step_of_last_row(killed / "solver.csv"));
    const Result r = run("run --restart " + killed.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    expect_same_outputs(ref, killed);
}

TEST_F(Restart, TerminatedRunWritesACheckpointAndExitsWith143)
{
    const fs::path ref = reference();
    const fs::path stopped = root_ / "stopped";
    const pid_t pid = start(stopped);
    wait_for_checkpoints(stopped, 1);
    ::kill(pid, SIGTERM);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGTERM);
    const std::string output = file_contents(log_);
    EXPECT_NE(output.find("interrupted by SIGTERM"), std::string::npos) << output;
    EXPECT_NE(output.find("continue with: fddem run --restart " + stopped.string()),
              std::string::npos)
        << output;
    // The checkpoint is of the last step written.
    const long last = step_of_last_row(stopped / "solver.csv");
    EXPECT_TRUE(fs::exists(stopped / "checkpoints" /
                           ("checkpoint_" + std::string(10 - std::to_string(last).size(), '0') +
                            std::to_string(last) + ".ckpt")))
        << "step " << last;
    EXPECT_NE(file_contents(stopped / "summary.json").find("interrupted by SIGTERM"),
              std::string::npos);
    const Result r = run("run --restart " + stopped.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    expect_same_outputs(ref, stopped);
}

TEST_F(Restart, DamagedNewestCheckpointFallsBackToThePreviousOne)
{
    const fs::path ref = reference();
    const fs::path copy = copy_stopped_at(ref, 35, "damaged");
    const fs::path newest = copy / "checkpoints/checkpoint_0000000035.ckpt";
    std::string bytes = file_contents(newest);
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x01);
    std::ofstream(newest, std::ios::binary | std::ios::trunc) << bytes;
    const Result r = run("run --restart " + copy.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("checkpoint_0000000035.ckpt is damaged"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("from step " + std::to_string(35 - checkpoint_interval)),
              std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::exists(copy / "checkpoints/checkpoint_0000000035.ckpt.damaged"));
    expect_same_outputs(ref, copy);
}

TEST_F(Restart, DeletedFieldFramesAreLeftOutOfTheCollections)
{
    // Issue 17: a restart did not notice frames the user had deleted, and fields.pvd then
    // listed missing files. Now they are left out, with a warning, and the frames after the
    // checkpoint are those of the uninterrupted run.
    const fs::path ref = reference();
    const fs::path copy = copy_stopped_at(ref, 35, "deleted_frames");
    fs::remove(copy / "fields/fields_000001.vtr");
    fs::remove(copy / "particles/particles_000002.vtp");
    const Result r = run("run --restart " + copy.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("warning: fields/fields_000001.vtr, a frame of the checkpoint, is "
                            "missing; left out of its .pvd"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("particles/particles_000002.vtp"), std::string::npos) << r.output;
    for (const char* pvd : {"fields.pvd", "particles.pvd"}) {
        const std::string text = file_contents(copy / pvd);
        EXPECT_EQ(text.find("fields_000001.vtr"), std::string::npos) << text;
        EXPECT_EQ(text.find("particles_000002.vtp"), std::string::npos) << text;
        for (std::size_t at = text.find("file=\""); at != std::string::npos;
             at = text.find("file=\"", at + 1)) {
            const std::size_t begin = at + 6;
            const std::string file = text.substr(begin, text.find('"', begin) - begin);
            EXPECT_TRUE(fs::exists(copy / file)) << pvd << " lists the missing " << file;
        }
    }
    for (const char* frame : {"fields/fields_000004.vtr", "fields/fields_000006.vtr",
                              "particles/particles_000006.vtp"}) {
        EXPECT_TRUE(file_contents(ref / frame) == file_contents(copy / frame)) << frame;
    }
    EXPECT_EQ(solver_rows_without_wall_time(ref), solver_rows_without_wall_time(copy));
}

TEST_F(Restart, NoUsableCheckpointIsBadInputAndChangesNothing)
{
    const fs::path ref = reference();
    const fs::path copy = copy_stopped_at(ref, 10, "all_damaged");
    for (const auto& f : fs::directory_iterator(copy / "checkpoints")) {
        fs::resize_file(f.path(), fs::file_size(f.path()) - 100); // truncated
    }
    const auto before = snapshot(copy);
    const Result r = run("run --restart " + copy.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("no usable checkpoint"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("checkpoint_0000000005.ckpt is truncated"), std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_TRUE(snapshot(copy) == before) << "the run directory was changed";
}

TEST_F(Restart, CheckpointsFollowTheTimeIntervalAndTheNewestAreKept)
{
    const fs::path dir = root_ / "timed";
    // Due at t = 0.07 and 0.14 (steps 7, 14), and at the end (step 20); keep = 2.
    const Result r = run("run " + case_file_.string() + " -o " + dir.string() +
                         " -q --set time.max_steps=20 --set checkpoint.step_interval=0 --set "
                         "checkpoint.time_interval=0.07 --set checkpoint.keep=2");
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::string> names;
    for (const auto& f : fs::directory_iterator(dir / "checkpoints")) {
        names.push_back(f.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"checkpoint_0000000014.ckpt",
                                               "checkpoint_0000000020.ckpt"}));
}

TEST_F(Restart, CompleteRunSaysSoAndChangesNothing)
{
    const fs::path ref = reference();
    const auto before = snapshot(ref);
    const Result r = run("run --restart " + ref.string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("is complete: step 60"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("time.end = 0.6 s"), std::string::npos) << r.output;
    EXPECT_TRUE(snapshot(ref) == before) << "the run directory was changed";
}

struct BadRestart {
    const char* name;
    std::string arguments;      ///< {dir}: a run directory (stopped after 10 steps)
    std::string message;        ///< expected in the one error line
    std::string edit_from = {}; ///< {dir}/case.toml edited by hand: this text …
    std::string edit_to = {};   ///< … replaced by this
};

void PrintTo(const BadRestart& bad, std::ostream* out)
{
    *out << bad.name;
}

class RestartBadInput : public Restart, public ::testing::WithParamInterface<BadRestart> {};

TEST_P(RestartBadInput, ExitsWithStatusTwoAndChangesNothing)
{
    const BadRestart& bad = GetParam();
    const fs::path dir = root_ / "run";
    const Result part =
        run("run " + case_file_.string() + " -o " + dir.string() + " -q --set time.max_steps=10");
    ASSERT_EQ(part.status, 0) << part.output;
    fs::create_directories(root_ / "empty");
    fs::create_directories(root_ / "no_checkpoints");
    fs::copy_file(dir / "case.toml", root_ / "no_checkpoints/case.toml");
    if (!bad.edit_from.empty()) {
        std::string text = file_contents(dir / "case.toml");
        ASSERT_NE(text.find(bad.edit_from), std::string::npos);
        text.replace(text.find(bad.edit_from), bad.edit_from.size(), bad.edit_to);
        std::ofstream(dir / "case.toml", std::ios::trunc) << text;
    }
    std::string arguments = bad.arguments;
    for (const auto& [token, value] : {std::pair<std::string, fs::path>{"{dir}", dir},
                                       {"{root}", root_},
                                       {"{case}", case_file_}}) {
        for (std::size_t at; (at = arguments.find(token)) != std::string::npos;) {
            arguments.replace(at, token.size(), value.string());
        }
    }
    const auto before = snapshot(root_);
    const Result r = run(arguments);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    auto after = snapshot(root_);
    after.erase(fs::relative(log_, root_).string());
    auto expected = before;
    expected.erase(fs::relative(log_, root_).string());
    EXPECT_TRUE(after == expected) << "something was written for " << bad.name;
}

INSTANTIATE_TEST_SUITE_P(
    Restart, RestartBadInput,
    ::testing::Values(
        BadRestart{"missing_directory", "run --restart {root}/nope", "no such run directory"},
        BadRestart{"not_a_run_directory", "run --restart {root}/empty",
                   "case.toml: cannot restart: missing"},
        BadRestart{"no_checkpoints", "run --restart {root}/no_checkpoints",
                   "cannot restart: no checkpoint"},
        BadRestart{"other_grid", "run --restart {dir} --set domain.cells=[16,32]",
                   "domain.cells: the checkpoint was written for domain.cells = [32, 64], the "
                   "case has [16, 32]"},
        BadRestart{"other_bodies", "run --restart {dir}",
                   "bodies.markers: the checkpoint was "
                   "written for bodies.markers = [37, 37, 37], the case has [61, 37, 37]",
                   "n_rings = 3", "n_rings = 4"},
        BadRestart{"bad_override", "run --restart {dir} --set time.dt=-1",
                   "time.dt: -1 s is out of range"},
        BadRestart{"case_and_restart", "run {case} --restart {dir}", "case excludes --restart"},
        BadRestart{"output_and_restart", "run --restart {dir} -o {root}/other",
                   "--output excludes --restart"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

} // namespace
