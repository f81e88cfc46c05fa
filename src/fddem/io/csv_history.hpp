// SPDX-License-Identifier: MIT
#pragma once
/// An append-only CSV history (solver.csv, particles.csv): a header, then one row per record,
/// flushed every row so that a run killed at any moment leaves every complete row readable.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace fddem {

class CsvHistory {
public:
    /// Creates `path` with the header line (replacing any file of that name).
    CsvHistory(const std::filesystem::path& path, const std::vector<std::string>& columns);
    /// Appends to an existing history (a restarted run, after truncate_history).
    struct Continue {};
    CsvHistory(const std::filesystem::path& path, const std::vector<std::string>& columns,
               Continue /*tag*/);
    CsvHistory(const CsvHistory&) = delete;
    CsvHistory& operator=(const CsvHistory&) = delete;
    CsvHistory(CsvHistory&&) = delete;
    CsvHistory& operator=(CsvHistory&&) = delete;
    ~CsvHistory();

    /// One row; values print in shortest round-trip form. Throws OutputError on failure.
    void append(std::initializer_list<double> values);
    void append(const std::vector<double>& values);

    /// Length of the file so far [bytes]: every row appended is flushed.
    [[nodiscard]] std::uint64_t size() const noexcept { return size_; }
    /// Forces the rows to disk (before a checkpoint records size()). Throws OutputError.
    void sync();

private:
    void write(const std::string& text);

    std::filesystem::path path_;
    std::FILE* file_;
    std::size_t n_columns_;
    std::uint64_t size_ = 0;
};

/// Checks that the history at `path` can be cut back to its first `bytes` (a restart): it
/// exists, starts with the header of `columns`, is at least that long, and the cut falls at
/// the end of a row. Throws InputError (naming the file) otherwise; changes nothing.
void check_history(const std::filesystem::path& path, const std::vector<std::string>& columns,
                   std::uint64_t bytes);

/// Cuts the history at `path` back to its first `bytes` (check_history first). Throws
/// OutputError.
void truncate_history(const std::filesystem::path& path, std::uint64_t bytes);

/// A small whole CSV written atomically (line samples).
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

} // namespace fddem
