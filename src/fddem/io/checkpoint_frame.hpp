// SPDX-License-Identifier: MIT
#pragma once
/// The frame of every checkpoint file (io/checkpoint.hpp): the magic "FDDEMCKP" and the format
/// version in front, and behind the named values a trailer of their length (8 bytes) and the
/// CRC-32 of everything before it (4 bytes, zlib's crc32, ISO-HDLC). A file is written whole to
/// a temporary name and renamed; read back whole, or, for the pieces of a split run's
/// checkpoint, checked in one pass and then read entry by entry, so that a rank restoring its
/// block holds one array of each piece at a time and never the piece.

#include "fddem/io/checkpoint_archive.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace fddem {

inline constexpr std::string_view checkpoint_magic = "FDDEMCKP";

/// The CRC-32 of `bytes` continued from `crc` (0 to begin; zlib's crc32 is incremental).
[[nodiscard]] std::uint32_t continue_crc32(std::uint32_t crc, std::string_view bytes);

/// The magic and `version`: the first 16 bytes of a file.
[[nodiscard]] std::string frame_start(std::uint64_t version);

/// Writes `head` then `state` (both after frame_start) to `path` atomically with the trailer,
/// without copying them into one string; returns the CRC-32. Throws OutputError.
std::uint32_t write_framed(const std::filesystem::path& path, std::string_view head,
                           std::string_view state);

/// What a framed file's check found.
struct FrameCheck {
    std::uint64_t content_end = 0; ///< where the trailer starts [B]
    std::uint32_t crc = 0;         ///< the trailer's CRC-32 (checked)
};

/// A framed file read whole and checked: its bytes (trailer included) and the check.
struct FramedBytes {
    std::string bytes;
    FrameCheck check;
};

/// Reads `path` whole and checks magic, `version`, length and CRC-32. Throws CheckpointError
/// with the reason ("cannot be opened", "is truncated …", "is damaged (CRC-32 …)", …).
[[nodiscard]] FramedBytes read_framed(const std::filesystem::path& path, std::uint64_t version);

/// The same checks in one pass of fixed-size reads, keeping nothing.
[[nodiscard]] FrameCheck check_framed(const std::filesystem::path& path, std::uint64_t version);

/// The named values of a checked framed file, read from disk one at a time (after the 16 bytes
/// of the frame's start). The file is opened for each value and closed again, so that a rank
/// may read from more pieces than it may keep files open. Throws CheckpointError if a name, a
/// size or the end does not match.
class FramedStream {
public:
    FramedStream(const std::filesystem::path& path, const FrameCheck& check);

    /// An integer (as ArchiveWriter wrote it).
    void operator()(std::string_view name, long& value);
    /// A vector of doubles (as ArchiveWriter wrote it: a count, then the values).
    void operator()(std::string_view name, std::vector<double>& values);
    /// Whether every value before the trailer has been read.
    [[nodiscard]] bool is_at_end() const noexcept { return position_ == end_; }

private:
    /// The file, at the next value.
    [[nodiscard]] std::ifstream open() const;
    /// The next entry's name (checked against `name`) and its `n` 8-byte words, into entry_.
    void read_entry(std::ifstream& in, std::string_view name, std::uint64_t n);
    void read_bytes(std::ifstream& in, char* data, std::uint64_t n);

    std::filesystem::path path_;
    std::uint64_t position_ = 0;
    std::uint64_t end_ = 0;
    std::string entry_; ///< the entry being decoded (reused)
};

} // namespace fddem
