// SPDX-License-Identifier: MIT
#include "fddem/io/body_entries.hpp"

#include "fddem/bodies/ball.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/io/body_file.hpp"
#include "fddem/io/case_checks.hpp"
#include "fddem/io/case_document.hpp"
#include "fddem/io/random_packing.hpp"

#include <climits>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fddem {
namespace {

namespace fs = std::filesystem;

/// Trial centres per body of a random insertion before it gives up. Near the jamming fraction
/// the share of trials that succeed falls towards 0, so some bound is needed; a trial is a look
/// into 3^Dim hash buckets, so 10⁴ per body stop a jammed insertion of 10⁴ bodies within
/// seconds. (Not measured: how close to the jamming fraction this bound gets in large regions.)
constexpr long trials_per_body = 10000;

enum class EntryKind { single, file, random };

/// One entry as read: its kind, and for a random insertion the ids it takes.
struct Entry {
    EntryKind kind = EntryKind::single;
    std::vector<BodyConfig> bodies;
    long count = 0;   ///< random: bodies to insert
    int first_id = 0; ///< random: the id of the first
};

const toml::table& entry_table(const CaseDocument& doc, std::size_t k)
{
    return doc.entry("bodies", k);
}

/// Keys that only the kinds of entry in `kinds` take.
void refuse_keys(const CaseDocument& doc, std::size_t k, const std::vector<std::string>& names,
                 const std::string& why)
{
    const toml::table& t = entry_table(doc, k);
    for (const std::string& name : names) {
        if (const toml::node* n = t.get(name)) {
            doc.fail("bodies." + name, n, why);
        }
    }
}

void require_keys(const CaseDocument& doc, std::size_t k, const std::vector<std::string>& names,
                  const std::string& when)
{
    const toml::table& t = entry_table(doc, k);
    for (const std::string& name : names) {
        if (!t.contains(name)) {
            doc.fail("bodies." + name, &(*doc.table_array("bodies"))[k],
                     "missing required key '" + name + "' in [[bodies]]" + when);
        }
    }
}

const std::vector<std::string> random_keys{
    "count", "volume_fraction", "region_low", "region_high", "seed", "gap"};

EntryKind kind_of(const CaseDocument& doc, std::size_t k, const BodyGroupConfig& group)
{
    const bool is_random = group.count > 0 || group.volume_fraction.has_value();
    const toml::table& t = entry_table(doc, k);
    if (!group.file.empty() && is_random) {
        doc.fail("bodies.file", t.get("file"),
                 "an entry gives bodies from a file or at random (count, volume_fraction), not "
                 "both");
    }
    if (group.count > 0 && group.volume_fraction) {
        doc.fail("bodies.volume_fraction", t.get("volume_fraction"),
                 "give bodies.count or bodies.volume_fraction, not both");
    }
    if (!group.file.empty()) {
        refuse_keys(doc, k, {"position", "diameter", "density"},
                    "the file gives each body's position, diameter and density (its columns)");
        refuse_keys(doc, k, random_keys,
                    "only a random insertion (count, volume_fraction) "
                    "takes this key");
        return EntryKind::file;
    }
    if (is_random) {
        refuse_keys(doc, k, {"position"}, "a random insertion places its bodies itself");
        require_keys(doc, k, {"diameter"}, "");
        return EntryKind::random;
    }
    refuse_keys(doc, k, random_keys,
                "only a random insertion (count, volume_fraction) takes this key");
    require_keys(doc, k, {"diameter", "position"},
                 " (or give bodies.file, or bodies.count for random insertion)");
    return EntryKind::single;
}

/// The text of an entry's file, and its path as messages name it.
std::string read_text(const CaseDocument& doc, std::size_t k, const fs::path& path)
{
    const toml::node* key = entry_table(doc, k).get("file");
    std::error_code error;
    if (!fs::exists(path, error)) {
        doc.fail("bodies.file", key, "no such file: " + path.string());
    }
    if (fs::is_directory(path, error)) {
        doc.fail("bodies.file", key, path.string() + " is a directory, not a body file");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in || in.bad()) {
        doc.fail("bodies.file", key, "cannot read " + path.string());
    }
    return text.str();
}

/// An entry's file: relative to the case file unless absolute.
fs::path file_path(const CaseDocument& doc, const BodyGroupConfig& group)
{
    fs::path path(group.file);
    if (path.is_relative()) {
        path = fs::path(doc.file()).parent_path() / path;
    }
    return path.lexically_normal();
}

/// The bodies of a file entry.
std::vector<BodyConfig> file_bodies(const CaseDocument& doc, std::size_t k, const BodyConfig& entry,
                                    const BodyGroupConfig& group, int dimension)
{
    const fs::path path = file_path(doc, group);
    const std::vector<BodyRow> rows =
        parse_body_file(read_text(doc, k, path), path.string(), dimension);
    std::vector<BodyConfig> bodies;
    bodies.reserve(rows.size());
    for (const BodyRow& row : rows) {
        BodyConfig b = entry;
        b.id = row.id;
        b.position = row.position;
        b.diameter = row.diameter;
        b.density = row.density;
        if (row.velocity) {
            b.velocity = *row.velocity;
        }
        b.file = path.string();
        b.file_line = row.line;
        bodies.push_back(std::move(b));
    }
    return bodies;
}

/// The region of a random insertion: its corners in the box (on every axis: inserted bodies are
/// not wrapped across a periodic side), holding a body with its gap.
std::pair<std::vector<double>, std::vector<double>> region_of(const CaseDocument& doc,
                                                              std::size_t k, const CaseConfig& c,
                                                              const BodyConfig& entry,
                                                              const BodyGroupConfig& group)
{
    const DomainConfig& box = c.domain;
    std::vector<double> low = group.region_low.empty() ? box.origin : group.region_low;
    std::vector<double> high = group.region_high;
    if (high.empty()) {
        for (std::size_t d = 0; d < box.origin.size(); ++d) {
            high.push_back(box.origin[d] + box.size[d]);
        }
    }
    const toml::table& t = entry_table(doc, k);
    for (std::size_t d = 0; d < low.size(); ++d) {
        const double box_low = box.origin[d];
        const double box_high = box.origin[d] + box.size[d];
        if (low[d] < box_low || low[d] > box_high) {
            doc.fail("bodies.region_low", t.get("region_low"),
                     fmt::format("the region's lower corner is outside the box on axis {}: {:g} "
                                 "not in [{:g}, {:g}]",
                                 d, low[d], box_low, box_high));
        }
        if (high[d] < box_low || high[d] > box_high) {
            doc.fail("bodies.region_high", t.get("region_high"),
                     fmt::format("the region's upper corner is outside the box on axis {}: {:g} "
                                 "not in [{:g}, {:g}]",
                                 d, high[d], box_low, box_high));
        }
        if (high[d] - low[d] < entry.diameter + 2.0 * group.gap) {
            doc.fail(t.contains("region_high") ? "bodies.region_high" : "bodies.diameter",
                     t.contains("region_high") ? t.get("region_high") : t.get("diameter"),
                     fmt::format("the region is {:g} wide on axis {}, less than a body's "
                                 "diameter {:g} and twice the gap {:g}",
                                 high[d] - low[d], d, entry.diameter, group.gap));
        }
    }
    return {low, high};
}

template <int Dim>
Vec<Dim> vec_of(const std::vector<double>& values)
{
    Vec<Dim> v;
    for (int a = 0; a < Dim; ++a) {
        v[a] = values[static_cast<std::size_t>(a)];
    }
    return v;
}

/// How many bodies a random insertion asks for: its count, or its volume fraction of the region
/// rounded to whole bodies. Refused above the jamming fraction of random sequential addition, and
/// for bodies the grid cannot resolve.
template <int Dim>
long random_count(const CaseDocument& doc, std::size_t k, const DomainConfig& box,
                  const Vec<Dim>& low, const Vec<Dim>& high, const BodyConfig& entry,
                  const BodyGroupConfig& group)
{
    const double region = (high - low).prod();
    const double body = Ball<Dim>{entry.diameter}.volume();
    const toml::table& t = entry_table(doc, k);
    const std::string key = group.count > 0 ? "bodies.count" : "bodies.volume_fraction";
    const toml::node* node = group.count > 0 ? t.get("count") : t.get("volume_fraction");
    const double wanted =
        group.count > 0 ? static_cast<double>(group.count) * body / region : *group.volume_fraction;
    const char* what = Dim == 2 ? "disks" : "spheres";
    // Checked here as well as in check_bodies, before the insertion: bodies too small for the
    // grid would otherwise be placed by the million (memory and time) only to be refused.
    const double h = coarsest_cell(box);
    if (entry.diameter < min_cells_across * h) {
        doc.fail("bodies.diameter", t.get("diameter"),
                 fmt::format("the {} of a random insertion are {:.2g} cells across; at least {:g} "
                             "are needed for the marker layout (refine domain.cells)",
                             what, entry.diameter / h, min_cells_across));
    }
    if (wanted > jamming_fraction<Dim>()) {
        doc.fail(key, node,
                 fmt::format("a volume fraction of {:.3g} % of the region is beyond random "
                             "insertion: random sequential addition of {} jams near {:.3g} % "
                             "(of disks in 2D near 54.7 %, of spheres in 3D near 38.4 %), lower "
                             "in a small region; insert fewer and let them settle, or give the "
                             "positions (bodies.file)",
                             100.0 * wanted, what, 100.0 * jamming_fraction<Dim>()));
    }
    if (group.count > 0) {
        return group.count;
    }
    const auto count = static_cast<long>(std::llround(wanted * region / body));
    if (count < 1) {
        doc.fail(key, node,
                 fmt::format("{:g} of the region ({:g}) holds no body of volume {:g}", wanted,
                             region, body));
    }
    if (count > max_inserted_bodies) {
        doc.fail(key, node,
                 fmt::format("{:g} of the region is {} bodies; one random insertion places at "
                             "most {} (give the positions in bodies.file, or larger bodies)",
                             wanted, count, max_inserted_bodies));
    }
    return count;
}

/// The bodies of a random insertion, clear of `others`.
template <int Dim>
std::vector<BodyConfig> random_bodies(CaseDocument& doc, std::size_t k, const CaseConfig& c,
                                      const Entry& entry_kind,
                                      const std::vector<BodyConfig>& others)
{
    const BodyConfig& entry = c.bodies[k];
    const BodyGroupConfig& group = c.body_groups[k];
    const auto [low, high] = region_of(doc, k, c, entry, group);
    PackingRequest<Dim> request;
    request.low = vec_of<Dim>(low);
    request.high = vec_of<Dim>(high);
    request.diameter = entry.diameter;
    request.count = entry_kind.count;
    request.gap = group.gap;
    request.seed = static_cast<std::uint64_t>(group.seed);
    request.trials_per_ball = trials_per_body;
    for (const BodyConfig& other : others) {
        request.obstacles.push_back({vec_of<Dim>(other.position), 0.5 * other.diameter});
    }
    const Packing<Dim> packing = random_packing(request);
    const auto placed = static_cast<long>(packing.centres.size());
    if (placed < request.count) {
        const toml::table& t = entry_table(doc, k);
        const double body = Ball<Dim>{entry.diameter}.volume();
        const double region = (request.high - request.low).prod();
        doc.fail(group.count > 0 ? "bodies.count" : "bodies.volume_fraction",
                 group.count > 0 ? t.get("count") : t.get("volume_fraction"),
                 fmt::format(
                     "random insertion placed {} of {} bodies (volume fraction {:.3g} % "
                     "of {:.3g} % asked) in {} trials, then jammed: random sequential "
                     "addition jams near 55 % in 2D and 38 % in 3D, lower in a small "
                     "region, with a gap or beside other bodies; insert fewer, or in a "
                     "larger region",
                     placed, request.count, 100.0 * static_cast<double>(placed) * body / region,
                     100.0 * static_cast<double>(request.count) * body / region, packing.trials));
    }
    if (!entry_table(doc, k).contains("seed")) {
        (*doc.table_array("bodies"))[k].as_table()->insert_or_assign("seed", std::int64_t{0});
    }
    std::vector<BodyConfig> bodies;
    for (long i = 0; i < placed; ++i) {
        BodyConfig b = entry;
        b.id = entry_kind.first_id + static_cast<int>(i);
        const Vec<Dim>& centre = packing.centres[static_cast<std::size_t>(i)];
        b.position.assign(centre.data(), centre.data() + Dim);
        bodies.push_back(std::move(b));
    }
    return bodies;
}

/// Each id once in the case: a file's id taken by an earlier entry stops at its row.
void check_ids_unique(const std::vector<Entry>& entries)
{
    std::set<int> taken;
    for (const Entry& entry : entries) {
        for (const BodyConfig& b : entry.bodies) {
            if (!taken.insert(b.id).second) {
                throw InputError(b.file, b.file_line, "id",
                                 fmt::format("the id {} is taken by a body of an earlier "
                                             "[[bodies]] entry: ids are unique in the case",
                                             b.id));
            }
        }
        for (long i = 0; i < entry.count; ++i) {
            taken.insert(entry.first_id + static_cast<int>(i));
        }
    }
}

template <int Dim>
void make_bodies_in(CaseDocument& doc, CaseConfig& c)
{
    std::vector<Entry> entries(c.bodies.size());
    long next_id = 0;
    for (std::size_t k = 0; k < entries.size(); ++k) {
        BodyConfig entry = c.bodies[k];
        entry.entry = k;
        c.bodies[k].entry = k;
        const BodyGroupConfig& group = c.body_groups[k];
        Entry& e = entries[k];
        e.kind = kind_of(doc, k, group);
        if (e.kind == EntryKind::file) {
            e.bodies = file_bodies(doc, k, entry, group, Dim);
            for (const BodyConfig& b : e.bodies) {
                next_id = std::max(next_id, static_cast<long>(b.id) + 1);
            }
            continue;
        }
        if (e.kind == EntryKind::single) {
            if (next_id > INT_MAX) {
                doc.fail("bodies.position", &(*doc.table_array("bodies"))[k],
                         fmt::format("the id of this body would pass {}", INT_MAX));
            }
            entry.id = static_cast<int>(next_id++);
            e.bodies.push_back(entry);
            continue;
        }
        const auto [low, high] = region_of(doc, k, c, entry, group);
        e.count =
            random_count<Dim>(doc, k, c.domain, vec_of<Dim>(low), vec_of<Dim>(high), entry, group);
        if (next_id + e.count - 1 > INT_MAX) {
            doc.fail("bodies.count", &(*doc.table_array("bodies"))[k],
                     fmt::format("the ids of these bodies would pass {}", INT_MAX));
        }
        e.first_id = static_cast<int>(next_id);
        next_id += e.count;
    }
    check_ids_unique(entries);
    // Random insertions last, each clear of every body given so far.
    std::vector<BodyConfig> given;
    for (const Entry& e : entries) {
        given.insert(given.end(), e.bodies.begin(), e.bodies.end());
    }
    for (std::size_t k = 0; k < entries.size(); ++k) {
        if (entries[k].kind == EntryKind::random) {
            entries[k].bodies = random_bodies<Dim>(doc, k, c, entries[k], given);
            given.insert(given.end(), entries[k].bodies.begin(), entries[k].bodies.end());
        }
    }
    std::vector<BodyConfig> bodies;
    for (Entry& e : entries) {
        std::move(e.bodies.begin(), e.bodies.end(), std::back_inserter(bodies));
    }
    c.bodies = std::move(bodies);
}

} // namespace

void record_body_files(CaseDocument& doc, const CaseConfig& c)
{
    for (std::size_t k = 0; k < c.body_groups.size(); ++k) {
        if (!c.body_groups[k].file.empty()) {
            std::error_code error;
            const fs::path path = fs::absolute(file_path(doc, c.body_groups[k]), error);
            (*doc.table_array("bodies"))[k].as_table()->insert_or_assign(
                "file", path.lexically_normal().string());
        }
    }
}

void make_bodies(CaseDocument& doc, CaseConfig& c)
{
    c.body_groups.resize(c.bodies.size());
    if (c.domain.dimension == 2) {
        make_bodies_in<2>(doc, c);
    } else {
        make_bodies_in<3>(doc, c);
    }
}

} // namespace fddem
