// SPDX-License-Identifier: MIT
#include "fddem/io/case_changes.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <map>
#include <sstream>

namespace fddem {
namespace {

using Flat = std::map<std::string, std::string>;

void flatten(const toml::node& node, const std::string& name, Flat& out)
{
    if (const toml::table* table = node.as_table()) {
        for (const auto& [key, value] : *table) {
            flatten(value,
                    name.empty() ? std::string(key.str()) : name + "." + std::string(key.str()),
                    out);
        }
        return;
    }
    const toml::array* array = node.as_array();
    if (array != nullptr && array->is_array_of_tables()) {
        for (std::size_t k = 0; k < array->size(); ++k) {
            flatten(*array->get(k), name + "." + std::to_string(k + 1), out);
        }
        return;
    }
    std::ostringstream text;
    node.visit([&](const auto& value) { text << value; });
    out[name] = text.str();
}

Flat flat_case(std::string_view text)
{
    Flat out;
    try {
        flatten(toml::parse(text), "", out);
    } catch (const toml::parse_error&) {
        out.clear();
    }
    return out;
}

} // namespace

std::vector<std::string> case_changes(std::string_view before, std::string_view after)
{
    const Flat old_case = flat_case(before);
    const Flat new_case = flat_case(after);
    std::vector<std::string> changes;
    if (old_case.empty() || new_case.empty()) {
        return changes;
    }
    const auto value = [](const Flat& flat, const std::string& key) {
        const auto found = flat.find(key);
        return found == flat.end() ? std::string("(none)") : found->second;
    };
    Flat keys = old_case;
    keys.insert(new_case.begin(), new_case.end());
    for (const auto& [key, ignored] : keys) {
        const std::string a = value(old_case, key);
        const std::string b = value(new_case, key);
        if (a != b) {
            changes.push_back(fmt::format("{}: {} → {}", key, a, b));
        }
    }
    return changes;
}

} // namespace fddem
