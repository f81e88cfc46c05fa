// SPDX-License-Identifier: MIT
#include "fddem/io/csv_history.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <system_error>
#include <unistd.h>

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
    write(header_line(columns));
}

CsvHistory::CsvHistory(const std::filesystem::path& path, const std::vector<std::string>& columns,
                       Continue /*tag*/)
    : path_(path), file_(std::fopen(path.c_str(), "ab")), n_columns_(columns.size())
{
    std::error_code error;
    size_ = std::filesystem::file_size(path, error);
    if (file_ == nullptr || error) {
        throw OutputError("cannot append to " + path.string());
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
    write(row_line(values));
}

void CsvHistory::write(const std::string& text)
{
    if (std::fputs(text.c_str(), file_) < 0 || std::fflush(file_) != 0) {
        throw OutputError("cannot write " + path_.string() + " (disk full?)");
    }
    size_ += text.size();
}

void CsvHistory::sync()
{
    if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0) {
        throw OutputError("cannot sync " + path_.string());
    }
}

void check_history(const std::filesystem::path& path, const std::vector<std::string>& columns,
                   std::uint64_t bytes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path.string(), 0, "", "missing: the run directory is incomplete");
    }
    const std::string header = header_line(columns);
    std::string first;
    std::getline(in, first);
    if (first + "\n" != header) {
        throw InputError(path.string(), 1, "",
                         "the header is not fddem's for this case (" +
                             std::to_string(columns.size()) + " columns expected)");
    }
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(path, error);
    if (error || size < bytes || bytes < header.size()) {
        throw InputError(path.string(), 0, "",
                         fmt::format("{} bytes, shorter than the {} the checkpoint records: the "
                                     "file was cut or replaced",
                                     size, bytes));
    }
    in.seekg(static_cast<std::streamoff>(bytes - 1));
    if (in.get() != '\n') {
        throw InputError(path.string(), 0, "",
                         fmt::format("byte {} is not the end of a row, as the checkpoint "
                                     "records: the file was changed",
                                     bytes));
    }
}

void truncate_history(const std::filesystem::path& path, std::uint64_t bytes)
{
    std::error_code error;
    std::filesystem::resize_file(path, bytes, error);
    if (error) {
        throw OutputError("cannot truncate " + path.string() + ": " + error.message());
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
