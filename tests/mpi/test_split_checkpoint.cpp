// SPDX-License-Identifier: MIT
// A checkpoint of a run on a split grid, written in pieces (io/checkpoint.hpp, issue 15): every
// rank writes its piece and restores its block from the pieces it overlaps, bit for bit; a
// damaged or missing piece is refused by the ranks that read it, and named. Run under mpirun
// -n 1, 2 and 4 (on other numbers of ranks than the writer's: tests/mpi/split_run.py).

#include "fddem/core/errors.hpp"
#include "fddem/grid/loops.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/checkpoint.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;

/// The four colliding disks (tests/mpi/cases/disks.toml), split over every rank.
CaseConfig disks()
{
    return read_case(std::string(FDDEM_SOURCE_DIR) + "/tests/mpi/cases/disks.toml",
                     {"simple.pressure_solver=hypre", "simple.linear_tolerance=1e-13"});
}

/// A directory all ranks share, made by rank 0.
fs::path shared_directory(const Communicator& world)
{
    std::string path;
    if (world.rank() == 0) {
        path = test::fresh_test_directory("fddem_split_checkpoint").string();
    }
    world.broadcast(path);
    return path;
}

/// Whether every storage entry of every array (ghosts included) and every body is the same, bit
/// for bit, on this rank.
bool is_same_state(const Simulation<2>& a, const Simulation<2>& b)
{
    bool same = a.clock().step == b.clock().step && a.clock().time == b.clock().time;
    const Box<2> storage = a.grid().storage_box();
    for_each_cell_in_vtk_order(storage, [&](const Index<2>& i) {
        same = same && a.fluid().p(i) == b.fluid().p(i) && a.fluid().u[0](i) == b.fluid().u[0](i) &&
               a.fluid().u[1](i) == b.fluid().u[1](i) &&
               a.fluid().body_force[1](i) == b.fluid().body_force[1](i);
    });
    for (std::size_t k = 0; k < a.bodies().size(); ++k) {
        same = same && a.bodies()[k].centre == b.bodies()[k].centre &&
               a.bodies()[k].velocity == b.bodies()[k].velocity &&
               a.bodies()[k].force == b.bodies()[k].force;
    }
    return same;
}

TEST(SplitCheckpoint, EveryRankRestoresItsBlockBitForBitAndStepsOnAlike)
{
    const Communicator world = Communicator::world();
    const CaseConfig config = disks();
    Simulation<2> run(config, world);
    for (int k = 0; k < 3; ++k) {
        static_cast<void>(run.advance());
    }
    const fs::path file = shared_directory(world) / "state.ckpt";
    run.share_marker_state();
    // Written twice at the same name, as a step written again after a numerical failure: the
    // second write's pieces have a write number of their own, and the first's are removed.
    write_checkpoint(file, run, RunRecord{});
    write_checkpoint(file, run, RunRecord{});
    const CheckpointFile checkpoint(file);
    EXPECT_EQ(checkpoint.header().pieces.size(), static_cast<std::size_t>(world.size()));
    EXPECT_EQ(checkpoint.header().pieces_write, world.size() > 1 ? 2 : 1); // one process: none
    EXPECT_FALSE(fs::exists(checkpoint_piece_path(file, 2, world.size())));
    for (int r = 1; r < world.size(); ++r) {
        EXPECT_TRUE(fs::exists(checkpoint_piece_path(file, 2, r)));
        EXPECT_FALSE(fs::exists(checkpoint_piece_path(file, 1, r)));
    }
    Simulation<2> continued(config, world);
    RunRecord record;
    checkpoint.restore(continued, record);
    EXPECT_EQ(world.max(is_same_state(run, continued) ? 0.0 : 1.0), 0.0);
    static_cast<void>(run.advance());
    static_cast<void>(continued.advance());
    EXPECT_EQ(world.max(is_same_state(run, continued) ? 0.0 : 1.0), 0.0);
}

TEST(SplitCheckpoint, ADamagedMissingOrForeignPieceIsRefusedWhereItIsReadAndNamed)
{
    const Communicator world = Communicator::world();
    if (world.size() == 1) {
        GTEST_SKIP() << "a checkpoint of one process has no piece files";
    }
    const CaseConfig config = disks();
    Simulation<2> run(config, world);
    static_cast<void>(run.advance());
    const fs::path directory = shared_directory(world);
    const fs::path file = directory / "state.ckpt";
    write_checkpoint(file, run, RunRecord{});
    static_cast<void>(run.advance());
    write_checkpoint(directory / "later.ckpt", run, RunRecord{}); // the foreign piece's source
    const fs::path piece = checkpoint_piece_path(file, 1, 1);
    const std::string intact = test::file_contents(piece);
    const std::array<std::string, 3> kinds{"damaged", "missing", "foreign"};
    for (const std::string& kind : kinds) {
        if (world.rank() == 0) {
            fs::remove(piece);
            if (kind == "damaged") {
                std::string bytes = intact;
                bytes[100] = static_cast<char>(bytes[100] ^ 0x5a); // inside its grid values
                std::ofstream(piece, std::ios::binary) << bytes;
            } else if (kind == "foreign") {
                fs::copy_file(checkpoint_piece_path(directory / "later.ckpt", 1, 1), piece);
            }
        }
        static_cast<void>(world.max(0.0)); // every rank sees the change
        Simulation<2> continued(config, world);
        RunRecord record;
        std::string said;
        try {
            CheckpointFile(file).restore(continued, record);
        } catch (const CheckpointError& e) {
            said = e.what();
        }
        // Rank 1 reads its own piece: refused there, with the piece's name and the reason.
        if (world.rank() == 1) {
            EXPECT_NE(said.find("state.ckpt.1.piece1"), std::string::npos) << said;
            const std::string reason = kind == "damaged"   ? "is damaged (CRC-32"
                                       : kind == "missing" ? "cannot be opened"
                                                           : "of another checkpoint";
            EXPECT_NE(said.find(reason), std::string::npos) << kind << ": " << said;
        }
        EXPECT_EQ(world.max(said.empty() ? 0.0 : 1.0), 1.0) << kind;
    }
}

} // namespace
} // namespace fddem
