// SPDX-License-Identifier: MIT
// The frames of a run directory that a restart or --force removes, a split run's frames in
// pieces (fields/fields_NNNNNN.pvtr and the folder fields/fields_NNNNNN/) among them.

#include "fddem/io/run_directory.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;

class FrameFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = test::fresh_test_directory("fddem_test_frames_");
        // Frames 0 and 1 of one process, 2 and 3 of a split run on two ranks, and the user's.
        for (const char* file :
             {"fields/fields_000000.vtr", "fields/fields_000001.vtr", "fields/fields_000002.pvtr",
              "fields/fields_000002/fields_000002_0000.vtr",
              "fields/fields_000002/fields_000002_0001.vtr", "fields/fields_000003.pvtr",
              "fields/fields_000003/fields_000003_0000.vtr",
              "fields/fields_000003/fields_000003_0001.vtr", "fields/my_plot.png",
              "fields/mine/notes.vtr"}) {
            fs::create_directories((dir_ / file).parent_path());
            std::ofstream(dir_ / file) << "frame";
        }
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path dir_;
};

TEST_F(FrameFiles, RestartRemovesUnlistedFramesWithTheirPieces)
{
    // A checkpoint that lists frames 0 and 2: frame 1 (one process) and frame 3 (its master and
    // its folder of pieces) go; the user's files stay.
    const int removed = remove_unlisted_files(
        dir_, "fields", {".vtr", ".pvtr"},
        {{0.0, "fields/fields_000000.vtr"}, {0.1, "fields/fields_000002.pvtr"}});
    EXPECT_EQ(removed, 3);
    for (const char* kept : {"fields/fields_000000.vtr", "fields/fields_000002.pvtr",
                             "fields/fields_000002/fields_000002_0000.vtr",
                             "fields/fields_000002/fields_000002_0001.vtr", "fields/my_plot.png",
                             "fields/mine/notes.vtr"}) {
        EXPECT_TRUE(fs::exists(dir_ / kept)) << kept;
    }
    for (const char* gone :
         {"fields/fields_000001.vtr", "fields/fields_000003.pvtr", "fields/fields_000003"}) {
        EXPECT_FALSE(fs::exists(dir_ / gone)) << gone;
    }
}

TEST_F(FrameFiles, PiecesAreRunOutputsThatForceRemoves)
{
    EXPECT_TRUE(is_run_output("fields/fields_000002.pvtr"));
    EXPECT_TRUE(is_run_output("fields/fields_000002/fields_000002_0001.vtr"));
    EXPECT_TRUE(is_run_output("particles/particles_000002.pvtp"));
    EXPECT_TRUE(is_run_output("particles/particles_000002/particles_000002_0013.vtp"));
    EXPECT_TRUE(is_run_output("fields/fields_000002/fields_000002_0001.vtr.tmp.4711"));
    EXPECT_FALSE(is_run_output("fields/mine/notes.vtr"));
    EXPECT_FALSE(is_run_output("fields/fields_000002/notes.vtr"));

    // 8 frame files; the piece folders go with their pieces, the user's folder stays.
    EXPECT_EQ(remove_run_outputs(dir_), 8);
    EXPECT_FALSE(fs::exists(dir_ / "fields/fields_000002"));
    EXPECT_FALSE(fs::exists(dir_ / "fields/fields_000003"));
    EXPECT_TRUE(fs::exists(dir_ / "fields/my_plot.png"));
    EXPECT_TRUE(fs::exists(dir_ / "fields/mine/notes.vtr"));
}

} // namespace
} // namespace fddem
