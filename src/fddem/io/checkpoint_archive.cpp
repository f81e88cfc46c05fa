// SPDX-License-Identifier: MIT
#include "fddem/io/checkpoint_archive.hpp"

namespace fddem {

void ArchiveWriter::put_name(std::string_view name)
{
    // Names are short identifiers written by fddem itself ("body.centre").
    const char length = static_cast<char>(name.size() & 0xffU);
    append(std::string_view(&length, 1));
    append(name.substr(0, 0xff));
}

std::uint64_t ArchiveReader::get_u64()
{
    if (bytes_.size() - position_ < 8) {
        fail("the data end early");
    }
    std::uint64_t value = 0;
    for (int k = 0; k < 8; ++k) {
        value |= static_cast<std::uint64_t>(
                     static_cast<unsigned char>(bytes_[position_ + static_cast<std::size_t>(k)]))
                 << (8 * k);
    }
    position_ += 8;
    return value;
}

void ArchiveReader::expect_name(std::string_view name)
{
    current_name_ = name;
    if (position_ >= bytes_.size()) {
        fail("the data end early");
    }
    const auto length = static_cast<unsigned char>(bytes_[position_]);
    if (bytes_.size() - position_ - 1 < length) {
        fail("the data end early");
    }
    const std::string_view stored = bytes_.substr(position_ + 1, length);
    if (stored != name) {
        fail("found '" + std::string(stored) +
             "' instead (a checkpoint of another fddem "
             "version?)");
    }
    position_ += 1 + length;
}

std::size_t ArchiveReader::get_count(std::size_t element_bytes)
{
    const std::uint64_t n = get_u64();
    if (n > (bytes_.size() - position_) / element_bytes) {
        fail("a count of " + std::to_string(n) + " that does not fit in the data");
    }
    return static_cast<std::size_t>(n);
}

void ArchiveReader::fail(const std::string& what) const
{
    throw CheckpointError("at byte " + std::to_string(position_) + ", reading '" + current_name_ +
                          "': " + what);
}

} // namespace fddem
