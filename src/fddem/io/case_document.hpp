// SPDX-License-Identifier: MIT
#pragma once
/// The TOML side of reading a case: the document as parsed, with `--set` overrides applied,
/// defaults filled in (io/case_keys.cpp) and derived values recorded, which prints as the case as
/// run; and where each key came from (file and line, or --set), for messages. Only io/ sees it.

#include <toml++/toml.h>

#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fddem {

class CaseDocument {
public:
    /// Parses `text` (a syntax error is an InputError at its line) and applies `overrides`
    /// (`section.key=value`; see read_case).
    CaseDocument(std::string_view text, std::string source_name,
                 const std::vector<std::string>& overrides);

    [[nodiscard]] const std::string& file() const noexcept { return file_; }

    /// Stops the reading: InputError naming the file and the line of `node` (0 if none), or
    /// "--set" for a key that an override set.
    [[noreturn]] void fail(const std::string& key, const toml::node* node,
                           const std::string& message) const;

    [[nodiscard]] const toml::table& root() const noexcept { return doc_; }

    /// A section ([fluid]), or nullptr.
    [[nodiscard]] const toml::node* node(const std::string& section) const;
    /// A key of a section, given or filled in as a default; nullptr if neither.
    [[nodiscard]] const toml::node* node(const std::string& section, const std::string& name) const;
    /// The entries of a table array ("bodies", "output.lines"), or nullptr.
    [[nodiscard]] const toml::array* table_array(const std::string& path) const;
    [[nodiscard]] toml::array* table_array(const std::string& path);
    /// Entry `k` of a table array (which must have it).
    [[nodiscard]] const toml::table& entry(const std::string& path, std::size_t k) const;

    /// Fills in the schema's default `value` of a key the case does not give.
    void insert_default(const std::string& section, const std::string& name,
                        const toml::node& value);
    /// The key is in the case as given (or set by --set), not filled in as a default.
    [[nodiscard]] bool is_given(const std::string& section, const std::string& name) const;

    /// Records a value fddem derived (a number, or a toml::array) in [derived] of the case as run.
    template <class Value>
    void record_derived(const std::string& name, Value&& value)
    {
        derived_.insert_or_assign(name, std::forward<Value>(value));
        doc_.insert_or_assign("derived", derived_);
    }
    /// Leaves a key out of the case as run.
    void erase(const std::string& section, const std::string& name);
    /// The case as run: the document with its defaults, overrides and derived values.
    [[nodiscard]] std::string as_run() const;

private:
    void apply_override(const std::string& text);

    std::string file_;
    toml::table doc_;
    toml::table derived_;
    std::set<std::string> overridden_; ///< full keys set by --set
    std::set<std::string> defaulted_;  ///< full keys holding the schema's default
};

/// A value fddem derives (recorded in [derived]) must be a finite positive number; when extreme
/// inputs overflow or underflow it, stops at `section` and says which inputs (`from`).
void check_derived(const CaseDocument& doc, const std::string& section, const std::string& name,
                   double value, const std::string& from);

/// `text` with its control characters written as escapes (\n, \t, \x01) and `\` as `\\`: a file
/// name on one line of a comment.
[[nodiscard]] std::string escape_control_characters(std::string_view text);

/// Whether `section` is an array of tables ([[bodies]], [[output.lines]]).
[[nodiscard]] bool is_table_array(const std::string& section);

} // namespace fddem
