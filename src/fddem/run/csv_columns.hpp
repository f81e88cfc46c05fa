// SPDX-License-Identifier: MIT
#pragma once
/// Output columns written once: a row visitor names each column next to its value,
/// `visit(ColumnName, value)` in column order, so the header and the rows come from one list.
/// Component names follow the dimension: x, y[, z] and u, v[, w]; an angular quantity is one
/// column in 2D (about z) and three, `_x`, `_y`, `_z`, in 3D.

#include "fddem/core/vec.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace fddem {

/// stem + component: "f" + "x" is "fx", "omega" + "_y" is "omega_y", "time" + "" is "time".
struct ColumnName {
    std::string_view stem;
    std::string_view component = {};
    [[nodiscard]] std::string str() const
    {
        std::string name(stem);
        name += component;
        return name;
    }
};

inline constexpr std::array<std::string_view, 3> axis_names = {"x", "y", "z"};
inline constexpr std::array<std::string_view, 3> velocity_names = {"u", "v", "w"};
inline constexpr std::array<std::string_view, 3> angular_suffixes = {"_x", "_y", "_z"};

/// The Dim components of `value`, named stem + names[axis].
template <int Dim, class Visit>
void visit_components(Visit& visit, std::string_view stem,
                      const std::array<std::string_view, 3>& names, const Vec<Dim>& value)
{
    for (int axis = 0; axis < Dim; ++axis) {
        visit(ColumnName{stem, names.at(static_cast<std::size_t>(axis))}, value[axis]);
    }
}

/// An angular quantity: `stem` in 2D, stem_x, stem_y, stem_z in 3D.
template <int Dim, class Visit>
void visit_angular(Visit& visit, std::string_view stem, const AngularVec<Dim>& value)
{
    if constexpr (Dim == 2) {
        visit(ColumnName{stem, ""}, value);
    } else {
        visit_components<3>(visit, stem, angular_suffixes, value);
    }
}

/// The header of the rows `visit_row(visit)` writes.
template <class VisitRow>
[[nodiscard]] std::vector<std::string> column_names(const VisitRow& visit_row)
{
    std::vector<std::string> names;
    auto name_of = [&names](ColumnName name, double /*value*/) { names.push_back(name.str()); };
    visit_row(name_of);
    return names;
}

/// The values of one row, into `values` (cleared first; its storage is reused).
template <class VisitRow>
void row_values(const VisitRow& visit_row, std::vector<double>& values)
{
    values.clear();
    auto value_of = [&values](ColumnName /*name*/, double value) { values.push_back(value); };
    visit_row(value_of);
}

} // namespace fddem
