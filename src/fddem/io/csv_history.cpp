// SPDX-License-Identifier: MIT
#include "fddem/io/csv_history.hpp"

#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

namespace fddem {
namespace {

std::string header_line(const std::vector<std::string>& columns)
{
    std::string line;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        line += (k == 0 ? "" : ",") + columns[k];
    }
    return line + "\n";
}

template <class Values>
std::string row_line(const Values& values)
{
    std::string line;
    bool is_first = true;
    for (const double v : values) {
        line += is_first ? "" : ",";
        line += fmt::format("{}", v); // shortest representation that reads back exactly
        is_first = false;
    }
    return line + "\n";
}

} // namespace

CsvHistory::CsvHistory(const std::filesystem::path& path, const std::vector<std::string>& columns)
    : path_(path), file_(std::fopen(path.c_str(), "wb")), n_columns_(columns.size())
{
    if (file_ == nullptr) {
        throw OutputError("cannot create " + path.string());
    }
    const std::string header = header_line(columns);
    if (std::fputs(header.c_str(), file_) < 0 || std::fflush(file_) != 0) {
        throw OutputError("cannot write " + path.string());
    }
}

CsvHistory::~CsvHistory()
{
    if (file_ != nullptr) {
        std::fclose(file_);
    }
}

void CsvHistory::append(std::initializer_list<double> values)
{
    append(std::vector<double>(values));
}

void CsvHistory::append(const std::vector<double>& values)
{
    if (values.size() != n_columns_) {
        throw OutputError(fmt::format("{}: a row of {} values for {} columns", path_.string(),
                                      values.size(), n_columns_));
    }
    const std::string line = row_line(values);
    if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0) {
        throw OutputError("cannot write " + path_.string() + " (disk full?)");
    }
}

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows)
{
    std::string text = header_line(columns);
    for (const auto& row : rows) {
        text += row_line(row);
    }
    write_file_atomically(path, text);
}

} // namespace fddem
