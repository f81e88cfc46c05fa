// SPDX-License-Identifier: MIT
#pragma once
// Reads two-column reference CSV files kept with the cases (header line, then x,y rows).

#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fddem::test {

inline std::vector<std::pair<double, double>> read_two_columns(const std::string& path)
{
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot open reference file " + path);
    }
    std::string line;
    std::getline(in, line); // header
    std::vector<std::pair<double, double>> rows;
    while (std::getline(in, line)) {
        if (line.empty()) {
            continue;
        }
        const auto comma = line.find(',');
        rows.emplace_back(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
    }
    return rows;
}

} // namespace fddem::test
