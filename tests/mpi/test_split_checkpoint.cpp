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
    write_checkpoint(file, run, RunRecord{});
    EXPECT_EQ(fs::exists(checkpoint_piece_path(file, world.size())), false);
    if (world.size() > 1) {
        EXPECT_TRUE(fs::exists(checkpoint_piece_path(file, world.size() - 1)));
    }
    const CheckpointFile checkpoint(file);
    EXPECT_EQ(checkpoint.header().pieces.size(), static_cast<std::size_t>(world.size()));
    Simulation<2> continued(config, world);
    RunRecord record;
    checkpoint.restore(continued, record);
    EXPECT_EQ(world.max(is_same_state(run, continued) ? 0.0 : 1.0), 0.0);
    static_cast<void>(run.advance());
    static_cast<void>(continued.advance());
    EXPECT_EQ(world.max(is_same_state(run, continued) ? 0.0 : 1.0), 0.0);
}

TEST(SplitCheckpoint, ADamagedOrMissingPieceIsRefusedWhereItIsReadAndNamed)
{
    const Communicator world = Communicator::world();
    if (world.size() == 1) {
        GTEST_SKIP() << "a checkpoint of one process has no piece files";
    }
    const CaseConfig config = disks();
    Simulation<2> run(config, world);
    static_cast<void>(run.advance());
    const fs::path file = shared_directory(world) / "state.ckpt";
    write_checkpoint(file, run, RunRecord{});
    const fs::path piece = checkpoint_piece_path(file, 1);
    for (const bool is_missing : {false, true}) {
        if (world.rank() == 0) {
            if (is_missing) {
                fs::remove(piece);
            } else {
                std::fstream bytes(piece, std::ios::in | std::ios::out | std::ios::binary);
                bytes.seekp(100);
                bytes.put('\x5a'); // inside the piece's grid values
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
        // Rank 1 reads its own piece; no rank that reads it may pass.
        if (world.rank() == 1) {
            EXPECT_NE(said.find("state.ckpt.piece1"), std::string::npos) << said;
            EXPECT_NE(said.find(is_missing ? "cannot be opened" : "CRC-32"), std::string::npos)
                << said;
        }
        EXPECT_EQ(world.max(said.empty() ? 0.0 : 1.0), 1.0);
        if (world.rank() == 0) {
            // What rank 0 says of a piece another rank could not read.
            try {
                CheckpointFile(file).check_pieces();
                ADD_FAILURE() << "check_pieces passed a " << (is_missing ? "missing" : "damaged")
                              << " piece";
            } catch (const CheckpointError& e) {
                EXPECT_NE(std::string(e.what()).find("state.ckpt.piece1"), std::string::npos);
            }
        }
    }
}

} // namespace
} // namespace fddem
