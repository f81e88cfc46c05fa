// SPDX-License-Identifier: MIT
#include "fddem/io/body_file.hpp"

#include "fddem/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

namespace fddem {
namespace {

/// The columns of a header: each name's position (from 0), as the header gives them.
struct Columns {
    std::vector<std::string> names;
    std::map<std::string, std::size_t> index;
    bool has_velocity = false;

    /// The key of an error about a value: its column's name, as in the header.
    [[nodiscard]] const std::string& key(std::size_t column) const { return names[column]; }
};

std::string_view trimmed(std::string_view text)
{
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

/// The comma-separated fields of a line, trimmed.
std::vector<std::string_view> fields_of(std::string_view line)
{
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (std::size_t comma = line.find(','); comma != std::string_view::npos;
         comma = line.find(',', start)) {
        fields.push_back(trimmed(line.substr(start, comma - start)));
        start = comma + 1;
    }
    fields.push_back(trimmed(line.substr(start)));
    return fields;
}

bool is_skipped(std::string_view line)
{
    const std::string_view t = trimmed(line);
    return t.empty() || t.front() == '#';
}

std::vector<std::string> velocity_columns(int dimension)
{
    return dimension == 2 ? std::vector<std::string>{"u", "v"}
                          : std::vector<std::string>{"u", "v", "w"};
}

std::vector<std::string> required_columns(int dimension)
{
    std::vector<std::string> names{"id"};
    for (std::size_t axis = 0; axis < static_cast<std::size_t>(dimension); ++axis) {
        names.push_back(position_column(axis));
    }
    names.emplace_back("diameter");
    names.emplace_back("density");
    return names;
}

/// What the header of a `dimension`-D file must say, for messages.
std::string expected_header(int dimension)
{
    return dimension == 2 ? "id, x, y, diameter, density, and optionally u, v"
                          : "id, x, y, z, diameter, density, and optionally u, v, w";
}

Columns read_header(std::string_view line, int line_number, const std::string& file, int dimension)
{
    const auto fail = [&](const std::string& key, const std::string& message) {
        throw InputError(file, line_number, key,
                         "header: " + message + " (a " + std::to_string(dimension) +
                             "D case's header names " + expected_header(dimension) + ")");
    };
    std::vector<std::string> known = required_columns(dimension);
    const std::vector<std::string> velocity = velocity_columns(dimension);
    known.insert(known.end(), velocity.begin(), velocity.end());
    Columns columns;
    for (const std::string_view field : fields_of(line)) {
        const std::string name(field);
        const std::size_t column = columns.names.size();
        columns.names.push_back(name);
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            fail("", fmt::format("column {}: {}", column + 1,
                                 name.empty() ? std::string("no name")
                                              : "unknown column '" + name + "'"));
        }
        if (!columns.index.emplace(name, column).second) {
            fail("", fmt::format("column {}: '{}' is named twice", column + 1, name));
        }
    }
    for (const std::string& name : required_columns(dimension)) {
        if (columns.index.count(name) == 0) {
            fail("", "no '" + name + "' column");
        }
    }
    const auto given = std::count_if(velocity.begin(), velocity.end(), [&](const std::string& n) {
        return columns.index.count(n) > 0;
    });
    if (given != 0 && given != static_cast<long>(velocity.size())) {
        fail("", "the velocity columns come all or none");
    }
    columns.has_velocity = given != 0;
    return columns;
}

/// One row's values, each checked; `fail(column, message)` throws.
class RowReader {
public:
    RowReader(const Columns& columns, std::vector<std::string_view> fields, std::string file,
              int line)
        : columns_(columns), fields_(std::move(fields)), file_(std::move(file)), line_(line)
    {
    }

    [[noreturn]] void fail(std::size_t column, const std::string& message) const
    {
        throw InputError(file_, line_, columns_.key(column), message);
    }

    /// A finite number (a leading + allowed), above `open_min` when given.
    double number(const std::string& name, std::optional<double> open_min = {}) const
    {
        const std::size_t column = columns_.index.at(name);
        std::string_view text = fields_[column];
        if (text.starts_with('+')) {
            text.remove_prefix(1);
        }
        if (text.empty()) {
            fail(column, "empty value");
        }
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc::result_out_of_range) {
            fail(column, "'" + std::string(text) + "' is out of the range of a double");
        }
        if (error != std::errc() || end != text.data() + text.size()) {
            fail(column, "'" + std::string(text) + "' is not a number");
        }
        if (!std::isfinite(value)) {
            fail(column, "must be a finite number, got '" + std::string(text) + "'");
        }
        if (open_min && !(value > *open_min)) {
            fail(column, fmt::format("{:g} is out of range: must be > {:g}", value, *open_min));
        }
        return value;
    }

    /// A whole number ≥ 0 that fits an int.
    int id() const
    {
        const std::size_t column = columns_.index.at("id");
        const std::string_view text = fields_[column];
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool is_integer = error == std::errc() && end == text.data() + text.size();
        if (!is_integer || value < 0 || value > std::numeric_limits<int>::max()) {
            fail(column, fmt::format("'{}' is not a valid id: must be a whole number in [0, {}]",
                                     text, std::numeric_limits<int>::max()));
        }
        return static_cast<int>(value);
    }

private:
    const Columns& columns_;
    std::vector<std::string_view> fields_;
    std::string file_;
    int line_;
};

BodyRow read_row(const Columns& columns, std::string_view line, int line_number,
                 const std::string& file, int dimension)
{
    std::vector<std::string_view> fields = fields_of(line);
    if (fields.size() != columns.names.size()) {
        throw InputError(file, line_number, "",
                         fmt::format("has {} values; the header has {} columns", fields.size(),
                                     columns.names.size()));
    }
    const RowReader row(columns, std::move(fields), file, line_number);
    BodyRow body;
    body.line = line_number;
    body.id = row.id();
    for (std::size_t axis = 0; axis < static_cast<std::size_t>(dimension); ++axis) {
        body.position.push_back(row.number(position_column(axis)));
    }
    body.diameter = row.number("diameter", 0.0);
    body.density = row.number("density", 0.0);
    if (columns.has_velocity) {
        std::vector<double> velocity;
        for (const std::string& name : velocity_columns(dimension)) {
            velocity.push_back(row.number(name));
        }
        body.velocity = std::move(velocity);
    }
    return body;
}

} // namespace

std::string position_column(std::size_t axis)
{
    return std::string(1, static_cast<char>('x' + axis));
}

std::vector<BodyRow> parse_body_file(std::string_view text, const std::string& file_name,
                                     int dimension)
{
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    if (text.starts_with(byte_order_mark)) {
        text.remove_prefix(byte_order_mark.size());
    }
    std::optional<Columns> columns;
    std::vector<BodyRow> rows;
    std::map<int, int> line_of_id;
    int line_number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (is_skipped(line)) {
            continue;
        }
        if (!columns) {
            columns = read_header(line, line_number, file_name, dimension);
            continue;
        }
        BodyRow row = read_row(*columns, line, line_number, file_name, dimension);
        const auto [at, is_new] = line_of_id.emplace(row.id, line_number);
        if (!is_new) {
            throw InputError(file_name, line_number, columns->key(columns->index.at("id")),
                             fmt::format("the id {} is taken by the body of line {}: ids are "
                                         "unique",
                                         row.id, at->second));
        }
        rows.push_back(std::move(row));
    }
    if (!columns) {
        throw InputError(file_name, 0, "",
                         "has no header line (" + expected_header(dimension) + ")");
    }
    if (rows.empty()) {
        throw InputError(file_name, 0, "", "has a header but no bodies");
    }
    return rows;
}

} // namespace fddem
