// SPDX-License-Identifier: MIT
#pragma once
/// How a schema row binds its key to a field of CaseConfig (io/case_schema.cpp): a root (the
/// case, one [[bodies]] entry, one wall…) and a path of member pointers from it. The field's type
/// says how the checked value is stored; an enum field takes its choices from its name table
/// (io/case_names.hpp). So each key is written once: in its schema row.

#include "fddem/io/case_names.hpp"
#include "fddem/io/case_schema.hpp"
#include "fddem/simulation/case_config.hpp"

#include <type_traits>
#include <utility>

namespace fddem::detail {

/// The field at the end of `path`, from `object`.
template <class Object>
Object& follow(Object& object)
{
    return object;
}
template <class Object, class Member, class... Rest>
decltype(auto) follow(Object& object, Member Object::*member, Rest... rest)
{
    return follow(object.*member, rest...);
}

inline void assign(double& field, const KeyValue& value)
{
    field = std::get<double>(value);
}
inline void assign(std::optional<double>& field, const KeyValue& value)
{
    field = std::get<double>(value);
}
inline void assign(int& field, const KeyValue& value)
{
    field = static_cast<int>(std::get<std::int64_t>(value));
}
inline void assign(long& field, const KeyValue& value)
{
    field = std::get<std::int64_t>(value);
}
inline void assign(bool& field, const KeyValue& value)
{
    field = std::get<bool>(value);
}
inline void assign(std::string& field, const KeyValue& value)
{
    field = std::get<std::string>(value);
}
inline void assign(std::vector<double>& field, const KeyValue& value)
{
    field = std::get<std::vector<double>>(value);
}
inline void assign(std::vector<bool>& field, const KeyValue& value)
{
    field = std::get<std::vector<bool>>(value);
}
inline void assign(std::vector<int>& field, const KeyValue& value)
{
    field.clear();
    for (const std::int64_t n : std::get<std::vector<std::int64_t>>(value)) {
        field.push_back(static_cast<int>(n));
    }
}
/// A word of the enum's table (the key's choices, already checked).
template <class Enum>
requires std::is_enum_v<Enum>
void assign(Enum& field, const KeyValue& value)
{
    field = enum_named<Enum>(std::get<std::string>(value)).value();
}

/// `spec` bound to the field at `path` from `root(config, entry)`; an enum field gives the
/// key its choices.
template <class Root, class... Path>
KeySpec bound_in(Root root, KeySpec spec, Path... path)
{
    using Field = std::remove_cvref_t<decltype(follow(
        root(std::declval<CaseConfig&>(), std::size_t{}), path...))>;
    if constexpr (std::is_enum_v<Field>) {
        spec.choices = names_of<Field>();
    }
    spec.set = [root, path...](CaseConfig& config, std::size_t entry, const KeyValue& value) {
        assign(follow(root(config, entry), path...), value);
    };
    return spec;
}

/// A key of a section: the field at `path` from the case.
template <class... Path>
KeySpec bound(KeySpec spec, Path... path)
{
    return bound_in([](CaseConfig& config, std::size_t /*entry*/) -> CaseConfig& { return config; },
                    std::move(spec), path...);
}

/// The entry `entry` of a table array, made when its first key is read.
template <class Entry>
Entry& entry_of(std::vector<Entry>& entries, std::size_t entry)
{
    if (entries.size() <= entry) {
        entries.resize(entry + 1);
    }
    return entries[entry];
}

/// A key of each [[bodies]] entry: the field at `path` from its BodyConfig.
template <class... Path>
KeySpec body_key(KeySpec spec, Path... path)
{
    return bound_in([](CaseConfig& config,
                       std::size_t entry) -> BodyConfig& { return entry_of(config.bodies, entry); },
                    std::move(spec), path...);
}

/// A key of each [[output.lines]] entry: the field at `path` from its LineSample.
template <class... Path>
KeySpec line_key(KeySpec spec, Path... path)
{
    return bound_in(
        [](CaseConfig& config, std::size_t entry) -> LineSample& {
            return entry_of(config.output.lines, entry);
        },
        std::move(spec), path...);
}

} // namespace fddem::detail
