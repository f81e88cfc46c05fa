// SPDX-License-Identifier: MIT
#include "fddem/io/case_document.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/case_schema.hpp"
#include "fddem/io/floating_point_hold.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fddem {
namespace {

const std::string override_source = "--set";

/// toml++ nests "output.lines" as table "output" with array "lines". (Doc is a toml::table,
/// const or not.)
template <class Doc>
auto* find_table_array(Doc& doc, const std::string& path)
{
    const auto dot = path.find('.');
    if (dot == std::string::npos) {
        return doc.template get_as<toml::array>(path);
    }
    auto* parent = doc.template get_as<toml::table>(path.substr(0, dot));
    return parent == nullptr ? nullptr : parent->template get_as<toml::array>(path.substr(dot + 1));
}

/// Splits "a.b.c" at its dots.
std::vector<std::string> split_at_dots(const std::string& path)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
        parts.push_back(path.substr(start, dot - start));
        start = dot + 1;
    }
    parts.push_back(path.substr(start));
    return parts;
}

[[noreturn]] void fail_override(const std::string& path, const std::string& message)
{
    throw InputError(override_source, 0, path, message);
}

[[noreturn]] void fail_override_form(const std::string& path, const std::string& text)
{
    fail_override(path, "expected section.key=value (e.g. time.dt=1e-3, bodies.1.density=2.5), "
                        "got '" +
                            text + "'");
}

/// Whether a --set value that is not TOML may be taken as a bare word (a string): not when it
/// starts as a number, an array, a table or a quoted string would (`1e400`, `[64,64`), whose
/// TOML error says more than "got string" would.
bool may_be_bare_word(const std::string& value)
{
    return !value.empty() && value.find_first_of("0123456789+-.[{\"'") != 0;
}

/// The value of --set as TOML; a bare word is a string.
toml::table parse_override_value(const std::string& path, const std::string& value)
{
    const FloatingPointHold hold; // 1e400 overflows while it is read
    try {
        return toml::parse("v = " + value);
    } catch (const toml::parse_error& e) {
        if (!may_be_bare_word(value)) {
            fail_override(path,
                          "cannot read the value '" + value + "': " + std::string(e.description()));
        }
        try {
            return toml::parse("v = \"" + value + "\"");
        } catch (const toml::parse_error& word_error) {
            fail_override(path, "cannot read the value '" + value +
                                    "': " + std::string(word_error.description()));
        }
    }
}

/// Entries [first, last) of a table array of `count` that an override reaches: entry N
/// (`digits`, counted from 1), or every entry.
std::pair<std::size_t, std::size_t> override_entries(const std::string& path,
                                                     const std::string& section,
                                                     const std::string* digits, std::size_t count)
{
    if (digits == nullptr) {
        if (count == 0) {
            fail_override(path, "the case has no [[" + section + "]] entry to set it in");
        }
        return {0, count};
    }
    const std::size_t n = digits->size() > 6 ? 0 : std::stoul(*digits);
    if (n < 1 || n > count) {
        fail_override(path, fmt::format("the case has {} [[{}]] entr{} (counted from 1), there "
                                        "is no {}",
                                        count, section, count == 1 ? "y" : "ies", *digits));
    }
    return {n - 1, n};
}

/// Where `text` holds its first control character (a newline, a tab, …), npos if nowhere.
std::size_t find_control_character(std::string_view text)
{
    const auto* at = std::find_if(text.begin(), text.end(), [](char ch) {
        const auto byte = static_cast<unsigned char>(ch);
        return byte < 0x20 || byte == 0x7f;
    });
    return at == text.end() ? std::string_view::npos : static_cast<std::size_t>(at - text.begin());
}

} // namespace

std::string escape_control_characters(std::string_view text)
{
    std::string escaped;
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '\\') {
            escaped += "\\\\";
        } else if (ch == '\n') {
            escaped += "\\n";
        } else if (ch == '\t') {
            escaped += "\\t";
        } else if (byte < 0x20 || byte == 0x7f) {
            escaped += fmt::format("\\x{:02x}", byte);
        } else {
            escaped += ch;
        }
    }
    return escaped;
}

bool is_table_array(const std::string& section)
{
    const auto arrays = case_table_arrays();
    return std::any_of(arrays.begin(), arrays.end(),
                       [&](const TableArraySpec& t) { return t.name == section; });
}

CaseDocument::CaseDocument(std::string_view text, std::string source_name,
                           const std::vector<std::string>& overrides)
    : file_(std::move(source_name))
{
    try {
        const FloatingPointHold hold; // 1e400 overflows while it is read
        doc_ = toml::parse(text, file_);
    } catch (const toml::parse_error& e) {
        throw InputError(file_, static_cast<int>(e.source().begin.line), "",
                         "TOML syntax error: " + std::string(e.description()));
    }
    for (const std::string& o : overrides) {
        apply_override(o);
    }
}

/// --set section.key=value; for an array of tables ([[bodies]], [[output.lines]]) also
/// name.key=value (every entry) and name.N.key=value (entry N, counted from 1).
void CaseDocument::apply_override(const std::string& text)
{
    if (const std::size_t at = find_control_character(text); at != std::string_view::npos) {
        // A newline would hide a second key=value in one --set ($'time.dt=0.004\ntime.end=5').
        fail_override(text.substr(0, std::min(at, text.find('='))),
                      fmt::format("'{}' holds a control character (byte {} of it, 0x{:02x}); give "
                                  "one section.key=value per --set",
                                  escape_control_characters(text), at + 1,
                                  static_cast<unsigned char>(text[at])));
    }
    const auto equals = text.find('=');
    const std::string path = equals == std::string::npos ? text : text.substr(0, equals);
    const std::vector<std::string> parts = split_at_dots(path);
    const bool is_malformed =
        equals == std::string::npos || parts.size() < 2 ||
        std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); });
    if (is_malformed) {
        fail_override_form(path, text);
    }
    const toml::table parsed = parse_override_value(path, text.substr(equals + 1));
    const toml::node& value = *parsed.get("v");
    const std::string& name = parts.back();
    const bool has_index =
        parts.size() >= 3 &&
        std::all_of(parts[parts.size() - 2].begin(), parts[parts.size() - 2].end(),
                    [](char c) { return c >= '0' && c <= '9'; });
    std::string section;
    for (std::size_t k = 0; k + (has_index ? 2 : 1) < parts.size(); ++k) {
        section += (k == 0 ? "" : ".") + parts[k];
    }
    if (is_table_array(section)) {
        toml::array* entries = table_array(section);
        const auto [first, last] =
            override_entries(path, section, has_index ? &parts[parts.size() - 2] : nullptr,
                             entries == nullptr ? 0 : entries->size());
        for (std::size_t k = first; k < last; ++k) {
            if (toml::table* entry = entries->get_as<toml::table>(k)) {
                entry->insert_or_assign(name, value);
            }
        }
        overridden_.insert(section + "." + name);
        return;
    }
    if (parts.size() != 2) {
        fail_override_form(path, text);
    }
    toml::table* target = doc_.get_as<toml::table>(section);
    if (target == nullptr) {
        if (doc_.contains(section)) {
            fail_override(path, "'" + section + "' is not a section");
        }
        doc_.insert(section, toml::table{});
        target = doc_.get_as<toml::table>(section);
    }
    target->insert_or_assign(name, value);
    overridden_.insert(path);
}

void CaseDocument::fail(const std::string& key, const toml::node* node,
                        const std::string& message) const
{
    // A key set by --set, or a section that only --set brought in (--set nosuch.key=1).
    const auto is_under_key = [&](const std::string& set) { return set.starts_with(key + "."); };
    const bool is_from_override =
        overridden_.count(key) != 0 ||
        (!key.empty() && std::any_of(overridden_.begin(), overridden_.end(), is_under_key) &&
         node != nullptr && node->source().path == nullptr);
    if (is_from_override) {
        throw InputError(override_source, 0, key, message);
    }
    const int line = node != nullptr ? static_cast<int>(node->source().begin.line) : 0;
    throw InputError(file_, line, key, message);
}

const toml::node* CaseDocument::node(const std::string& section) const
{
    return doc_.get(section);
}

const toml::node* CaseDocument::node(const std::string& section, const std::string& name) const
{
    const toml::table* t = doc_.get_as<toml::table>(section);
    return t == nullptr ? nullptr : t->get(name);
}

const toml::array* CaseDocument::table_array(const std::string& path) const
{
    return find_table_array(doc_, path);
}

toml::array* CaseDocument::table_array(const std::string& path)
{
    return find_table_array(doc_, path);
}

const toml::table& CaseDocument::entry(const std::string& path, std::size_t k) const
{
    return *(*table_array(path))[k].as_table();
}

void CaseDocument::insert_default(const std::string& section, const std::string& name,
                                  const toml::node& value)
{
    if (!doc_.contains(section)) {
        doc_.insert(section, toml::table{});
    }
    doc_.get_as<toml::table>(section)->insert(name, value);
    defaulted_.insert(section + "." + name);
}

bool CaseDocument::is_given(const std::string& section, const std::string& name) const
{
    return node(section, name) != nullptr && defaulted_.count(section + "." + name) == 0;
}

void CaseDocument::erase(const std::string& section, const std::string& name)
{
    if (toml::table* t = doc_.get_as<toml::table>(section)) {
        t->erase(name);
    }
}

std::string CaseDocument::as_run() const
{
    std::ostringstream text;
    text << "# The case as run by fddem: defaults filled in and --set overrides applied.\n"
         << "# Source: " << escape_control_characters(file_) << "\n\n"
         << doc_ << "\n";
    return text.str();
}

void check_derived(const CaseDocument& doc, const std::string& section, const std::string& name,
                   double value, const std::string& from)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        doc.fail(section, doc.node(section),
                 fmt::format("the derived {} is {:g}, not a finite positive number: {} are out "
                             "of any usable range",
                             name, value, from));
    }
}

} // namespace fddem
