// SPDX-License-Identifier: MIT
#include "fddem/io/case_reader.hpp"

#include "fddem/contact/contact_models.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/io/case_schema.hpp"
#include "fddem/io/nondimensional.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cfenv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace fddem {

std::size_t edit_distance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] =
                std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

namespace {

const std::string override_source = "--set";

/// The wall keys of [walls]: the low and the high side of each axis.
constexpr std::array<std::array<const char*, 2>, 3> wall_names = {
    {{"x_low", "x_high"}, {"y_low", "y_high"}, {"z_low", "z_high"}}};

/// Extreme (but valid) inputs can overflow what is derived from them; the reader checks each
/// derived value and names the inputs. Floating-point traps (which the tests enable, STYLE.md
/// §10) are held meanwhile, and the caller's environment is restored afterwards.
class FloatingPointHold {
public:
    FloatingPointHold() { std::feholdexcept(&saved_); }
    ~FloatingPointHold() { std::fesetenv(&saved_); }
    FloatingPointHold(const FloatingPointHold&) = delete;
    FloatingPointHold& operator=(const FloatingPointHold&) = delete;
    FloatingPointHold(FloatingPointHold&&) = delete;
    FloatingPointHold& operator=(FloatingPointHold&&) = delete;

private:
    std::fenv_t saved_{};
};

/// Where things came from, for messages: the file, or "--set" for overridden keys.
class Locator {
public:
    explicit Locator(std::string file) : file_(std::move(file)) {}
    void mark_overridden(const std::string& full_key) { overridden_.insert(full_key); }

    [[noreturn]] void fail(const std::string& key, const toml::node* node,
                           const std::string& message) const
    {
        if (overridden_.count(key) != 0) {
            throw InputError(override_source, 0, key, message);
        }
        const int line = node != nullptr ? static_cast<int>(node->source().begin.line) : 0;
        throw InputError(file_, line, key, message);
    }
    [[nodiscard]] const std::string& file() const noexcept { return file_; }

private:
    std::string file_;
    std::set<std::string> overridden_;
};

std::string suggestion(const std::string& wrong, const std::vector<std::string>& valid)
{
    std::string best;
    std::size_t best_distance = std::string::npos;
    for (const auto& v : valid) {
        const std::size_t d = edit_distance(wrong, v);
        if (d < best_distance) {
            best_distance = d;
            best = v;
        }
    }
    // Suggest only near misses: at most a third of the name changed.
    if (best_distance <= std::max<std::size_t>(2, wrong.size() / 3)) {
        return "; did you mean '" + best + "'?";
    }
    // Or a valid name with a word added ("time.end_time" for "time.end").
    for (const auto& v : valid) {
        if (wrong.starts_with(v + "_") || v.starts_with(wrong + "_")) {
            return "; did you mean '" + v + "'?";
        }
    }
    return "";
}

bool is_table_array(const std::string& section)
{
    const auto arrays = case_table_arrays();
    return std::any_of(arrays.begin(), arrays.end(),
                       [&](const TableArraySpec& t) { return t.name == section; });
}

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

/// --set section.key=value; for an array of tables ([[bodies]], [[output.lines]]) also
/// name.key=value (every entry) and name.N.key=value (entry N, counted from 1).
void apply_override(toml::table& doc, const std::string& text, Locator& where)
{
    const auto equals = text.find('=');
    const std::string path = equals == std::string::npos ? text : text.substr(0, equals);
    const std::vector<std::string> parts = split_at_dots(path);
    const bool is_malformed =
        equals == std::string::npos || parts.size() < 2 ||
        std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); });
    if (is_malformed) {
        throw InputError(override_source, 0, path,
                         "expected section.key=value (e.g. time.dt=1e-3, bodies.1.density=2.5), "
                         "got '" +
                             text + "'");
    }
    const std::string value = text.substr(equals + 1);
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
        try {
            parsed = toml::parse("v = \"" + value + "\""); // a bare word is a string
        } catch (const toml::parse_error& e) {
            throw InputError(override_source, 0, path,
                             "cannot read the value '" + value +
                                 "': " + std::string(e.description()));
        }
    }
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
        toml::array* entries = find_table_array(doc, section);
        const std::size_t count = entries == nullptr ? 0 : entries->size();
        std::size_t first = 0;
        std::size_t last = count;
        if (has_index) {
            const std::string& digits = parts[parts.size() - 2];
            const std::size_t n = digits.size() > 6 ? 0 : std::stoul(digits);
            if (n < 1 || n > count) {
                throw InputError(override_source, 0, path,
                                 fmt::format("the case has {} [[{}]] entr{} (counted from 1), "
                                             "there is no {}",
                                             count, section, count == 1 ? "y" : "ies", digits));
            }
            first = n - 1;
            last = n;
        } else if (count == 0) {
            throw InputError(override_source, 0, path,
                             "the case has no [[" + section + "]] entry to set it in");
        }
        for (std::size_t k = first; k < last; ++k) {
            toml::table* entry = entries->get_as<toml::table>(k);
            if (entry != nullptr) {
                entry->insert_or_assign(name, *parsed.get("v"));
            }
        }
        where.mark_overridden(section + "." + name);
        return;
    }
    if (parts.size() != 2) {
        throw InputError(override_source, 0, path,
                         "expected section.key=value (e.g. time.dt=1e-3, bodies.1.density=2.5), "
                         "got '" +
                             text + "'");
    }
    toml::table* target = doc.get_as<toml::table>(section);
    if (target == nullptr) {
        if (doc.contains(section)) {
            throw InputError(override_source, 0, path, "'" + section + "' is not a section");
        }
        doc.insert(section, toml::table{});
        target = doc.get_as<toml::table>(section);
    }
    target->insert_or_assign(name, *parsed.get("v"));
    where.mark_overridden(path);
}

/// Checks one value against its spec; `dimension` is the vector length expected.
void check_value(const KeySpec& spec, const toml::node& node, int dimension, const Locator& where,
                 const std::string& key)
{
    const auto is_number = [](const toml::node& n) {
        return n.is_floating_point() || n.is_integer();
    };
    const auto check_range = [&](double x) {
        if (!std::isfinite(x)) {
            where.fail(key, &node, "must be a finite number");
        }
        const bool below = spec.is_min_open ? x <= spec.min : x < spec.min;
        const bool above = spec.is_max_open ? x >= spec.max : x > spec.max;
        if (below || above) {
            where.fail(key, &node,
                       fmt::format("{:g}{} is out of range: must be {}", x,
                                   spec.unit.empty() ? "" : " " + spec.unit, range_text(spec)));
        }
    };
    const auto wrong_type = [&]() {
        where.fail(
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
        check_range(node.value<double>().value_or(0.0));
        return;
    case KeyType::integer:
        if (!node.is_integer()) {
            wrong_type();
        }
        check_range(static_cast<double>(node.value<std::int64_t>().value_or(0)));
        return;
    case KeyType::string:
        if (!node.is_string()) {
            wrong_type();
        }
        if (!spec.choices.empty()) {
            const std::string v = *node.value<std::string>();
            if (std::find(spec.choices.begin(), spec.choices.end(), v) == spec.choices.end()) {
                where.fail(key, &node,
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
            where.fail(key, &node,
                       fmt::format("has {} entries; this {}D case needs {}", array->size(),
                                   dimension, dimension));
        }
        for (const toml::node& element : *array) {
            const bool ok = spec.type == KeyType::real_vector      ? is_number(element)
                            : spec.type == KeyType::integer_vector ? element.is_integer()
                                                                   : element.is_boolean();
            if (!ok) {
                wrong_type();
            }
            if (spec.type != KeyType::boolean_vector) {
                check_range(element.value<double>().value_or(0.0));
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
    std::string value = text;
    if (text == "zeros" || (spec.type == KeyType::boolean_vector && text == "false")) {
        value = "[";
        for (int d = 0; d < dimension; ++d) {
            value += d == 0 ? "" : ", ";
            value += text == "zeros" ? "0.0" : "false";
        }
        value += "]";
    }
    return toml::parse("v = " + value);
}

std::vector<double> as_reals(const toml::node& node)
{
    std::vector<double> out;
    for (const toml::node& e : *node.as_array()) {
        out.push_back(e.value<double>().value_or(0.0));
    }
    return out;
}

std::vector<int> as_integers(const toml::node& node)
{
    std::vector<int> out;
    for (const toml::node& e : *node.as_array()) {
        out.push_back(static_cast<int>(e.value<std::int64_t>().value_or(0)));
    }
    return out;
}

std::vector<bool> as_booleans(const toml::node& node, int dimension)
{
    if (node.is_boolean()) {
        return std::vector<bool>(static_cast<std::size_t>(dimension), *node.value<bool>());
    }
    std::vector<bool> out;
    for (const toml::node& e : *node.as_array()) {
        out.push_back(e.value<bool>().value_or(false));
    }
    return out;
}

class CaseBuilder {
public:
    CaseBuilder(toml::table doc, Locator where) : doc_(std::move(doc)), where_(std::move(where)) {}

    CaseConfig build()
    {
        check_sections();
        dimension_ = read_dimension();
        fill_defaults_and_check();
        CaseConfig c = convert();
        check_contradictions(c);
        drop_absent_sides(c);
        {
            const FloatingPointHold hold;
            derive(c);
            check_bodies(c);
            derive_contact(c);
        }
        std::ostringstream as_run;
        as_run << "# The case as run by fddem: defaults filled in and --set overrides applied.\n"
               << "# Source: " << where_.file() << "\n\n"
               << doc_ << "\n";
        c.as_run = as_run.str();
        return c;
    }

private:
    const toml::node* node(const std::string& section, const std::string& name) const
    {
        const toml::table* t = doc_.get_as<toml::table>(section);
        return t == nullptr ? nullptr : t->get(name);
    }

    void check_sections()
    {
        std::vector<std::string> sections;
        std::vector<std::string> full_names;
        for (const KeySpec& spec : schema_) {
            if (std::find(sections.begin(), sections.end(), spec.section) == sections.end()) {
                sections.push_back(spec.section);
            }
            full_names.push_back(spec.full_name());
        }
        for (const auto& [key, value] : doc_) {
            const std::string section(key.str());
            const bool is_known =
                std::any_of(sections.begin(), sections.end(), [&](const std::string& s) {
                    return s == section || s.rfind(section + ".", 0) == 0;
                });
            if (!is_known) {
                where_.fail(section, &value,
                            "unknown section '" + section + "'" + suggestion(section, sections));
            }
            if (is_table_array(section)) {
                check_table_array(section, value, full_names);
                continue;
            }
            const toml::table* table = value.as_table();
            if (table == nullptr) {
                where_.fail(section, &value,
                            "'" + section + "' must be a section ([" + section + "])");
            }
            for (const auto& [name_key, entry] : *table) {
                const std::string full = section + "." + std::string(name_key.str());
                if (is_table_array(full)) {
                    check_table_array(full, entry, full_names);
                    continue;
                }
                if (std::find(full_names.begin(), full_names.end(), full) == full_names.end()) {
                    where_.fail(full, &entry,
                                "unknown key '" + full + "'" + suggestion(full, full_names));
                }
            }
        }
    }

    void check_table_array(const std::string& path, const toml::node& entry,
                           const std::vector<std::string>& full_names)
    {
        const toml::array* array = entry.as_array();
        if (array == nullptr || !array->is_array_of_tables()) {
            where_.fail(path, &entry, "must be an array of tables ([[" + path + "]])");
        }
        for (const toml::node& element : *array) {
            for (const auto& [k, v] : *element.as_table()) {
                const std::string full = path + "." + std::string(k.str());
                if (std::find(full_names.begin(), full_names.end(), full) == full_names.end()) {
                    where_.fail(full, &v,
                                "unknown key '" + full + "'" + suggestion(full, full_names));
                }
            }
        }
    }

    int read_dimension()
    {
        const toml::node* size = node("domain", "size");
        if (size == nullptr) {
            where_.fail("domain.size", doc_.get("domain"), "missing required key 'domain.size'");
        }
        const toml::array* array = size->as_array();
        if (array == nullptr || (array->size() != 2 && array->size() != 3)) {
            where_.fail("domain.size", size, "must be an array of 2 (2D) or 3 (3D) side lengths");
        }
        return static_cast<int>(array->size());
    }

    void fill_defaults_and_check()
    {
        for (const KeySpec& spec : schema_) {
            if (is_table_array(spec.section)) {
                continue;
            }
            if ((spec.section == "walls" || spec.section == "boundaries") && spec.name[0] == 'z' &&
                dimension_ == 2) {
                if (const toml::node* n = node(spec.section, spec.name)) {
                    where_.fail(spec.full_name(), n,
                                spec.section == "walls" ? "a 2D case has no z walls"
                                                        : "a 2D case has no z sides");
                }
                continue;
            }
            const toml::node* n = node(spec.section, spec.name);
            if (n == nullptr) {
                if (!spec.value) {
                    where_.fail(spec.full_name(), doc_.get(spec.section),
                                "missing required key '" + spec.full_name() + "'");
                }
                if (*spec.value == "none") {
                    continue;
                }
                if (!doc_.contains(spec.section)) {
                    doc_.insert(spec.section, toml::table{});
                }
                doc_.get_as<toml::table>(spec.section)
                    ->insert(spec.name, *default_node(spec, dimension_).get("v"));
                defaulted_.insert(spec.full_name());
                continue;
            }
            check_value(spec, *n, dimension_, where_, spec.full_name());
        }
        for (const auto& t : case_table_arrays()) {
            const toml::array* array = find_table_array(doc_, t.name);
            if (array == nullptr) {
                continue;
            }
            for (const toml::node& element : *array) {
                toml::table& entry = *const_cast<toml::table*>(element.as_table());
                for (const KeySpec& spec : schema_) {
                    if (spec.section != t.name) {
                        continue;
                    }
                    const toml::node* n = entry.get(spec.name);
                    if (n == nullptr) {
                        if (!spec.value) {
                            where_.fail(spec.full_name(), &element,
                                        "missing required key '" + spec.name + "' in [[" + t.name +
                                            "]]");
                        }
                        if (*spec.value != "none") {
                            entry.insert(spec.name, *default_node(spec, dimension_).get("v"));
                        }
                        continue;
                    }
                    check_value(spec, *n, dimension_, where_, spec.full_name());
                }
            }
        }
    }

    CaseConfig convert() const
    {
        const auto real = [&](const char* s, const char* k) {
            return node(s, k)->value<double>().value_or(0.0);
        };
        const auto integer = [&](const char* s, const char* k) {
            return node(s, k)->value<std::int64_t>().value_or(0);
        };
        const auto text = [&](const char* s, const char* k) {
            return node(s, k)->value<std::string>().value_or("");
        };
        CaseConfig c;
        c.source_file = where_.file();
        c.title = text("case", "title");
        c.dimension = dimension_;
        c.origin = as_reals(*node("domain", "origin"));
        c.size = as_reals(*node("domain", "size"));
        c.cells = as_integers(*node("domain", "cells"));
        c.periodic = as_booleans(*node("domain", "periodic"), dimension_);
        for (std::size_t d = 0; d < c.size.size(); ++d) {
            c.wall_velocity.push_back({as_reals(*node("walls", wall_names.at(d)[0])),
                                       as_reals(*node("walls", wall_names.at(d)[1]))});
        }
        for (std::size_t d = 0; d < c.size.size(); ++d) {
            c.boundary_kind.push_back(
                {text("boundaries", wall_names.at(d)[0]), text("boundaries", wall_names.at(d)[1])});
        }
        c.inflow_profile = text("inflow", "profile");
        if (node("inflow", "velocity") != nullptr) {
            c.inflow_velocity = real("inflow", "velocity");
        }
        c.density = real("fluid", "density");
        c.viscosity = node("fluid", "viscosity") != nullptr ? real("fluid", "viscosity") : 0.0;
        c.gravity = as_reals(*node("fluid", "gravity"));
        c.body_force = as_reals(*node("fluid", "body_force"));
        c.dt = real("time", "dt");
        if (node("time", "end") != nullptr) {
            c.end_time = real("time", "end");
        }
        if (node("time", "steady_tolerance") != nullptr) {
            c.steady_tolerance = real("time", "steady_tolerance");
        }
        if (node("time", "rest_speed") != nullptr) {
            c.rest_speed = real("time", "rest_speed");
        }
        c.rest_duration = real("time", "rest_duration");
        c.min_end = real("time", "min_end");
        c.max_steps = integer("time", "max_steps");
        if (node("time", "max_courant") != nullptr) {
            c.max_courant = real("time", "max_courant");
        }
        c.is_steady = node("time", "steady")->value<bool>().value_or(false);
        c.tolerance = real("simple", "tolerance");
        c.max_outer_iterations = static_cast<int>(integer("simple", "max_outer_iterations"));
        c.velocity_relaxation = real("simple", "velocity_relaxation");
        c.pressure_relaxation = real("simple", "pressure_relaxation");
        c.pressure_update = text("simple", "pressure_update");
        c.acceleration_depth = static_cast<int>(integer("simple", "acceleration_depth"));
        c.momentum_sweeps = static_cast<int>(integer("simple", "momentum_sweeps"));
        c.momentum_cycles = static_cast<int>(integer("simple", "momentum_cycles"));
        c.momentum_solver = text("simple", "momentum_solver");
        c.convection = text("simple", "convection");
        c.pressure_solver = text("simple", "pressure_solver");
        c.fft_planning = text("simple", "fft_planning");
        c.linear_tolerance = real("simple", "linear_tolerance");
        c.linear_max_iterations = static_cast<int>(integer("simple", "linear_max_iterations"));
        c.output_directory = text("output", "directory");
        c.field_interval = real("output", "field_interval");
        c.log_interval = integer("output", "log_interval");
        c.particle_interval = real("output", "particle_interval");
        c.checkpoint_step_interval = integer("checkpoint", "step_interval");
        c.checkpoint_time_interval = real("checkpoint", "time_interval");
        c.checkpoint_keep = static_cast<int>(integer("checkpoint", "keep"));
        c.kernel = text("coupling", "kernel");
        c.marker_spacing_ratio = real("coupling", "marker_spacing_ratio");
        if (node("nondimensional", "reynolds") != nullptr) {
            c.reynolds = real("nondimensional", "reynolds");
        }
        if (node("nondimensional", "density_ratio") != nullptr) {
            c.density_ratio = real("nondimensional", "density_ratio");
        }
        c.characteristic_velocity = real("nondimensional", "velocity");
        c.contact_model = text("contact", "model");
        c.contact_coupling = text("contact", "coupling");
        c.contact_beta = real("contact", "velocity_damping");
        c.contact_margin = real("contact", "margin");
        if (const toml::array* bodies = find_table_array(doc_, "bodies")) {
            for (const toml::node& element : *bodies) {
                const toml::table& t = *element.as_table();
                BodyConfig b;
                b.shape = t.get("shape")->value<std::string>().value_or("disk");
                b.diameter = t.get("diameter")->value<double>().value_or(0.0);
                b.density =
                    t.contains("density") ? t.get("density")->value<double>().value_or(0.0) : 0.0;
                b.position = as_reals(*t.get("position"));
                b.velocity = as_reals(*t.get("velocity"));
                b.omega = t.get("omega")->value<double>().value_or(0.0);
                b.motion = t.get("motion")->value<std::string>().value_or("free");
                b.n_rings = static_cast<int>(t.get("n_rings")->value<std::int64_t>().value_or(0));
                c.bodies.push_back(b);
            }
        }
        if (const toml::array* lines = find_table_array(doc_, "output.lines")) {
            for (const toml::node& element : *lines) {
                const toml::table& t = *element.as_table();
                LineSample line;
                line.name = t.get("name")->value<std::string>().value_or("");
                line.from = as_reals(*t.get("from"));
                line.to = as_reals(*t.get("to"));
                line.n_points =
                    static_cast<int>(t.get("points")->value<std::int64_t>().value_or(2));
                c.lines.push_back(line);
            }
        }
        return c;
    }

    /// [nondimensional] → viscosity, body densities, gravity (eqs. 19–22), recorded in
    /// [derived] of the case as run.
    void derive(CaseConfig& c)
    {
        const toml::node* re = node("nondimensional", "reynolds");
        const toml::node* ratio = node("nondimensional", "density_ratio");
        const bool has_viscosity = node("fluid", "viscosity") != nullptr;
        if (c.reynolds && has_viscosity) {
            where_.fail("fluid.viscosity", node("fluid", "viscosity"),
                        "give either fluid.viscosity or nondimensional.reynolds, not both");
        }
        if (!c.reynolds && !has_viscosity) {
            where_.fail("fluid.viscosity", doc_.get("fluid"),
                        "missing required key 'fluid.viscosity' (or give nondimensional.reynolds)");
        }
        if (c.density_ratio && !c.reynolds) {
            where_.fail("nondimensional.density_ratio", ratio,
                        "nondimensional.density_ratio needs nondimensional.reynolds (eq. 22 uses "
                        "both)");
        }
        const toml::array* bodies = find_table_array(doc_, "bodies");
        for (std::size_t k = 0; k < c.bodies.size(); ++k) {
            const toml::table& t = *(*bodies)[k].as_table();
            if (c.density_ratio && t.contains("density")) {
                where_.fail("bodies.density", t.get("density"),
                            "give either bodies.density or nondimensional.density_ratio, not both");
            }
            if (!c.density_ratio && !t.contains("density")) {
                where_.fail("bodies.density", &(*bodies)[k],
                            "missing required key 'density' in [[bodies]] (or give "
                            "nondimensional.density_ratio)");
            }
        }
        if (!c.reynolds) {
            return;
        }
        if (c.bodies.empty()) {
            where_.fail("nondimensional.reynolds", re,
                        "[nondimensional] needs a body: its diameter is the length scale");
        }
        const double diameter = c.bodies.front().diameter;
        const std::string nondimensional_inputs =
            "the values of [nondimensional] with fluid.density and the first body's diameter";
        if (!c.density_ratio) {
            c.viscosity = c.density * c.characteristic_velocity * diameter / *c.reynolds;
        } else {
            if (std::abs(*c.density_ratio - 1.0) < 1e-12) {
                where_.fail("nondimensional.density_ratio", ratio,
                            "a density ratio of 1 gives no settling velocity scale (eq. 21); give "
                            "fluid.viscosity, fluid.gravity and bodies.density instead");
            }
            const toml::node* gravity = node("fluid", "gravity");
            if (gravity != nullptr && defaulted_.count("fluid.gravity") == 0) {
                where_.fail("fluid.gravity", gravity,
                            "fluid.gravity is derived from [nondimensional] (eq. 21); do not give "
                            "both");
            }
            // The case as run records it in [derived] only: its zero default, left in [fluid],
            // would read back as a gravity given with [nondimensional].
            doc_.get_as<toml::table>("fluid")->erase("gravity");
            const DerivedScales scales =
                derive_scales(*c.reynolds, *c.density_ratio, c.size[0] / diameter, c.density,
                              diameter, c.characteristic_velocity);
            check_derived("nondimensional", "body density", scales.body_density,
                          nondimensional_inputs);
            check_derived("nondimensional", "gravity", scales.gravity, nondimensional_inputs);
            check_derived("nondimensional", "wall factor", scales.wall_factor,
                          nondimensional_inputs);
            c.viscosity = scales.viscosity;
            c.wall_factor = scales.wall_factor;
            for (BodyConfig& b : c.bodies) {
                b.density = scales.body_density;
            }
            c.gravity.assign(static_cast<std::size_t>(dimension_), 0.0);
            c.gravity[1] = -scales.gravity; // settling along −y
            toml::array g;
            for (const double x : c.gravity) {
                g.push_back(x);
            }
            derived_.insert_or_assign("gravity", g);
            derived_.insert_or_assign("body_density", scales.body_density);
            derived_.insert_or_assign("wall_factor", scales.wall_factor);
        }
        check_derived("nondimensional", "viscosity", c.viscosity, nondimensional_inputs);
        derived_.insert_or_assign("viscosity", c.viscosity);
        doc_.insert_or_assign("derived", derived_);
    }

    /// A value fddem derives (recorded in [derived]) must be a finite positive number; when
    /// extreme inputs overflow or underflow it, stop at `section` and say which inputs (`from`).
    void check_derived(const std::string& section, const std::string& name, double value,
                       const std::string& from) const
    {
        if (!(value > 0.0) || !std::isfinite(value)) {
            where_.fail(section, doc_.get(section),
                        fmt::format("the derived {} is {:g}, not a finite positive number: {} "
                                    "are out of any usable range",
                                    name, value, from));
        }
    }

    /// Bodies: the right shape for the dimension, inside the box, apart, resolved by the grid.
    void check_bodies(const CaseConfig& c) const
    {
        const toml::array* bodies = find_table_array(doc_, "bodies");
        double h = c.size[0] / c.cells[0];
        for (int d = 1; d < dimension_; ++d) {
            h = std::max(h, c.size[static_cast<std::size_t>(d)] /
                                c.cells[static_cast<std::size_t>(d)]);
        }
        for (std::size_t k = 0; k < c.bodies.size(); ++k) {
            const BodyConfig& b = c.bodies[k];
            const toml::table& t = *(*bodies)[k].as_table();
            if ((b.shape == "disk") != (dimension_ == 2)) {
                where_.fail("bodies.shape", t.get("shape"),
                            "a " + b.shape + " does not fit a " + std::to_string(dimension_) +
                                "D case (disk: 2D, sphere: 3D)");
            }
            if (b.diameter < 4.0 * h) {
                where_.fail("bodies.diameter", t.get("diameter"),
                            fmt::format("the body is {:.2g} cells across; at least 4 are needed "
                                        "for the marker layout (refine domain.cells)",
                                        b.diameter / h));
            }
            const double r = 0.5 * b.diameter;
            for (int d = 0; d < dimension_; ++d) {
                const auto dd = static_cast<std::size_t>(d);
                if (c.periodic[dd]) {
                    continue;
                }
                const double lo = c.origin[dd];
                const double hi = c.origin[dd] + c.size[dd];
                if (b.position[dd] - r < lo || b.position[dd] + r > hi) {
                    where_.fail("bodies.position", t.get("position"),
                                fmt::format("body {} reaches outside the box on axis {} (centre "
                                            "{:g}, radius {:g}, box [{:g}, {:g}])",
                                            k, d, b.position[dd], r, lo, hi));
                }
            }
            for (std::size_t j = 0; j < k; ++j) {
                const BodyConfig& o = c.bodies[j];
                double distance2 = 0.0;
                for (int d = 0; d < dimension_; ++d) {
                    const auto dd = static_cast<std::size_t>(d);
                    distance2 += std::pow(b.position[dd] - o.position[dd], 2);
                }
                if (std::sqrt(distance2) < 0.5 * (b.diameter + o.diameter)) {
                    where_.fail("bodies.position", t.get("position"),
                                fmt::format("body {} overlaps body {}", k, j));
                }
            }
        }
    }

    /// Keys that belong to the other contact model stop the case: they would be ignored. (None
    /// of them has a default filled in, so a case as run reads back.)
    void check_model_keys(const CaseConfig& c) const
    {
        const bool is_linear = c.contact_model == "linear";
        const std::vector<std::string> linear_only = {"stiffness", "damping", "duration",
                                                      "tangential_stiffness_ratio"};
        const std::vector<std::string> hertz_only = {"young_modulus", "poisson_ratio",
                                                     "impact_velocity"};
        const std::vector<std::string> hertz_surface = {"young_modulus", "poisson_ratio",
                                                        "restitution"};
        const std::string other = is_linear ? "hertz_mindlin" : "linear";
        const auto fail = [&](const std::string& key, const toml::node* n) {
            where_.fail(key, n,
                        "only contact.model = \"" + other + "\" takes this key (the case uses \"" +
                            c.contact_model + "\")");
        };
        for (const std::string& name : is_linear ? hertz_only : linear_only) {
            if (const toml::node* n = node("contact", name)) {
                fail("contact." + name, n);
            }
        }
        if (!is_linear) {
            return;
        }
        for (const std::string& name : hertz_surface) {
            if (const toml::node* n = node("walls", name)) {
                fail("walls." + name, n);
            }
            if (const toml::array* bodies = find_table_array(doc_, "bodies")) {
                for (const toml::node& element : *bodies) {
                    if (const toml::node* n = element.as_table()->get(name)) {
                        fail("bodies." + name, n);
                    }
                }
            }
        }
    }

    /// One surface: its own keys in `table` (a [[bodies]] entry or [walls]), else [contact]'s.
    Material surface(const toml::table* table) const
    {
        const auto value = [&](const std::string& name, double fallback) {
            const toml::node* own = table != nullptr ? table->get(name) : nullptr;
            const toml::node* common = node("contact", name);
            const toml::node* n = own != nullptr ? own : common;
            return n != nullptr ? n->value<double>().value_or(fallback) : fallback;
        };
        constexpr double typical_poisson_ratio = 0.3; // the schema's documented default
        Material m;
        m.young_modulus = value("young_modulus", 0.0);
        m.poisson_ratio = value("poisson_ratio", typical_poisson_ratio);
        m.friction = value("friction", 0.0);
        m.rolling_friction = value("rolling_friction", 0.0);
        m.restitution = value("restitution", 1.0);
        return m;
    }

    /// Hertz–Mindlin needs E for every body, and for the walls if there are any.
    void check_young_moduli(const CaseConfig& c, bool has_walls) const
    {
        const std::string message = "hertz_mindlin needs a Young's modulus: give "
                                    "contact.young_modulus (or young_modulus in every [[bodies]]"
                                    " and in [walls])";
        const toml::array* bodies = find_table_array(doc_, "bodies");
        for (std::size_t k = 0; k < c.bodies.size(); ++k) {
            if (!(c.bodies[k].material.young_modulus > 0.0)) {
                where_.fail("contact.young_modulus", &(*bodies)[k], message);
            }
        }
        if (has_walls && !(c.wall_material.young_modulus > 0.0)) {
            where_.fail("contact.young_modulus", doc_.get("walls"), message);
        }
    }

    /// The fastest impact to expect, when contact.impact_velocity is not given: falling the
    /// largest box side under gravity, plus twice the fastest initial body (head-on) and the
    /// fastest wall. t_c ∝ v^(−1/5), so a generous estimate costs few sub-steps.
    double impact_velocity(const CaseConfig& c) const
    {
        if (const toml::node* n = node("contact", "impact_velocity")) {
            return n->value<double>().value_or(0.0);
        }
        const auto norm = [](const std::vector<double>& v) {
            double sum = 0.0;
            for (const double x : v) {
                sum += x * x;
            }
            return std::sqrt(sum);
        };
        double body = 0.0;
        for (const BodyConfig& b : c.bodies) {
            body = std::max(body, norm(b.velocity));
        }
        double wall = 0.0;
        for (const auto& axis : c.wall_velocity) {
            wall = std::max({wall, norm(axis[0]), norm(axis[1])});
        }
        const double fall =
            std::sqrt(2.0 * norm(c.gravity) * *std::max_element(c.size.begin(), c.size.end()));
        const double v = fall + 2.0 * body + wall;
        if (!(v > 0.0)) {
            where_.fail("contact.impact_velocity", doc_.get("contact"),
                        "cannot estimate the fastest impact (no gravity, bodies and walls at "
                        "rest): give contact.impact_velocity");
        }
        return v;
    }

    /// [contact] → the model's coefficients and N_i (recorded in [derived]). Linear: k and c
    /// from stiffness and damping, or from the restitution and duration of a wall collision of
    /// the lightest free body. Hertz–Mindlin: the surfaces' E, ν and e, and the impact speed.
    void derive_contact(CaseConfig& c)
    {
        if (c.contact_model == "none") {
            return; // no collisions to resolve; [contact] keys are ignored
        }
        check_model_keys(c);
        const bool is_linear = c.contact_model == "linear";
        if (is_linear) {
            check_linear_keys();
        }
        const toml::array* bodies = find_table_array(doc_, "bodies");
        for (std::size_t k = 0; k < c.bodies.size(); ++k) {
            c.bodies[k].material = surface((*bodies)[k].as_table());
        }
        c.wall_material = surface(doc_.get_as<toml::table>("walls"));
        if (const toml::node* ratio = node("contact", "tangential_stiffness_ratio")) {
            c.contact_tangential_ratio = ratio->value<double>().value_or(0.0);
        }
        const bool has_walls =
            std::any_of(c.periodic.begin(), c.periodic.end(), [](bool p) { return !p; });

        std::vector<PairSide> sides;
        double lightest = std::numeric_limits<double>::infinity();
        PairSide lightest_side;
        for (const BodyConfig& b : c.bodies) {
            const double r = 0.5 * b.diameter;
            const double volume = dimension_ == 2 ? std::numbers::pi * r * r
                                                  : 4.0 / 3.0 * std::numbers::pi * r * r * r;
            const double mass = b.density * volume;
            const double inertia = (dimension_ == 2 ? 0.5 : 0.4) * mass * r * r;
            const bool is_free = b.motion == "free";
            sides.push_back(ball_side(mass, inertia, r, b.material, is_free));
            if (is_free && mass < lightest) {
                lightest = mass;
                lightest_side = sides.back();
            }
        }
        if (!std::isfinite(lightest)) {
            return; // no collisions to resolve
        }
        c.contact_reference_mass = lightest;
        // The wall collision of the lightest body (two of them if the box has no walls).
        const ContactPair reference = make_contact_pair(
            lightest_side, has_walls ? wall_side(c.wall_material) : lightest_side);
        double impact_speed = 0.0;
        if (is_linear) {
            derive_linear(c, lightest);
        } else {
            check_young_moduli(c, has_walls);
            impact_speed = impact_velocity(c);
            const HertzMindlin hertz;
            c.contact_impact_velocity = impact_speed;
            c.contact_duration = hertz.elastic_collision_time(reference, impact_speed);
            c.contact_restitution = hertz.restitution(reference);
            derived_.insert_or_assign("contact_impact_velocity", impact_speed);
            derived_.insert_or_assign("contact_damping_constant",
                                      HertzMindlin::damping_constant(reference.restitution));
        }
        const ContactModelInput input{
            {c.contact_stiffness, c.contact_damping, c.contact_tangential_ratio}, lightest};
        const std::optional<AnyContactModel> model = make_contact_model(c.contact_model, input);
        set_substeps(c, shortest_collision(*model, sides,
                                           has_walls ? std::optional<Material>(c.wall_material)
                                                     : std::nullopt,
                                           impact_speed));
        derived_.insert_or_assign("contact_duration", c.contact_duration);
        derived_.insert_or_assign("contact_restitution", c.contact_restitution);
        derived_.insert_or_assign("contact_substeps",
                                  static_cast<std::int64_t>(c.contact_substeps));
        doc_.insert_or_assign("derived", derived_);
    }

    /// The linear model takes k (and c), or e and t_c.
    void check_linear_keys() const
    {
        const toml::node* stiffness = node("contact", "stiffness");
        const toml::node* damping = node("contact", "damping");
        const toml::node* restitution = node("contact", "restitution");
        const toml::node* duration = node("contact", "duration");
        if (stiffness != nullptr && (restitution != nullptr || duration != nullptr)) {
            where_.fail(restitution != nullptr ? "contact.restitution" : "contact.duration",
                        restitution != nullptr ? restitution : duration,
                        "give either contact.stiffness (and damping) or contact.restitution and "
                        "contact.duration, not both");
        }
        if (damping != nullptr && stiffness == nullptr) {
            where_.fail("contact.damping", damping,
                        "contact.damping needs contact.stiffness (with restitution and duration "
                        "fddem derives it)");
        }
    }

    /// The linear model's k and c, from stiffness and damping or from restitution and duration.
    void derive_linear(CaseConfig& c, double lightest)
    {
        const toml::node* stiffness = node("contact", "stiffness");
        const toml::node* damping = node("contact", "damping");
        const toml::node* restitution = node("contact", "restitution");
        const toml::node* duration = node("contact", "duration");
        LinearSpringDashpot::Params law{};
        try {
            if (stiffness != nullptr) {
                law = {stiffness->value<double>().value_or(0.0),
                       damping != nullptr ? damping->value<double>().value_or(0.0) : 0.0};
            } else {
                const double e =
                    restitution != nullptr ? restitution->value<double>().value_or(1.0) : 1.0;
                const double t =
                    duration != nullptr ? duration->value<double>().value_or(c.dt) : c.dt;
                law = LinearSpringDashpot::from_restitution(e, t, lightest);
            }
            const std::string inputs = fmt::format(
                "the contact parameters and the lightest free body's mass ({:g} kg)", lightest);
            check_derived("contact", "contact stiffness", law.stiffness, inputs);
            if (!std::isfinite(law.damping)) {
                check_derived("contact", "contact damping", law.damping, inputs);
            }
            law.tangential_ratio = c.contact_tangential_ratio;
            const LinearSpringDashpot model(law, lightest);
            c.contact_stiffness = law.stiffness;
            c.contact_damping = law.damping;
            c.contact_duration = model.contact_time(lightest);
            c.contact_restitution = model.restitution(lightest);
        } catch (const InputError& e) {
            where_.fail(e.key(),
                        stiffness != nullptr ? (damping != nullptr ? damping : stiffness)
                                             : doc_.get("contact"),
                        e.what());
        }
        derived_.insert_or_assign("contact_stiffness", c.contact_stiffness);
        derived_.insert_or_assign("contact_damping", c.contact_damping);
    }

    /// N_i: `contact.substeps`, or enough for 80 sub-steps in the shortest collision `shortest`
    /// [s] (at most contact.substeps' upper limit); at least 10 are required.
    void set_substeps(CaseConfig& c, double shortest) const
    {
        const toml::node* substeps = node("contact", "substeps");
        constexpr double min_per_collision = 10.0;
        constexpr double auto_per_collision = 80.0;
        const double max_substeps = spec("contact", "substeps").max;
        const bool is_resolvable = shortest > 0.0 && std::isfinite(shortest) &&
                                   std::ceil(min_per_collision * c.dt / shortest) <= max_substeps;
        if (!is_resolvable || !(c.contact_duration > 0.0) || !std::isfinite(c.contact_duration)) {
            where_.fail(
                "contact", doc_.get("contact"),
                fmt::format("the contact parameters give a shortest collision of {:.3g} s and a "
                            "contact_duration of {:.3g} s; {:g} sub-steps per collision need a "
                            "finite duration of at least {:.3g} s (time.dt / {:.0f}, the most DEM "
                            "sub-steps allowed): change the contact parameters ({}) or time.dt",
                            shortest, c.contact_duration, min_per_collision,
                            min_per_collision * c.dt / max_substeps, max_substeps,
                            c.contact_model == "linear"
                                ? "contact.stiffness, or contact.restitution and duration"
                                : "young_modulus, contact.impact_velocity"));
        }
        const auto given_substeps = substeps->value<std::int64_t>().value_or(0);
        if (given_substeps == 0) {
            c.contact_substeps = static_cast<int>(
                std::clamp(std::ceil(auto_per_collision * c.dt / shortest), 1.0, max_substeps));
            return;
        }
        c.contact_substeps = static_cast<int>(given_substeps);
        const double per_collision = shortest / (c.dt / static_cast<double>(given_substeps));
        if (per_collision < min_per_collision) {
            where_.fail("contact.substeps", substeps,
                        fmt::format("{} DEM sub-steps per time step resolve a collision "
                                    "(duration {:.3g} s) with only {:.1f} sub-steps; at least "
                                    "{:g} are needed: use substeps >= {:.0f} (or 0 for automatic)",
                                    given_substeps, shortest, per_collision, min_per_collision,
                                    std::ceil(min_per_collision * c.dt / shortest)));
        }
    }

    /// The schema's entry for `section.name`.
    [[nodiscard]] const KeySpec& spec(const std::string& section, const std::string& name) const
    {
        return *std::find_if(schema_.begin(), schema_.end(), [&](const KeySpec& s) {
            return s.section == section && s.name == name;
        });
    }

    /// The case as run leaves out the defaults filled in for sides that do not exist or are
    /// not walls: both sides of a periodic axis ([walls] velocities and [boundaries] kinds), and
    /// the wall velocity of an inflow or outflow side. Read back, they would be given values.
    void drop_absent_sides(const CaseConfig& c)
    {
        toml::table& walls = *doc_.get_as<toml::table>("walls");
        toml::table* boundaries = doc_.get_as<toml::table>("boundaries");
        for (std::size_t d = 0; d < c.periodic.size(); ++d) {
            for (std::size_t side = 0; side < 2; ++side) {
                const char* name = wall_names.at(d).at(side);
                if (c.periodic[d] || c.boundary_kind[d][side] != "wall") {
                    walls.erase(name);
                }
                if (c.periodic[d] && boundaries != nullptr) {
                    boundaries->erase(name);
                }
            }
        }
    }

    /// An inflow needs a speed and an outflow (else the Poisson problem of the pressure
    /// correction has no solution: the fluid let in could not leave); inflow keys without an
    /// inflow would be ignored.
    void check_inflow_and_outflow(const CaseConfig& c) const
    {
        bool has_inflow = false;
        bool has_outflow = false;
        const toml::node* first_inflow = nullptr;
        for (int d = 0; d < dimension_; ++d) {
            if (c.periodic[static_cast<std::size_t>(d)]) {
                continue;
            }
            for (int side = 0; side < 2; ++side) {
                const std::string& kind =
                    c.boundary_kind[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)];
                if (kind == "inflow" && !has_inflow) {
                    has_inflow = true;
                    first_inflow = node("boundaries", wall_names.at(static_cast<std::size_t>(d))
                                                          .at(static_cast<std::size_t>(side)));
                }
                has_outflow = has_outflow || kind == "outflow";
            }
        }
        const toml::node* velocity = node("inflow", "velocity");
        if (has_inflow && velocity == nullptr) {
            where_.fail("inflow.velocity", first_inflow,
                        "a side is an inflow: give its speed, inflow.velocity");
        }
        if (!has_inflow && velocity != nullptr) {
            where_.fail("inflow.velocity", velocity,
                        "no side is an inflow (boundaries.*): inflow.velocity would be ignored");
        }
        if (has_inflow && !has_outflow) {
            where_.fail("boundaries", first_inflow,
                        "an inflow needs an outflow side (boundaries.* = \"outflow\"): the "
                        "fluid let in must leave");
        }
    }

    void check_contradictions(const CaseConfig& c) const
    {
        if (!c.end_time && !c.steady_tolerance && !c.rest_speed) {
            where_.fail("time.end", doc_.get("time"),
                        "give time.end, time.steady_tolerance or time.rest_speed: the run needs "
                        "a way to stop");
        }
        if (c.is_steady && !c.steady_tolerance) {
            where_.fail("time.steady", node("time", "steady"),
                        "a pseudo-time march needs time.steady_tolerance, the residual at "
                        "which it has arrived");
        }
        if (c.is_steady && std::any_of(c.bodies.begin(), c.bodies.end(),
                                       [](const auto& b) { return b.motion == "free"; })) {
            where_.fail("time.steady", node("time", "steady"),
                        "free bodies have no steady state to march to: use time.max_courant "
                        "for an adaptive, time-accurate step");
        }
        if (c.rest_speed && std::none_of(c.bodies.begin(), c.bodies.end(),
                                         [](const auto& b) { return b.motion == "free"; })) {
            where_.fail("time.rest_speed", node("time", "rest_speed"),
                        "the case has no free body to come to rest");
        }
        if (c.end_time && c.min_end > *c.end_time) {
            where_.fail("time.min_end", node("time", "min_end"),
                        fmt::format("the earliest end {:g} s is after the end time {:g} s",
                                    c.min_end, *c.end_time));
        }
        if (c.end_time && c.dt > *c.end_time) {
            where_.fail("time.dt", node("time", "dt"),
                        fmt::format("the time step {:g} s is longer than the end time {:g} s", c.dt,
                                    *c.end_time));
        }
        for (int d = 0; d < dimension_; ++d) {
            for (int side = 0; side < 2; ++side) {
                const char* wall =
                    wall_names.at(static_cast<std::size_t>(d)).at(static_cast<std::size_t>(side));
                const std::string key = std::string("walls.") + wall;
                const toml::node* n = node("walls", wall);
                const bool is_given = n != nullptr && defaulted_.count(key) == 0;
                if (c.periodic[static_cast<std::size_t>(d)] && is_given) {
                    where_.fail(key, n,
                                "axis " + std::to_string(d) +
                                    " is periodic (domain.periodic): it has no walls");
                }
                const std::string boundary_key = std::string("boundaries.") + wall;
                const toml::node* kind_node = node("boundaries", wall);
                const std::string& kind =
                    c.boundary_kind[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)];
                if (c.periodic[static_cast<std::size_t>(d)] &&
                    defaulted_.count(boundary_key) == 0 && kind_node != nullptr) {
                    where_.fail(boundary_key, kind_node,
                                "axis " + std::to_string(d) +
                                    " is periodic (domain.periodic): it has no sides");
                }
                if (kind != "wall" && is_given) {
                    where_.fail(key, n,
                                "the " + std::string(wall) + " side is an " + kind + " (" +
                                    boundary_key +
                                    "), not a wall: it takes no wall "
                                    "velocity");
                }
                const double normal =
                    c.wall_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)]
                                   [static_cast<std::size_t>(d)];
                if (normal != 0.0) {
                    where_.fail(key, n,
                                fmt::format("the wall-normal component is {:g}; a wall may only "
                                            "slide along itself (normal component 0)",
                                            normal));
                }
            }
        }
        check_inflow_and_outflow(c);
        std::set<std::string> names;
        const toml::array* lines = find_table_array(doc_, "output.lines");
        for (std::size_t k = 0; k < c.lines.size(); ++k) {
            const LineSample& line = c.lines[k];
            const toml::table& t = *(*lines)[k].as_table();
            const bool is_valid_name =
                !line.name.empty() && std::all_of(line.name.begin(), line.name.end(), [](char ch) {
                    return std::isalnum(static_cast<unsigned char>(ch)) != 0 || ch == '_' ||
                           ch == '-';
                });
            if (!is_valid_name) {
                where_.fail("output.lines.name", t.get("name"),
                            "'" + line.name +
                                "' is not a valid sample name (letters, digits, _, -)");
            }
            if (!names.insert(line.name).second) {
                where_.fail("output.lines.name", t.get("name"),
                            "the sample name '" + line.name + "' is used twice");
            }
            for (const auto* end : {"from", "to"}) {
                const std::vector<double>& p = std::string(end) == "from" ? line.from : line.to;
                for (int d = 0; d < dimension_; ++d) {
                    const auto k2 = static_cast<std::size_t>(d);
                    const double lo = c.origin[k2];
                    const double hi = c.origin[k2] + c.size[k2];
                    if (p[k2] < lo || p[k2] > hi) {
                        where_.fail(std::string("output.lines.") + end, t.get(end),
                                    fmt::format("point is outside the box on axis {}: {:g} not in "
                                                "[{:g}, {:g}]",
                                                d, p[k2], lo, hi));
                    }
                }
            }
        }
    }

    std::vector<KeySpec> schema_ = case_schema();
    toml::table doc_;
    toml::table derived_;
    std::set<std::string> defaulted_; ///< keys whose value is the schema's default
    Locator where_;
    int dimension_ = 2;
};

} // namespace

CaseConfig read_case_string(std::string_view text, const std::string& source_name,
                            const std::vector<std::string>& overrides)
{
    toml::table doc;
    try {
        doc = toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        throw InputError(source_name, static_cast<int>(e.source().begin.line), "",
                         "TOML syntax error: " + std::string(e.description()));
    }
    Locator where(source_name);
    for (const std::string& o : overrides) {
        apply_override(doc, o, where);
    }
    return CaseBuilder(std::move(doc), std::move(where)).build();
}

CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path, 0, "", "cannot open the case file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return read_case_string(text.str(), path, overrides);
}

} // namespace fddem
