// SPDX-License-Identifier: MIT
#pragma once
// Reads a CSV file fddem wrote (a header line, then rows of numbers) into named columns.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fddem::test {

struct CsvTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;

    /// The values of column `name`, top to bottom; throws if there is none.
    [[nodiscard]] std::vector<double> column(const std::string& name) const
    {
        const auto at = std::find(columns.begin(), columns.end(), name);
        if (at == columns.end()) {
            throw std::runtime_error("no column " + name);
        }
        const auto index = static_cast<std::size_t>(at - columns.begin());
        std::vector<double> values;
        for (const std::vector<double>& row : rows) {
            values.push_back(row.at(index));
        }
        return values;
    }
};

/// The comma-separated fields of one line.
inline std::vector<std::string> csv_fields(const std::string& line)
{
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) {
        fields.push_back(field);
    }
    return fields;
}

inline CsvTable read_csv_table(const std::filesystem::path& path)
{
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot open " + path.string());
    }
    CsvTable table;
    std::string line;
    std::getline(in, line);
    table.columns = csv_fields(line);
    while (std::getline(in, line)) {
        std::vector<double> row;
        for (const std::string& field : csv_fields(line)) {
            row.push_back(std::stod(field));
        }
        table.rows.push_back(row);
    }
    return table;
}

} // namespace fddem::test
