// SPDX-License-Identifier: MIT
#pragma once
/// Every case key, declared once: section, name, type, unit, default, range, doc
/// (DESIGN.md §7; deal.II's ParameterHandler idea). The reader checks a case against this
/// table; `fddem info --keys` and docs/case-file.md print it.

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace fddem {

enum class KeyType {
    real,           ///< a number (an integer is accepted)
    integer,        ///< a whole number
    string,         ///< text, possibly from a fixed list of choices
    boolean,        ///< true or false
    real_vector,    ///< one number per axis
    integer_vector, ///< one whole number per axis
    boolean_vector, ///< one true/false per axis
};

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

    [[nodiscard]] std::string full_name() const { return section + "." + name; }
};

/// Sections that are arrays of tables ([[output.lines]]), with a one-line doc each.
struct TableArraySpec {
    std::string name;
    std::string doc;
};

/// The schema. Later issues add sections ([[bodies]], [contact], [nondimensional]) here.
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
