// SPDX-License-Identifier: MIT
// The frame of checkpoint files (io/checkpoint_frame.hpp): a file written from its parts reads
// back whole; the one-pass check that a split run's pieces get (check_framed) refuses exactly
// what reading the file whole refuses, with the same reason; and a piece read entry by entry
// from disk (FramedStream) gives the values ArchiveWriter wrote, bit for bit, and names a value
// that is not where it is expected.

#include "fddem/io/checkpoint_frame.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include "support/files_and_programs.hpp"

namespace fddem {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t version = 42;

class CheckpointFrameTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = test::fresh_test_directory("fddem_checkpoint_frame");
        ArchiveWriter head;
        head.bytes() = frame_start(version);
        head("piece", 3L);
        ArchiveWriter state;
        // More than the check's 1 MiB chunk, so that it reads the file in several.
        values_.resize(200'000);
        for (std::size_t k = 0; k < values_.size(); ++k) {
            values_[k] =
                std::sin(0.001 * static_cast<double>(k)) * 1e-300 * (k % 3 == 0 ? 1 : 1e300);
        }
        values_[7] = -0.0;
        values_[8] = std::numeric_limits<double>::denorm_min();
        state("fluid.u", values_);
        state("step", 17L);
        file_ = dir_ / "piece.ckpt";
        crc_ = write_framed(file_, head.bytes(), state.bytes());
        bytes_ = test::file_contents(file_);
    }

    /// The reasons the whole read and the one-pass check give for `bytes` ("accepted" if none).
    std::pair<std::string, std::string> refusals(const std::string& bytes)
    {
        const fs::path path = dir_ / "damaged.ckpt";
        std::ofstream(path, std::ios::binary) << bytes;
        std::pair<std::string, std::string> said{"accepted", "accepted"};
        try {
            static_cast<void>(read_framed(path, version));
        } catch (const CheckpointError& e) {
            said.first = e.what();
        }
        try {
            static_cast<void>(check_framed(path, version));
        } catch (const CheckpointError& e) {
            said.second = e.what();
        }
        return said;
    }

    fs::path dir_;
    fs::path file_;
    std::string bytes_;
    std::vector<double> values_;
    std::uint32_t crc_ = 0;
};

TEST_F(CheckpointFrameTest, WrittenFromItsPartsItReadsBackWithItsCrc)
{
    const FramedBytes whole = read_framed(file_, version);
    EXPECT_EQ(whole.bytes, bytes_);
    EXPECT_EQ(whole.check.crc, crc_);
    EXPECT_EQ(whole.check.content_end, bytes_.size() - 12);
    const FrameCheck check = check_framed(file_, version);
    EXPECT_EQ(check.crc, crc_);
    EXPECT_EQ(check.content_end, whole.check.content_end);
}

TEST_F(CheckpointFrameTest, TheOnePassCheckRefusesWhatTheWholeReadRefusesWithTheSameReason)
{
    std::vector<std::string> cases;
    for (const std::size_t at : {std::size_t{3}, std::size_t{20}, bytes_.size() / 2,
                                 bytes_.size() - 14, bytes_.size() - 2}) {
        std::string damaged = bytes_;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
        cases.push_back(damaged);
    }
    cases.push_back(bytes_.substr(0, bytes_.size() / 2));
    cases.push_back(bytes_.substr(0, 20));
    cases.push_back("");
    std::string newer = bytes_;
    newer[8] = static_cast<char>(version + 1);
    cases.push_back(newer);
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const auto [whole, one_pass] = refusals(cases[k]);
        EXPECT_NE(whole, "accepted") << "case " << k;
        EXPECT_EQ(one_pass, whole) << "case " << k;
    }
    EXPECT_EQ(refusals(bytes_), std::make_pair(std::string("accepted"), std::string("accepted")));
}

TEST_F(CheckpointFrameTest, EntriesReadFromDiskOneAtATimeAreTheValuesWrittenBitForBit)
{
    FramedStream stream(file_, check_framed(file_, version));
    long piece = 0;
    stream("piece", piece);
    EXPECT_EQ(piece, 3);
    std::vector<double> read;
    stream("fluid.u", read);
    ASSERT_EQ(read.size(), values_.size());
    for (std::size_t k = 0; k < read.size(); ++k) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(read[k]), std::bit_cast<std::uint64_t>(values_[k]))
            << k;
    }
    EXPECT_FALSE(stream.is_at_end());
    long step = 0;
    stream("step", step);
    EXPECT_EQ(step, 17);
    EXPECT_TRUE(stream.is_at_end());
}

TEST_F(CheckpointFrameTest, AValueNotWhereItIsExpectedIsNamed)
{
    FramedStream stream(file_, check_framed(file_, version));
    long piece = 0;
    stream("piece", piece);
    std::vector<double> read;
    try {
        stream("fluid.p", read);
        FAIL() << "read fluid.u as fluid.p";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("'fluid.u' where 'fluid.p'"), std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace fddem
