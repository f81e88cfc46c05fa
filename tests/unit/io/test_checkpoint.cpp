// SPDX-License-Identifier: MIT
// Checkpoints: the encoding reads back exactly, the file refuses damage, truncation, other
// formats and other grids by name, and a simulation restored from a checkpoint continues bit
// for bit as the one that wrote it (2D with colliding disks, 3D with a sphere on the floor,
// and a fluid-only cavity, whose steps reuse the momentum systems assembled by the last one).

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/checkpoint.hpp"
#include "fddem/io/checkpoint_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() /
                         ("fddem_checkpoint_test_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write_bytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary) << bytes;
}

TEST(Crc32, MatchesTheStandardCheckValue)
{
    // The CRC-32 (ISO-HDLC) check value of "123456789", as every CRC catalogue lists it.
    EXPECT_EQ(crc32_of("123456789"), 0xCBF43926U);
}

TEST(CheckpointArchive, ValuesReadBackExactly)
{
    const double tiny = std::numeric_limits<double>::denorm_min();
    ArchiveWriter writer;
    writer("a", -0.0);
    writer("b", tiny);
    writer("c", -123456789012L);
    writer("d", true);
    writer("e", std::string("text with\nnewline"));
    writer("f", Vec<3>(1.0 / 3.0, -2.5, 1e300));
    writer("g", std::vector<std::pair<double, std::string>>{{0.1, "x"}, {0.2, "yy"}});
    writer("h", std::map<int, double>{{3, 0.5}, {-1, 2.0}});

    ArchiveReader reader(writer.bytes());
    double a = 1.0;
    double b = 0.0;
    long c = 0;
    bool d = false;
    std::string e;
    Vec<3> f = Vec<3>::Zero();
    std::vector<std::pair<double, std::string>> g;
    std::map<int, double> h;
    reader("a", a);
    reader("b", b);
    reader("c", c);
    reader("d", d);
    reader("e", e);
    reader("f", f);
    reader("g", g);
    reader("h", h);
    EXPECT_TRUE(reader.is_at_end());
    EXPECT_EQ(a, 0.0);
    EXPECT_TRUE(std::signbit(a));
    EXPECT_EQ(b, tiny);
    EXPECT_EQ(c, -123456789012L);
    EXPECT_TRUE(d);
    EXPECT_EQ(e, "text with\nnewline");
    EXPECT_EQ(f, Vec<3>(1.0 / 3.0, -2.5, 1e300));
    ASSERT_EQ(g.size(), 2U);
    EXPECT_EQ(g[1].first, 0.2);
    EXPECT_EQ(g[1].second, "yy");
    EXPECT_EQ(h.at(-1), 2.0);
}

/// A record of the kind a per-pair contact history would keep.
struct PairSpring {
    int first = 0;
    int second = 0;
    Vec<2> displacement = Vec<2>::Zero();

    template <class Self, class Archive>
    static void visit(Self& s, Archive& archive)
    {
        archive("pair.first", s.first);
        archive("pair.second", s.second);
        archive("pair.displacement", s.displacement);
    }
};

TEST(CheckpointArchive, StructsThatListTheirMembersReadBack)
{
    const std::vector<PairSpring> springs = {{0, 2, Vec<2>(1e-6, -2e-7)}, {1, 2, Vec<2>(0.5, 0)}};
    ArchiveWriter writer;
    writer("springs", springs);
    ArchiveReader reader(writer.bytes());
    std::vector<PairSpring> read;
    reader("springs", read);
    ASSERT_EQ(read.size(), 2U);
    EXPECT_EQ(read[0].second, 2);
    EXPECT_EQ(read[0].displacement, springs[0].displacement);
    EXPECT_EQ(read[1].first, 1);
    EXPECT_TRUE(reader.is_at_end());
}

TEST(CheckpointArchive, OutOfStepReadingIsAnErrorNamingTheValue)
{
    ArchiveWriter writer;
    writer("body.centre", Vec<2>(1.0, 2.0));
    ArchiveReader reader(writer.bytes());
    Vec<2> velocity;
    try {
        reader("body.velocity", velocity);
        FAIL() << "no error";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("'body.velocity'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'body.centre'"), std::string::npos) << e.what();
    }
    ArchiveReader short_reader(std::string_view(writer.bytes()).substr(0, 20));
    Vec<2> centre;
    EXPECT_THROW(short_reader("body.centre", centre), CheckpointError);
}

/// Disks (2D) or a sphere (3D) dropped near each other and the floor. The 2D disks hit the
/// floor at step 10 and each other and the floor at steps 21–22, the sphere rests on the floor
/// from step 20 (checked below: the checkpoint catches contacts in flight).
std::string falling_balls_case(int dim)
{
    if (dim == 2) {
        return R"([domain]
size = [1.0, 1.0]
cells = [24, 24]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -9.81]
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.45, 0.14]
n_rings = 2
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.52, 0.42]
n_rings = 2
[[bodies]]
diameter = 0.25
density = 4.0
position = [0.8, 0.2]
velocity = [-1.0, 0.0]
n_rings = 2
[contact]
restitution = 0.5
[time]
dt = 0.01
end = 1.0
[simple]
tolerance = 1e-3
max_outer_iterations = 10
fft_planning = "estimate"
)";
    }
    return R"([domain]
size = [1.0, 1.0, 1.0]
cells = [10, 10, 10]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -9.81, 0.0]
[[bodies]]
shape = "sphere"
diameter = 0.4
density = 4.0
position = [0.5, 0.22, 0.5]
n_rings = 1
[contact]
restitution = 0.5
[time]
dt = 0.01
end = 1.0
[simple]
tolerance = 1e-3
max_outer_iterations = 10
fft_planning = "estimate"
)";
}

std::string cavity_case()
{
    return R"([domain]
size = [1.0, 1.0]
cells = [12, 12]
[walls]
y_high = [1.0, 0.0]
[fluid]
density = 1.0
viscosity = 0.01
[time]
dt = 0.05
end = 1.0
)";
}

template <int Dim>
void expect_same_state(const Simulation<Dim>& a, const Simulation<Dim>& b)
{
    EXPECT_EQ(a.clock().step, b.clock().step);
    EXPECT_EQ(a.clock().time, b.clock().time);
    for (int axis = 0; axis < Dim; ++axis) {
        const auto u = a.fluid().u[axis].values();
        const auto v = b.fluid().u[axis].values();
        ASSERT_TRUE(std::equal(u.begin(), u.end(), v.begin())) << "u component " << axis;
    }
    const auto p = a.fluid().p.values();
    const auto q = b.fluid().p.values();
    ASSERT_TRUE(std::equal(p.begin(), p.end(), q.begin())) << "pressure";
    ASSERT_EQ(a.bodies().size(), b.bodies().size());
    for (std::size_t k = 0; k < a.bodies().size(); ++k) {
        EXPECT_EQ(a.bodies()[k].centre, b.bodies()[k].centre) << "body " << k;
        EXPECT_EQ(a.bodies()[k].velocity, b.bodies()[k].velocity) << "body " << k;
        EXPECT_EQ(a.bodies()[k].omega, b.bodies()[k].omega) << "body " << k;
        EXPECT_EQ(a.bodies()[k].force, b.bodies()[k].force) << "body " << k;
        EXPECT_EQ(a.bodies()[k].coupling.lambda, b.bodies()[k].coupling.lambda) << "body " << k;
    }
}

/// Runs `steps_before` steps, writes a checkpoint, runs `steps_after` more; a second
/// simulation of the same case restored from the checkpoint runs `steps_after` steps too.
/// Returns how many bodies were in contact at the checkpoint.
template <int Dim>
int expect_bit_identical_continuation(const CaseConfig& config, int steps_before, int steps_after)
{
    const fs::path dir = scratch("continuation" + std::to_string(Dim));
    const fs::path file = dir / "state.ckpt";
    Simulation<Dim> original(config);
    for (int k = 0; k < steps_before; ++k) {
        static_cast<void>(original.advance());
    }
    RunRecord record;
    record.total_outer_iterations = 1234;
    record.unfinished_film_solves = 7; // a restarted run warns of them only if it has none yet
    record.field_frames = {{0.0, "fields/fields_000000.vtr"}};
    write_checkpoint(file, original, record);
    int in_contact = 0;
    for (const Particle<Dim>& body : original.bodies()) {
        in_contact += body.contact.is_in_contact ? 1 : 0;
    }
    for (int k = 0; k < steps_after; ++k) {
        static_cast<void>(original.advance());
    }

    Simulation<Dim> restored(config);
    RunRecord restored_record;
    const CheckpointFile checkpoint(file);
    EXPECT_EQ(checkpoint.header().step, steps_before);
    EXPECT_EQ(checkpoint.header().case_text, config.as_run);
    checkpoint.restore(restored, restored_record);
    EXPECT_EQ(restored_record.total_outer_iterations, 1234);
    EXPECT_EQ(restored_record.unfinished_film_solves, 7);
    EXPECT_EQ(restored_record.field_frames, record.field_frames);
    for (int k = 0; k < steps_after; ++k) {
        static_cast<void>(restored.advance());
    }
    expect_same_state(original, restored);
    fs::remove_all(dir);
    return in_contact;
}

TEST(CheckpointRestart, DisksInContactContinueBitForBit2D)
{
    const CaseConfig config = read_case_string(falling_balls_case(2), "test:disks");
    const int in_contact = expect_bit_identical_continuation<2>(config, 21, 8);
    EXPECT_GT(in_contact, 0) << "the checkpoint should catch a contact in flight";
}

TEST(CheckpointRestart, FrictionalDisksKeepTheirTangentialSpringsBitForBit)
{
    // Hertz–Mindlin with friction and rolling resistance: the tangential springs (the contact
    // history) must come back from the checkpoint, or the continuation differs.
    const CaseConfig config =
        read_case_string(falling_balls_case(2), "test:frictional disks",
                         {"contact.model=\"hertz_mindlin\"", "contact.young_modulus=1e6",
                          "contact.friction=0.4", "contact.rolling_friction=0.05"});
    Simulation<2> probe(config);
    bool has_springs = false;
    for (int k = 0; k < 21; ++k) {
        static_cast<void>(probe.advance());
    }
    has_springs = !probe.contact_history().springs.empty();
    EXPECT_TRUE(has_springs) << "the checkpoint should catch a tangential spring in flight";
    const int in_contact = expect_bit_identical_continuation<2>(config, 21, 8);
    EXPECT_GT(in_contact, 0);
}

TEST(CheckpointRestart, AdaptiveCollisionsKeepTheirConstantsBitForBit)
{
    // The adaptive model fixes k_n, d_n when a contact opens (the contact history): a
    // restart that lost them would fix them anew from the speed at the restart.
    const CaseConfig config =
        read_case_string(falling_balls_case(2), "test:adaptive disks",
                         {"contact.model=\"adaptive\"", "contact.collision_steps=10"});
    Simulation<2> probe(config);
    for (int k = 0; k < 21; ++k) {
        static_cast<void>(probe.advance());
    }
    EXPECT_FALSE(probe.contact_history().coefficients.empty())
        << "the checkpoint should catch a collision in flight";
    const int in_contact = expect_bit_identical_continuation<2>(config, 21, 8);
    EXPECT_GT(in_contact, 0);
}

TEST(CheckpointRestart, SurfaceRingsWithTheInnerFluidFromTheCellsContinueBitForBit)
{
    // coupling.inner_fluid = "volume" takes the level-n inner fluid at each step's start from
    // u^n, which the checkpoint holds: nothing more needs writing.
    const CaseConfig config =
        read_case_string(falling_balls_case(2), "test:surface disks",
                         {"coupling.markers=\"surface\"", "coupling.inner_fluid=\"volume\""});
    const int in_contact = expect_bit_identical_continuation<2>(config, 21, 8);
    EXPECT_GT(in_contact, 0) << "the checkpoint should catch a contact in flight";
}

TEST(CheckpointRestart, SphereOnTheFloorContinuesBitForBit3D)
{
    const CaseConfig config = read_case_string(falling_balls_case(3), "test:sphere");
    // Step 18: in the first bounce with the mirror-symmetric shells of issue 17.
    const int in_contact = expect_bit_identical_continuation<3>(config, 18, 4);
    EXPECT_GT(in_contact, 0) << "the checkpoint should catch a contact in flight";
}

TEST(CheckpointRestart, ATurnedSphereContinuesBitForBit3D)
{
    // A sphere's markers are not exactly isotropic, so the fluid's second moment they stand
    // for (eqs. (13)–(14)) turns with the body; it is derived from the orientation, not stored,
    // and a restart that kept the body-frame one took a different first step (found on the
    // 25-sphere pile, 2026-11-28).
    const CaseConfig config = read_case_string(falling_balls_case(3), "test:spinning sphere",
                                               {"bodies.omega=[30.0, 0.0, 40.0]"});
    {
        Simulation<3> probe(config);
        for (int k = 0; k < 6; ++k) {
            static_cast<void>(probe.advance());
        }
        EXPECT_LT(std::abs(probe.bodies().front().orientation.w()), 0.999)
            << "the sphere should have turned by the checkpoint";
    }
    expect_bit_identical_continuation<3>(config, 6, 3);
}

TEST(CheckpointRestart, CavityWithReusedAssemblyContinuesBitForBit)
{
    const CaseConfig config = read_case_string(cavity_case(), "test:cavity");
    expect_bit_identical_continuation<2>(config, 5, 5);
    const CaseConfig hypre =
        read_case_string(cavity_case(), "test:cavity", {"simple.pressure_solver=hypre"});
    expect_bit_identical_continuation<2>(hypre, 5, 5);
}

TEST(CheckpointRestart, AdaptiveTimeStepContinuesBitForBit)
{
    // The step length depends on the state and on the last steps (time.max_courant's growth
    // limit, time.steady's residual history): all of it must come back from the checkpoint.
    const CaseConfig courant =
        read_case_string(falling_balls_case(2), "test:adaptive disks", {"time.max_courant=0.2"});
    {
        Simulation<2> probe(courant);
        for (int k = 0; k < 21; ++k) {
            static_cast<void>(probe.advance());
        }
        EXPECT_LT(probe.clock().dt, courant.time.dt) << "the limit should act by the checkpoint";
    }
    expect_bit_identical_continuation<2>(courant, 21, 8);
    const CaseConfig steady = read_case_string(cavity_case(), "test:steady cavity",
                                               {"time.steady=true", "time.steady_tolerance=1e-8"});
    expect_bit_identical_continuation<2>(steady, 5, 5);
}

TEST(CheckpointRestart, Bdf2WithAnAdaptiveStepContinuesBitForBit)
{
    // time.scheme = "bdf2" reads u^{n−1}, U^{n−1}, ω^{n−1} and the last Δt (for the step ratio
    // ω) besides the level-n state. The checkpoint is taken before a step whose Δt differs from
    // the last one (time.max_courant), so that a lost Δt_{n−1} or level n−1 changes it.
    const CaseConfig config = read_case_string(falling_balls_case(2), "test:bdf2 disks",
                                               {"time.max_courant=0.2", "time.scheme=\"bdf2\""});
    int checkpoint_step = 0;
    {
        Simulation<2> probe(config);
        double last_dt = 0.0;
        for (int k = 1; k <= 30 && checkpoint_step == 0; ++k) {
            static_cast<void>(probe.advance());
            if (k > 2 && probe.clock().dt != last_dt) {
                checkpoint_step = k - 1; // step k is the first continued one
            }
            last_dt = probe.clock().dt;
        }
    }
    ASSERT_GT(checkpoint_step, 0) << "no change of Δt in 30 steps";
    expect_bit_identical_continuation<2>(config, checkpoint_step, 8);
}

class CheckpointFileTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = scratch(::testing::UnitTest::GetInstance()->current_test_info()->name());
        config_ = read_case_string(cavity_case(), "test:cavity");
        Simulation<2> sim(config_);
        static_cast<void>(sim.advance());
        file_ = dir_ / "state.ckpt";
        write_checkpoint(file_, sim, RunRecord{});
        bytes_ = test::file_contents(file_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// The reason a damaged copy is refused with.
    std::string refusal(const std::string& bytes)
    {
        const fs::path damaged = dir_ / "damaged.ckpt";
        write_bytes(damaged, bytes);
        try {
            const CheckpointFile checkpoint(damaged);
        } catch (const CheckpointError& e) {
            return e.what();
        }
        return "accepted";
    }

    fs::path dir_;
    fs::path file_;
    std::string bytes_;
    CaseConfig config_;
};

TEST_F(CheckpointFileTest, OneFlippedBitAnywhereIsDetected)
{
    for (const std::size_t at : {std::size_t{20}, bytes_.size() / 2, bytes_.size() - 20}) {
        std::string damaged = bytes_;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x04);
        EXPECT_NE(refusal(damaged).find("damaged"), std::string::npos) << "byte " << at;
    }
}

TEST_F(CheckpointFileTest, TruncatedOtherAndNewerFilesAreRefusedWithTheReason)
{
    EXPECT_NE(refusal(bytes_.substr(0, bytes_.size() / 2)).find("truncated"), std::string::npos);
    EXPECT_NE(refusal(bytes_.substr(0, 10)).find("truncated"), std::string::npos);
    EXPECT_NE(refusal("# a case file\n" + bytes_).find("not an fddem checkpoint"),
              std::string::npos);
    std::string newer = bytes_;
    newer[8] = static_cast<char>(checkpoint_format_version + 1);
    EXPECT_NE(
        refusal(newer).find("format version " + std::to_string(checkpoint_format_version + 1)),
        std::string::npos);
    EXPECT_EQ(refusal(bytes_), "accepted");
}

TEST_F(CheckpointFileTest, AnotherGridIsRefusedByKey)
{
    const CaseConfig finer =
        read_case_string(cavity_case(), "test:cavity", {"domain.cells=[16,12]"});
    Simulation<2> sim(finer);
    RunRecord record;
    const CheckpointFile checkpoint(file_);
    try {
        checkpoint.restore(sim, record);
        FAIL() << "restored into another grid";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "domain.cells");
        EXPECT_NE(std::string(e.what()).find("[12, 12]"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[16, 12]"), std::string::npos) << e.what();
    }
}

TEST_F(CheckpointFileTest, ChangedTimeStepIsAdopted)
{
    const CaseConfig smaller = read_case_string(cavity_case(), "test:cavity", {"time.dt=0.025"});
    Simulation<2> sim(smaller);
    RunRecord record;
    CheckpointFile(file_).restore(sim, record);
    EXPECT_EQ(sim.clock().step, 1);
    EXPECT_EQ(sim.clock().time, 0.05);
    EXPECT_EQ(sim.clock().dt, 0.025);
    static_cast<void>(sim.advance());
    EXPECT_DOUBLE_EQ(sim.clock().time, 0.075);
}

TEST(CheckpointFiles, ListedNewestFirstAndPrunedToTheNewest)
{
    const fs::path run = scratch("listing");
    fs::create_directories(checkpoint_directory(run));
    for (const long step : {5L, 100L, 20L}) {
        write_bytes(checkpoint_path(run, step), "x");
    }
    write_bytes(checkpoint_directory(run) / "checkpoint_0000000200.ckpt.tmp.123", "partial");
    write_bytes(checkpoint_directory(run) / "checkpoint_0000000300.ckpt.damaged", "bad");
    const std::vector<CheckpointEntry> listed = list_checkpoints(run);
    ASSERT_EQ(listed.size(), 3U);
    EXPECT_EQ(listed[0].step, 100);
    EXPECT_EQ(listed[2].step, 5);
    EXPECT_EQ(listed[0].path.filename(), "checkpoint_0000000100.ckpt");

    prune_checkpoints(run, 2);
    const std::vector<CheckpointEntry> kept = list_checkpoints(run);
    ASSERT_EQ(kept.size(), 2U);
    EXPECT_EQ(kept[1].step, 20);
    remove_stale_temporaries(checkpoint_directory(run));
    EXPECT_FALSE(fs::exists(checkpoint_directory(run) / "checkpoint_0000000200.ckpt.tmp.123"));
    EXPECT_TRUE(fs::exists(checkpoint_directory(run) / "checkpoint_0000000300.ckpt.damaged"));
    EXPECT_TRUE(list_checkpoints(run / "nothing_here").empty());
    fs::remove_all(run);
}

TEST(CheckpointFiles, PiecesArePrunedWithTheirCheckpointAndSetAsideWithIt)
{
    // A run on several ranks (io/checkpoint.hpp): checkpoint_<step>.ckpt.<w>.piece<r>.
    const fs::path run = scratch("pieces");
    const fs::path dir = checkpoint_directory(run);
    fs::create_directories(dir);
    for (const long step : {5L, 20L, 100L}) {
        write_bytes(checkpoint_path(run, step), "x");
        for (const char* piece : {".1.piece1", ".1.piece2"}) {
            write_bytes(dir / (checkpoint_path(run, step).filename().string() + piece), "p");
        }
    }
    write_bytes(dir / "checkpoint_0000000007.ckpt.3.piece1", "orphan"); // its checkpoint is gone
    const fs::path aside = set_checkpoint_aside(checkpoint_path(run, 100));
    EXPECT_EQ(aside.filename(), "checkpoint_0000000100.ckpt.damaged");
    EXPECT_TRUE(fs::exists(dir / "checkpoint_0000000100.ckpt.damaged.1.piece1"));
    EXPECT_TRUE(fs::exists(dir / "checkpoint_0000000100.ckpt.damaged.1.piece2"));
    EXPECT_FALSE(fs::exists(dir / "checkpoint_0000000100.ckpt.1.piece1"));
    prune_checkpoints(run, 1); // keeps step 20
    EXPECT_FALSE(fs::exists(dir / "checkpoint_0000000005.ckpt.1.piece1"));
    EXPECT_FALSE(fs::exists(dir / "checkpoint_0000000007.ckpt.3.piece1"));
    EXPECT_TRUE(fs::exists(dir / "checkpoint_0000000020.ckpt.1.piece2"));
    EXPECT_TRUE(fs::exists(dir / "checkpoint_0000000100.ckpt.damaged.1.piece1"));
    fs::remove_all(run);
}

TEST(CheckpointFormat, DocsOutputFilesStateTheVersionTheProgramWrites)
{
    // Issue 17: docs/output-files.md said version 2 while fddem wrote 3.
    const std::string docs =
        test::file_contents(std::string(FDDEM_SOURCE_DIR) + "/docs/output-files.md");
    const std::string stated = "Format (version " + std::to_string(checkpoint_format_version);
    EXPECT_NE(docs.find(stated), std::string::npos)
        << "docs/output-files.md does not say \"" << stated << "\"";
}

} // namespace
} // namespace fddem
