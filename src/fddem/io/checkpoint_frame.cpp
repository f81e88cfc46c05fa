// SPDX-License-Identifier: MIT
#include "fddem/io/checkpoint_frame.hpp"

#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <utility>
#include <zlib.h>

namespace fddem {
namespace {

constexpr std::size_t start_bytes = 8 + 8;   ///< magic and version
constexpr std::size_t trailer_bytes = 8 + 4; ///< length and CRC-32

std::uint64_t get_le(std::string_view bytes, std::size_t at, int n)
{
    std::uint64_t value = 0;
    for (int k = 0; k < n; ++k) {
        value |= static_cast<std::uint64_t>(
                     static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]))
                 << (8 * k);
    }
    return value;
}

void put_le(std::string& bytes, std::uint64_t value, int n)
{
    for (int k = 0; k < n; ++k) {
        bytes.push_back(static_cast<char>((value >> (8 * k)) & 0xffU));
    }
}

/// The checks shared by read_framed and check_framed, on a file of `size` bytes whose first 16
/// are `start`, whose last 12 are `trailer`, and whose bytes before the CRC-32 have `crc`.
FrameCheck check_frame(std::uint64_t size, std::string_view start, std::string_view trailer,
                       std::uint32_t crc, std::uint64_t version)
{
    if (size < start_bytes + trailer_bytes) {
        throw CheckpointError(
            fmt::format("is truncated ({} bytes; not even a header and a trailer)", size));
    }
    if (start.substr(0, checkpoint_magic.size()) != checkpoint_magic) {
        throw CheckpointError("is not an fddem checkpoint (no FDDEMCKP magic number)");
    }
    const std::uint64_t stored_version = get_le(start, checkpoint_magic.size(), 8);
    if (stored_version != version) {
        throw CheckpointError(fmt::format("has format version {}; this fddem reads version {}",
                                          stored_version, version));
    }
    FrameCheck check{size - trailer_bytes, 0};
    const std::uint64_t length = get_le(trailer, 0, 8);
    if (length != check.content_end) {
        throw CheckpointError(
            fmt::format("is truncated or damaged ({} bytes; its trailer expects {})", size,
                        length + trailer_bytes));
    }
    check.crc = static_cast<std::uint32_t>(get_le(trailer, 8, 4));
    if (crc != check.crc) {
        throw CheckpointError(
            fmt::format("is damaged (CRC-32 {:08x}, the file records {:08x})", crc, check.crc));
    }
    return check;
}

std::ifstream open_checkpoint(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw CheckpointError("cannot be opened");
    }
    return in;
}

std::uint64_t file_size(std::ifstream& in)
{
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    return static_cast<std::uint64_t>(std::max<std::streamoff>(size, 0));
}

} // namespace

std::uint32_t continue_crc32(std::uint32_t crc, std::string_view bytes)
{
    // zlib takes bytes as unsigned char; reading a char buffer through it is well defined.
    const auto* data = reinterpret_cast<const Bytef*>( // NOLINT(*-reinterpret-cast)
        bytes.data());
    return static_cast<std::uint32_t>(crc32_z(crc, data, bytes.size()));
}

std::string frame_start(std::uint64_t version)
{
    std::string start(checkpoint_magic);
    put_le(start, version, 8);
    return start;
}

std::uint32_t write_framed(const std::filesystem::path& path, std::string_view head,
                           std::string_view state)
{
    std::string trailer;
    put_le(trailer, head.size() + state.size(), 8);
    std::uint32_t crc = continue_crc32(0, head);
    crc = continue_crc32(crc, state);
    crc = continue_crc32(crc, trailer);
    put_le(trailer, crc, 4);
    const std::array<std::string_view, 3> parts{head, state, trailer};
    write_file_atomically(path, parts);
    return crc;
}

FramedBytes read_framed(const std::filesystem::path& path, std::uint64_t version)
{
    std::ifstream in = open_checkpoint(path);
    // Read into a string of the file's size (through a string stream it would be held twice).
    FramedBytes file{std::string(file_size(in), '\0'), {}};
    if (!in.read(file.bytes.data(), static_cast<std::streamsize>(file.bytes.size()))) {
        throw CheckpointError("cannot be read");
    }
    const std::string_view bytes = file.bytes;
    const std::uint64_t size = bytes.size();
    const std::size_t end = size >= trailer_bytes ? size - trailer_bytes : 0;
    file.check = check_frame(
        size, bytes.substr(0, start_bytes), bytes.substr(end),
        size >= trailer_bytes ? continue_crc32(0, bytes.substr(0, end + 8)) : 0, version);
    return file;
}

FrameCheck check_framed(const std::filesystem::path& path, std::uint64_t version)
{
    std::ifstream in = open_checkpoint(path);
    const std::uint64_t size = file_size(in);
    std::string start(start_bytes, '\0');
    std::string trailer(trailer_bytes, '\0');
    std::uint32_t crc = 0;
    if (size >= start_bytes + trailer_bytes) {
        in.seekg(static_cast<std::streamoff>(size - trailer_bytes));
        if (!in.read(trailer.data(), trailer_bytes)) {
            throw CheckpointError("cannot be read");
        }
        in.seekg(0);
        // The CRC-32 of all but its own 4 bytes, 1 MiB at a time.
        std::string chunk(std::size_t{1} << 20, '\0');
        for (std::uint64_t left = size - 4; left > 0;) {
            const std::uint64_t n = std::min<std::uint64_t>(left, chunk.size());
            if (!in.read(chunk.data(), static_cast<std::streamsize>(n))) {
                throw CheckpointError("cannot be read");
            }
            if (left == size - 4) {
                start.assign(chunk, 0, start_bytes);
            }
            crc = continue_crc32(crc, std::string_view(chunk.data(), n));
            left -= n;
        }
    }
    return check_frame(size, start, trailer, crc, version);
}

FramedStream::FramedStream(const std::filesystem::path& path, const FrameCheck& check)
    : path_(path), position_(start_bytes), end_(check.content_end)
{
}

std::ifstream FramedStream::open() const
{
    std::ifstream in = open_checkpoint(path_);
    in.seekg(static_cast<std::streamoff>(position_));
    return in;
}

void FramedStream::read_bytes(std::ifstream& in, char* data, std::uint64_t n)
{
    if (end_ - position_ < n) {
        throw CheckpointError(fmt::format("ends early (at byte {}, {} more wanted)", position_, n));
    }
    if (!in.read(data, static_cast<std::streamsize>(n))) {
        throw CheckpointError("cannot be read");
    }
    position_ += n;
}

void FramedStream::read_entry(std::ifstream& in, std::string_view name, std::uint64_t n)
{
    char length = 0;
    read_bytes(in, &length, 1);
    std::string found(static_cast<unsigned char>(length), '\0');
    read_bytes(in, found.data(), found.size());
    if (found != name) {
        throw CheckpointError(fmt::format("holds '{}' where '{}' was expected", found, name));
    }
    entry_.resize(8 * n);
    read_bytes(in, entry_.data(), entry_.size());
}

void FramedStream::operator()(std::string_view name, long& value)
{
    std::ifstream in = open();
    read_entry(in, name, 1);
    value = static_cast<long>(static_cast<std::int64_t>(get_le(entry_, 0, 8)));
}

void FramedStream::operator()(std::string_view name, std::vector<double>& values)
{
    std::ifstream in = open();
    read_entry(in, name, 1);
    const std::uint64_t n = get_le(entry_, 0, 8);
    if (n > (end_ - position_) / 8) {
        throw CheckpointError(
            fmt::format("has {} values of '{}' in {} bytes", n, name, end_ - position_));
    }
    entry_.resize(8 * n);
    read_bytes(in, entry_.data(), entry_.size());
    values.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        values[k] = std::bit_cast<double>(get_le(entry_, 8 * k, 8));
    }
}

} // namespace fddem
