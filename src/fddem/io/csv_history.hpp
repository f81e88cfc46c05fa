// SPDX-License-Identifier: MIT
#pragma once
/// An append-only CSV history (solver.csv, particles.csv): a header, then one row per record,
/// flushed every row so that a run killed at any moment leaves every complete row readable.

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace fddem {

class CsvHistory {
public:
    CsvHistory(const std::filesystem::path& path, const std::vector<std::string>& columns);
    CsvHistory(const CsvHistory&) = delete;
    CsvHistory& operator=(const CsvHistory&) = delete;
    CsvHistory(CsvHistory&&) = delete;
    CsvHistory& operator=(CsvHistory&&) = delete;
    ~CsvHistory();

    /// One row; values print in shortest round-trip form. Throws OutputError on failure.
    void append(std::initializer_list<double> values);
    void append(const std::vector<double>& values);

private:
    std::filesystem::path path_;
    std::FILE* file_;
    std::size_t n_columns_;
};

/// A small whole CSV written atomically (line samples).
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

} // namespace fddem
