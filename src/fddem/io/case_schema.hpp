// SPDX-License-Identifier: MIT
#pragma once
/// Every case key, declared once: section, name, type, unit, default, range, doc, and the field
/// of CaseConfig it sets (DESIGN.md §7; deal.II's ParameterHandler idea). The reader checks a
/// case against this table and converts it through it; `fddem info --keys` and
/// docs/case-file.md print it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace fddem {

struct CaseConfig;

enum class KeyType {
    real,           ///< a number (an integer is accepted)
    integer,        ///< a whole number
    string,         ///< text, possibly from a fixed list of choices
    boolean,        ///< true or false
    real_vector,    ///< one number per axis
    integer_vector, ///< one whole number per axis
    boolean_vector, ///< one true/false per axis
    angular,        ///< an angular quantity: a number (about z) in 2D, three numbers in 3D
};

/// A key's value as read, by its KeyType: real → double, integer → int64, string, boolean,
/// real_vector → vector<double>, integer_vector → vector<int64>, boolean_vector → vector<bool>
/// (one entry per axis), angular → vector<double> (one entry in 2D, three in 3D).
using KeyValue = std::variant<double, std::int64_t, std::string, bool, std::vector<double>,
                              std::vector<std::int64_t>, std::vector<bool>>;

/// Stores a key's checked value in its field of the case; `entry` counts the entries of a table
/// array ([[bodies]]) from 0 and is 0 elsewhere.
using KeySetter = std::function<void(CaseConfig& config, std::size_t entry, const KeyValue&)>;

struct KeySpec {
    std::string section; ///< "domain", or "output.lines" for entries of a table array
    std::string name;
    KeyType type;
    std::string unit;                 ///< "" for dimensionless
    std::optional<std::string> value; ///< the default as TOML text; none: required
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool is_min_open = false; ///< min excluded (> rather than ≥)
    bool is_max_open = false;
    std::vector<std::string> choices; ///< allowed strings (empty: any)
    std::string doc;
    KeySetter set; ///< none: the key is read but sets nothing ([derived], written by fddem)

    [[nodiscard]] std::string full_name() const { return section + "." + name; }
};

/// The sides of the box as the keys of [walls] and [boundaries] name them, [axis][side] (side 0:
/// low, 1: high).
inline constexpr std::array<std::array<const char*, 2>, 3> side_names{
    {{"x_low", "x_high"}, {"y_low", "y_high"}, {"z_low", "z_high"}}};

/// Sections that are arrays of tables ([[output.lines]]), with a one-line doc each.
struct TableArraySpec {
    std::string name;
    std::string doc;
};

/// The schema, in the order of docs/case-file.md.
[[nodiscard]] std::vector<KeySpec> case_schema();
[[nodiscard]] std::vector<TableArraySpec> case_table_arrays();
/// Human-readable type name ("number", "[number; dim]", …).
[[nodiscard]] std::string type_name(KeyType type);
/// The valid range or choices as text ("> 0", "[0, 1]", "one of: a, b"), "" if unrestricted.
[[nodiscard]] std::string range_text(const KeySpec& spec);

/// Every key with type, unit, default, range and doc: plain text for `fddem info --keys`, or
/// Markdown (docs/case-file.md).
[[nodiscard]] std::string describe_keys(bool markdown);

} // namespace fddem
