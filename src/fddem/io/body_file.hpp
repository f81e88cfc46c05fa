// SPDX-License-Identifier: MIT
#pragma once
/// Reads the bodies of a [[bodies]] entry's `file` (issue 14): a CSV file, one body per row,
/// for the thousands of particles a bed needs. The first line that is neither blank nor a
/// comment (`#`) is the header; it names the columns, in any order:
///
///     id, x, y, [z,] diameter, density [, u, v [, w]]
///
/// z and w in 3D only; the velocity columns all or none. An id is a whole number ≥ 0, unique in
/// the file; every other value a finite number (diameter and density > 0). Each problem is an
/// InputError naming the file, the line and the column (as the error's key).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fddem {

/// One row of a body file.
struct BodyRow {
    int id = 0;
    int line = 0;                                ///< in the file, from 1
    std::vector<double> position;                ///< [m], one entry per axis
    double diameter = 0.0;                       ///< [m]
    double density = 0.0;                        ///< [kg/m³]
    std::optional<std::vector<double>> velocity; ///< [m/s]; none: the file has no u, v (w)
};

/// The rows of a body file's text, for a `dimension`-D case; `file_name` names it in messages.
[[nodiscard]] std::vector<BodyRow> parse_body_file(std::string_view text,
                                                   const std::string& file_name, int dimension);

/// The column of position axis `axis` (x, y, z), as the header and messages name it.
[[nodiscard]] std::string position_column(std::size_t axis);

} // namespace fddem
