// SPDX-License-Identifier: MIT
#pragma once
/// Whole-file writes that never leave a half-written file: write to a temporary name in the
/// same directory, flush, then rename over the target (DESIGN.md §4, STYLE.md §9).

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string_view>

namespace fddem {

/// An output file could not be written during a run (disk full, directory removed, …).
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Writes `content` to `path` atomically. Throws OutputError on failure; `path` is untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);
/// The same for a file made of `parts`, one after the other (no copy of them is made).
void write_file_atomically(const std::filesystem::path& path,
                           std::span<const std::string_view> parts);

/// Flushes a directory's entries (a rename into it) to disk, so that a file renamed into place
/// survives a crash of the machine, not only of the process. Best effort: false if the file
/// system refuses (some do for directories; the rename itself is atomic regardless).
bool sync_directory(const std::filesystem::path& directory) noexcept;

} // namespace fddem
