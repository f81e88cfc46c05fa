// SPDX-License-Identifier: MIT
#include "fddem/io/case_keys.hpp"

#include "fddem/io/case_document.hpp"
#include "fddem/io/did_you_mean.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace fddem {
namespace {

/// Each section of the schema once, in its order, and every full key name.
struct KnownNames {
    std::vector<std::string> sections;
    std::vector<std::string> keys;
};

KnownNames known_names(const std::vector<KeySpec>& schema)
{
    KnownNames known;
    for (const KeySpec& spec : schema) {
        if (std::find(known.sections.begin(), known.sections.end(), spec.section) ==
            known.sections.end()) {
            known.sections.push_back(spec.section);
        }
        known.keys.push_back(spec.full_name());
    }
    return known;
}

bool is_known(const std::vector<std::string>& names, const std::string& name)
{
    return std::find(names.begin(), names.end(), name) != names.end();
}

void check_table_array(const CaseDocument& doc, const std::string& path, const toml::node& entry,
                       const std::vector<std::string>& keys)
{
    const toml::array* array = entry.as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        doc.fail(path, &entry, "must be an array of tables ([[" + path + "]])");
    }
    for (const toml::node& element : *array) {
        for (const auto& [k, v] : *element.as_table()) {
            const std::string full = path + "." + std::string(k.str());
            if (!is_known(keys, full)) {
                doc.fail(full, &v, "unknown key '" + full + "'" + suggestion(full, keys));
            }
        }
    }
}

/// Every section and key of the case is in the schema.
void check_names(const CaseDocument& doc, const std::vector<KeySpec>& schema)
{
    const KnownNames known = known_names(schema);
    for (const auto& [key, value] : doc.root()) {
        const std::string section(key.str());
        const bool is_known_section =
            std::any_of(known.sections.begin(), known.sections.end(), [&](const std::string& s) {
                return s == section || s.rfind(section + ".", 0) == 0;
            });
        if (!is_known_section) {
            doc.fail(section, &value,
                     "unknown section '" + section + "'" + suggestion(section, known.sections));
        }
        if (is_table_array(section)) {
            check_table_array(doc, section, value, known.keys);
            continue;
        }
        const toml::table* table = value.as_table();
        if (table == nullptr) {
            doc.fail(section, &value, "'" + section + "' must be a section ([" + section + "])");
        }
        for (const auto& [name_key, entry] : *table) {
            const std::string full = section + "." + std::string(name_key.str());
            if (is_table_array(full)) {
                check_table_array(doc, full, entry, known.keys);
                continue;
            }
            if (!is_known(known.keys, full)) {
                doc.fail(full, &entry, "unknown key '" + full + "'" + suggestion(full, known.keys));
            }
        }
    }
}

/// 2 or 3: the length of domain.size.
int read_dimension(const CaseDocument& doc)
{
    const toml::node* size = doc.node("domain", "size");
    if (size == nullptr) {
        doc.fail("domain.size", doc.node("domain"), "missing required key 'domain.size'");
    }
    const toml::array* array = size->as_array();
    if (array == nullptr || (array->size() != 2 && array->size() != 3)) {
        doc.fail("domain.size", size, "must be an array of 2 (2D) or 3 (3D) side lengths");
    }
    return static_cast<int>(array->size());
}

/// A number of the case as a double: a float as it is, an integer exactly (none if it has no
/// exact double: beyond 2^53 most have none, and toml++ then gives no value at all).
std::optional<double> exact_number(const toml::node& node)
{
    if (!node.is_integer()) {
        return node.value<double>();
    }
    const std::int64_t integer = node.as_integer()->get();
    const auto real = static_cast<double>(integer);
    // 2^63 rounds INT64_MAX up and does not fit back; every other double here does.
    constexpr double two_to_63 = 9223372036854775808.0;
    if (real >= two_to_63 || static_cast<std::int64_t>(real) != integer) {
        return std::nullopt;
    }
    return real;
}

/// Checks one value against its spec; `dimension` is the vector length expected.
void check_value(const KeySpec& spec, const toml::node& node, int dimension,
                 const CaseDocument& doc, const std::string& key)
{
    const auto is_number = [](const toml::node& n) {
        return n.is_floating_point() || n.is_integer();
    };
    // A real key's number: an integer without an exact double is refused, not read as 0.
    const auto real_value = [&](const toml::node& number) {
        const std::optional<double> exact = exact_number(number);
        if (!exact) {
            const std::int64_t integer = number.as_integer()->get();
            doc.fail(key, &node,
                     fmt::format("the integer {} has no exact floating-point value (beyond 2^53 = "
                                 "9007199254740992 not every integer has one); write it as a "
                                 "float ({:.16e}) if that rounding is meant",
                                 integer, static_cast<double>(integer)));
        }
        return *exact;
    };
    const auto check_range = [&](double x) {
        if (!std::isfinite(x)) {
            doc.fail(key, &node, "must be a finite number");
        }
        const bool below = spec.is_min_open ? x <= spec.min : x < spec.min;
        const bool above = spec.is_max_open ? x >= spec.max : x > spec.max;
        if (below || above) {
            doc.fail(key, &node,
                     fmt::format("{:g}{} is out of range: must be {}", x,
                                 spec.unit.empty() ? "" : " " + spec.unit, range_text(spec)));
        }
    };
    const auto wrong_type = [&]() {
        doc.fail(
            key, &node,
            fmt::format(
                "expected {}, got {}", type_name(spec.type),
                node.is_array()
                    ? "an array"
                    : std::string(
                          toml::impl::node_type_friendly_names[static_cast<int>(node.type())])));
    };
    switch (spec.type) {
    case KeyType::real:
        if (!is_number(node)) {
            wrong_type();
        }
        check_range(real_value(node));
        return;
    case KeyType::integer:
        if (!node.is_integer()) {
            wrong_type();
        }
        check_range(static_cast<double>(node.as_integer()->get()));
        return;
    case KeyType::string:
        if (!node.is_string()) {
            wrong_type();
        }
        if (!spec.choices.empty()) {
            const std::string v = *node.value<std::string>();
            if (!is_known(spec.choices, v)) {
                doc.fail(key, &node,
                         "'" + v + "' is not valid: must be " + range_text(spec) +
                             suggestion(v, spec.choices));
            }
        }
        return;
    case KeyType::boolean:
        if (!node.is_boolean()) {
            wrong_type();
        }
        return;
    case KeyType::angular:
        if (dimension == 2) {
            if (!is_number(node)) {
                doc.fail(key, &node,
                         node.is_array() ? "a 2D case turns about z only: give one number"
                                         : "expected a number");
            }
            check_range(real_value(node));
            return;
        }
        if (is_number(node)) {
            doc.fail(key, &node, "a 3D case needs the three components [x, y, z]");
        }
        [[fallthrough]];
    case KeyType::boolean_vector:
        if (node.is_boolean()) {
            return;
        }
        [[fallthrough]];
    case KeyType::real_vector:
    case KeyType::integer_vector: {
        const toml::array* array = node.as_array();
        if (array == nullptr) {
            wrong_type();
        }
        if (static_cast<int>(array->size()) != dimension) {
            doc.fail(key, &node,
                     fmt::format("has {} entries; this {}D case needs {}", array->size(), dimension,
                                 dimension));
        }
        for (const toml::node& element : *array) {
            const bool ok = spec.type == KeyType::real_vector || spec.type == KeyType::angular
                                ? is_number(element)
                            : spec.type == KeyType::integer_vector ? element.is_integer()
                                                                   : element.is_boolean();
            if (!ok) {
                wrong_type();
            }
            if (spec.type != KeyType::boolean_vector) {
                check_range(spec.type == KeyType::integer_vector
                                ? static_cast<double>(element.as_integer()->get())
                                : real_value(element));
            }
        }
        return;
    }
    }
}

/// The default of `spec` as a TOML node for a `dimension`-D case.
toml::table default_node(const KeySpec& spec, int dimension)
{
    const std::string& text = *spec.value;
    if (spec.type == KeyType::angular && text == "zeros" && dimension == 2) {
        return toml::parse("v = 0.0");
    }
    if (text == "zeros" || (spec.type == KeyType::boolean_vector && text == "false")) {
        const std::vector<std::string> entries(static_cast<std::size_t>(dimension),
                                               text == "zeros" ? "0.0" : "false");
        return toml::parse(fmt::format("v = [{}]", fmt::join(entries, ", ")));
    }
    return toml::parse("v = " + text);
}

/// The keys of the sections: each checked, or its default filled in (2D cases have no z sides).
void check_section_keys(CaseDocument& doc, const std::vector<KeySpec>& schema, int dimension)
{
    for (const KeySpec& spec : schema) {
        if (is_table_array(spec.section)) {
            continue;
        }
        if ((spec.section == "walls" || spec.section == "boundaries") && spec.name[0] == 'z' &&
            dimension == 2) {
            if (const toml::node* n = doc.node(spec.section, spec.name)) {
                doc.fail(spec.full_name(), n,
                         spec.section == "walls" ? "a 2D case has no z walls"
                                                 : "a 2D case has no z sides");
            }
            continue;
        }
        const toml::node* n = doc.node(spec.section, spec.name);
        if (n == nullptr) {
            if (!spec.value) {
                doc.fail(spec.full_name(), doc.node(spec.section),
                         "missing required key '" + spec.full_name() + "'");
            }
            if (*spec.value == "none") {
                continue;
            }
            doc.insert_default(spec.section, spec.name, *default_node(spec, dimension).get("v"));
            continue;
        }
        check_value(spec, *n, dimension, doc, spec.full_name());
    }
}

/// The keys of each entry of the table arrays: each checked, or its default filled in.
void check_entry_keys(CaseDocument& doc, const std::vector<KeySpec>& schema, int dimension)
{
    for (const auto& t : case_table_arrays()) {
        toml::array* array = doc.table_array(t.name);
        if (array == nullptr) {
            continue;
        }
        for (toml::node& element : *array) {
            toml::table& entry = *element.as_table();
            for (const KeySpec& spec : schema) {
                if (spec.section != t.name) {
                    continue;
                }
                const toml::node* n = entry.get(spec.name);
                if (n == nullptr) {
                    if (!spec.value) {
                        doc.fail(spec.full_name(), &element,
                                 "missing required key '" + spec.name + "' in [[" + t.name + "]]");
                    }
                    if (*spec.value != "none") {
                        entry.insert(spec.name, *default_node(spec, dimension).get("v"));
                    }
                    continue;
                }
                check_value(spec, *n, dimension, doc, spec.full_name());
            }
        }
    }
}

/// A checked value, as its KeyType reads it.
KeyValue value_of(const KeySpec& spec, const toml::node& node, int dimension)
{
    const auto elements = [&](auto read) {
        std::vector<decltype(read(node))> out;
        for (const toml::node& e : *node.as_array()) {
            out.push_back(read(e));
        }
        return out;
    };
    const auto real = [](const toml::node& n) { return exact_number(n).value_or(0.0); };
    const auto integer = [](const toml::node& n) { return n.value<std::int64_t>().value_or(0); };
    const auto boolean = [](const toml::node& n) { return n.value<bool>().value_or(false); };
    switch (spec.type) {
    case KeyType::real:
        return real(node);
    case KeyType::integer:
        return integer(node);
    case KeyType::string:
        return node.value<std::string>().value_or("");
    case KeyType::boolean:
        return boolean(node);
    case KeyType::real_vector:
        return elements(real);
    case KeyType::integer_vector:
        return elements(integer);
    case KeyType::boolean_vector:
        if (node.is_boolean()) {
            return std::vector<bool>(static_cast<std::size_t>(dimension), boolean(node));
        }
        return elements(boolean);
    case KeyType::angular:
        if (node.is_array()) {
            return elements(real);
        }
        return std::vector<double>{real(node)};
    }
    return {};
}

/// Every key's value into its field, through its schema row.
CaseConfig convert(const CaseDocument& doc, const std::vector<KeySpec>& schema, int dimension)
{
    CaseConfig c;
    c.source_file = doc.file();
    c.domain.dimension = dimension;
    for (const KeySpec& spec : schema) {
        if (!spec.set) {
            continue; // [derived]: written by fddem, ignored on input
        }
        if (!is_table_array(spec.section)) {
            if (const toml::node* n = doc.node(spec.section, spec.name)) {
                spec.set(c, 0, value_of(spec, *n, dimension));
            }
            continue;
        }
        const toml::array* entries = doc.table_array(spec.section);
        for (std::size_t k = 0; entries != nullptr && k < entries->size(); ++k) {
            if (const toml::node* n = doc.entry(spec.section, k).get(spec.name)) {
                spec.set(c, k, value_of(spec, *n, dimension));
            }
        }
    }
    return c;
}

} // namespace

CaseConfig read_keys(CaseDocument& doc, const std::vector<KeySpec>& schema)
{
    check_names(doc, schema);
    const int dimension = read_dimension(doc);
    check_section_keys(doc, schema, dimension);
    check_entry_keys(doc, schema, dimension);
    return convert(doc, schema, dimension);
}

} // namespace fddem
