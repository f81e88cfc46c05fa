// SPDX-License-Identifier: MIT
#include "fddem/io/case_checks.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/body_file.hpp"
#include "fddem/io/case_document.hpp"
#include "fddem/io/case_names.hpp"
#include "fddem/io/case_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <set>

namespace fddem {
namespace {

bool has_free_body(const CaseConfig& c)
{
    return std::any_of(c.bodies.begin(), c.bodies.end(),
                       [](const BodyConfig& b) { return moves_freely(b); });
}

/// A way to stop, a pseudo-time march that can arrive, an end after the earliest end.
void check_time(const CaseDocument& doc, const CaseConfig& c)
{
    const TimeConfig& time = c.time;
    if (!time.end && !time.steady_tolerance && !time.rest_speed) {
        doc.fail("time.end", doc.node("time"),
                 "give time.end, time.steady_tolerance or time.rest_speed: the run needs "
                 "a way to stop");
    }
    if (time.is_steady && !time.steady_tolerance) {
        doc.fail("time.steady", doc.node("time", "steady"),
                 "a pseudo-time march needs time.steady_tolerance, the residual at "
                 "which it has arrived");
    }
    if (time.is_steady && has_free_body(c)) {
        doc.fail("time.steady", doc.node("time", "steady"),
                 "free bodies have no steady state to march to: use time.max_courant "
                 "for an adaptive, time-accurate step");
    }
    if (time.rest_speed && !has_free_body(c)) {
        doc.fail("time.rest_speed", doc.node("time", "rest_speed"),
                 "the case has no free body to come to rest");
    }
    if (time.end && time.min_end > *time.end) {
        doc.fail("time.min_end", doc.node("time", "min_end"),
                 fmt::format("the earliest end {:g} s is after the end time {:g} s", time.min_end,
                             *time.end));
    }
    if (time.end && time.dt > *time.end) {
        doc.fail("time.dt", doc.node("time", "dt"),
                 fmt::format("the time step {:g} s is longer than the end time {:g} s", time.dt,
                             *time.end));
    }
}

/// Walls and side kinds only where the box has sides; a wall only slides along itself.
void check_sides(const CaseDocument& doc, const CaseConfig& c)
{
    for (std::size_t d = 0; d < static_cast<std::size_t>(c.domain.dimension); ++d) {
        const bool is_periodic = c.domain.periodic[d];
        for (std::size_t side = 0; side < 2; ++side) {
            const std::string wall = side_names.at(d).at(side);
            const std::string key = "walls." + wall;
            const toml::node* n = doc.node("walls", wall);
            const bool is_given = doc.is_given("walls", wall);
            if (is_periodic && is_given) {
                doc.fail(key, n,
                         "axis " + std::to_string(d) +
                             " is periodic (domain.periodic): it has no walls");
            }
            const std::string boundary_key = "boundaries." + wall;
            const BoundaryKind kind = c.boundaries[d][side];
            if (is_periodic && doc.is_given("boundaries", wall)) {
                doc.fail(boundary_key, doc.node("boundaries", wall),
                         "axis " + std::to_string(d) +
                             " is periodic (domain.periodic): it has no sides");
            }
            if (kind != BoundaryKind::wall && is_given) {
                doc.fail(key, n,
                         "the " + wall + " side is an " + name_of(kind) + " (" + boundary_key +
                             "), not a wall: it takes no wall velocity");
            }
            const double normal = c.walls.velocity[d][side][d];
            if (normal != 0.0) {
                doc.fail(key, n,
                         fmt::format("the wall-normal component is {:g}; a wall may only "
                                     "slide along itself (normal component 0)",
                                     normal));
            }
        }
    }
}

/// An inflow needs a speed and an outflow (else the Poisson problem of the pressure
/// correction has no solution: the fluid let in could not leave); inflow keys without an
/// inflow would be ignored.
void check_inflow_and_outflow(const CaseDocument& doc, const CaseConfig& c)
{
    bool has_inflow = false;
    bool has_outflow = false;
    const toml::node* first_inflow = nullptr;
    for (std::size_t d = 0; d < static_cast<std::size_t>(c.domain.dimension); ++d) {
        if (c.domain.periodic[d]) {
            continue;
        }
        for (std::size_t side = 0; side < 2; ++side) {
            const BoundaryKind kind = c.boundaries[d][side];
            if (kind == BoundaryKind::inflow && !has_inflow) {
                has_inflow = true;
                first_inflow = doc.node("boundaries", side_names.at(d).at(side));
            }
            has_outflow = has_outflow || kind == BoundaryKind::outflow;
        }
    }
    const toml::node* velocity = doc.node("inflow", "velocity");
    if (has_inflow && velocity == nullptr) {
        doc.fail("inflow.velocity", first_inflow,
                 "a side is an inflow: give its speed, inflow.velocity");
    }
    if (!has_inflow && velocity != nullptr) {
        doc.fail("inflow.velocity", velocity,
                 "no side is an inflow (boundaries.*): inflow.velocity would be ignored");
    }
    if (has_inflow && !has_outflow) {
        doc.fail("boundaries", first_inflow,
                 "an inflow needs an outflow side (boundaries.* = \"outflow\"): the "
                 "fluid let in must leave");
    }
}

bool is_valid_sample_name(const std::string& name)
{
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) != 0 || ch == '_' || ch == '-';
    });
}

/// Line samples: valid, distinct names; both ends in the box.
void check_lines(const CaseDocument& doc, const CaseConfig& c)
{
    std::set<std::string> names;
    for (std::size_t k = 0; k < c.output.lines.size(); ++k) {
        const LineSample& line = c.output.lines[k];
        const toml::table& t = doc.entry("output.lines", k);
        if (!is_valid_sample_name(line.name)) {
            doc.fail("output.lines.name", t.get("name"),
                     "'" + line.name + "' is not a valid sample name (letters, digits, _, -)");
        }
        if (!names.insert(line.name).second) {
            doc.fail("output.lines.name", t.get("name"),
                     "the sample name '" + line.name + "' is used twice");
        }
        for (const std::string end : {"from", "to"}) {
            const std::vector<double>& p = end == "from" ? line.from : line.to;
            for (std::size_t d = 0; d < static_cast<std::size_t>(c.domain.dimension); ++d) {
                const double lo = c.domain.origin[d];
                const double hi = c.domain.origin[d] + c.domain.size[d];
                if (p[d] < lo || p[d] > hi) {
                    doc.fail("output.lines." + end, t.get(end),
                             fmt::format("point is outside the box on axis {}: {:g} not in "
                                         "[{:g}, {:g}]",
                                         d, p[d], lo, hi));
                }
            }
        }
    }
}

/// "body 2" (its [[bodies]] entry) or, for a body of a file or a random insertion, "body id 7".
std::string body_name(const CaseDocument& doc, const BodyConfig& b)
{
    const bool is_one_of_many = !doc.entry("bodies", b.entry).contains("position");
    return is_one_of_many ? fmt::format("body id {}", b.id) : fmt::format("body {}", b.entry + 1);
}

/// Stops at a body: at the line of its row and the column `column` of its file, else at the
/// key `name` of its [[bodies]] entry (or at the entry, for a key it does not give).
[[noreturn]] void fail_body(const CaseDocument& doc, const BodyConfig& b, const std::string& name,
                            const std::string& column, const std::string& message)
{
    if (b.file_line > 0) {
        throw InputError(b.file, b.file_line, column, message);
    }
    const toml::table& t = doc.entry("bodies", b.entry);
    const toml::node* n = t.get(name);
    doc.fail("bodies." + name, n != nullptr ? n : &(*doc.table_array("bodies"))[b.entry], message);
}

/// No two bodies overlap: sweep along x, in order of the left ends, comparing each body with
/// those whose left ends lie within its reach (O(N log N) for a bed of equal bodies, not N²).
/// The later body of a pair (in the case's order) is the one named first.
void check_apart(const CaseDocument& doc, const std::vector<BodyConfig>& bodies,
                 std::size_t dimension)
{
    std::vector<std::size_t> order(bodies.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto left = [&](std::size_t k) {
        return bodies[k].position[0] - 0.5 * bodies[k].diameter;
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return left(a) < left(b) || (left(a) == left(b) && a < b);
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
        const BodyConfig& a = bodies[order[i]];
        const double right = a.position[0] + 0.5 * a.diameter;
        for (std::size_t j = i + 1; j < order.size() && left(order[j]) < right; ++j) {
            const BodyConfig& b = bodies[order[j]];
            double distance2 = 0.0;
            for (std::size_t d = 0; d < dimension; ++d) {
                distance2 += std::pow(b.position[d] - a.position[d], 2);
            }
            if (std::sqrt(distance2) < 0.5 * (a.diameter + b.diameter)) {
                const bool is_b_later = order[j] > order[i];
                const BodyConfig& later = is_b_later ? b : a;
                const BodyConfig& earlier = is_b_later ? a : b;
                std::string columns = "x, y";
                if (dimension == 3) {
                    columns += ", z";
                }
                fail_body(doc, later, "position", columns,
                          fmt::format(
                              "{} overlaps {}{}", body_name(doc, later), body_name(doc, earlier),
                              earlier.file_line > 0 && earlier.file != later.file
                                  ? fmt::format(" ({}:{})", earlier.file, earlier.file_line)
                              : earlier.file_line > 0 ? fmt::format(" (line {})", earlier.file_line)
                                                      : ""));
            }
        }
    }
}

/// simple.algorithm = "projection": not relaxed, and no free body lighter than the fluid.
void check_step_algorithm(const CaseDocument& doc, const CaseConfig& c)
{
    if (c.simple.algorithm != StepAlgorithm::projection) {
        return;
    }
    const auto fail = [&](const std::string& why) {
        doc.fail("simple.algorithm", doc.node("simple", "algorithm"), why);
    };
    for (const BodyConfig& b : c.bodies) {
        // One pass of eqs. (13)–(16) a step: the fluid inside a body comes from the pass before,
        // so a light body's added mass feeds back explicitly. Measured (a disk rising in a
        // 2 × 4 box, D/8, Δt 0.001, to t = 0.1): ρs/ρf 0.7 and 0.9 follow SIMPLE within 1.5 %,
        // 0.5 blows up at step 59, 0.3 and 0.1 within 10 steps (docs/method.md §1).
        if (moves_freely(b) && b.density < c.fluid.density) {
            fail(fmt::format("\"projection\" makes one pass of eqs. (13)–(16) a step, which "
                             "blew up for bodies at half the fluid's density and below, so it "
                             "takes none lighter than the fluid, and {} has ρs/ρf = {:g}: use "
                             "\"simple\"",
                             body_name(doc, b), b.density / c.fluid.density));
        }
    }
    if (!c.bodies.empty() && !c.coupling.is_forcing_normalised) {
        // One forcing pass a step is a Richardson step of eq. (15) that no outer iteration damps:
        // modes of I·D above 2 grow from step to step. Measured: the impulsive cylinder at D/40
        // (retracted markers) blew up at t = 1.48 without the normalised correction and ran
        // with it (docs/method.md §1).
        fail("with bodies, \"projection\" needs coupling.normalised_forcing = true: its single "
             "forcing pass a step otherwise blew up (the impulsive cylinder at D/40, t = 1.48)");
    }
    if (!c.bodies.empty() && c.time.scheme == TimeScheme::bdf2) {
        // Measured: Schäfer & Turek 2D-2 (a fixed cylinder, D/20, Δt 0.0025) blew up at t = 2.5–2.6
        // with BDF2 and either marker layout, and ran with Euler (docs/method.md §1).
        fail("with bodies, \"projection\" blew up under time.scheme = \"bdf2\" (the shedding "
             "cylinder of Schäfer & Turek at t = 2.6): use time.scheme = \"euler\", or "
             "\"simple\"");
    }
    if (c.simple.velocity_relaxation != 1.0 || c.simple.pressure_relaxation != 1.0) {
        fail("\"projection\" takes the whole predictor and the whole pressure correction: set "
             "simple.velocity_relaxation and simple.pressure_relaxation to 1 (or leave them out)");
    }
}

} // namespace

void check_case(const CaseDocument& doc, const CaseConfig& c)
{
    check_time(doc, c);
    check_sides(doc, c);
    check_inflow_and_outflow(doc, c);
    check_lines(doc, c);
}

double coarsest_cell(const DomainConfig& box)
{
    double h = box.size[0] / box.cells[0];
    for (std::size_t d = 1; d < static_cast<std::size_t>(box.dimension); ++d) {
        h = std::max(h, box.size[d] / box.cells[d]);
    }
    return h;
}

void check_bodies(const CaseDocument& doc, const CaseConfig& c)
{
    check_step_algorithm(doc, c); // after [nondimensional] has derived the densities
    const DomainConfig& box = c.domain;
    const auto dimension = static_cast<std::size_t>(box.dimension);
    const double h = coarsest_cell(box);
    for (const BodyConfig& b : c.bodies) {
        if ((b.shape == BodyShape::disk) != (dimension == 2)) {
            fail_body(doc, b, "shape", "shape",
                      "a " + name_of(b.shape) + " does not fit a " + std::to_string(dimension) +
                          "D case (disk: 2D, sphere: 3D)");
        }
        if (b.diameter < min_cells_across * h) {
            fail_body(doc, b, "diameter", "diameter",
                      fmt::format("{} is {:.2g} cells across; at least {:g} are needed for "
                                  "the marker layout (refine domain.cells)",
                                  body_name(doc, b), b.diameter / h, min_cells_across));
        }
        if (b.release_time && b.motion != Motion::prescribed) {
            fail_body(doc, b, "release_time", "release_time",
                      fmt::format("{} is {}: bodies.release_time lets go of a prescribed body "
                                  "(set motion = \"prescribed\", or remove the release time)",
                                  body_name(doc, b), name_of(b.motion)));
        }
        const double r = 0.5 * b.diameter;
        for (std::size_t d = 0; d < dimension; ++d) {
            if (box.periodic[d]) {
                continue;
            }
            const double lo = box.origin[d];
            const double hi = box.origin[d] + box.size[d];
            if (b.position[d] - r < lo || b.position[d] + r > hi) {
                fail_body(doc, b, "position", position_column(d),
                          fmt::format("{} reaches outside the box on axis {} (centre "
                                      "{:g}, radius {:g}, box [{:g}, {:g}])",
                                      body_name(doc, b), d, b.position[d], r, lo, hi));
            }
        }
    }
    check_apart(doc, c.bodies, dimension);
    if (c.coupling.markers == MarkerLayout::surface && has_free_body(c) &&
        c.coupling.inner_fluid != InnerFluidSource::volume) {
        doc.fail("coupling.markers", doc.node("coupling", "markers"),
                 "the surface layout has no markers inside a body, so eqs. (13)–(14) cannot "
                 "take a free body's inner fluid from them: set coupling.inner_fluid = "
                 "\"volume\", or use \"paper\" or \"retracted\"");
    }
    if (c.coupling.wall_marker_reach.has_value() && !c.coupling.is_wall_marker_off &&
        !c.coupling.is_body_marker_off) {
        doc.fail("coupling.markers_off_reach", doc.node("coupling", "markers_off_reach"),
                 "coupling.markers_off_at_walls and coupling.markers_off_between_bodies are "
                 "off, so the reach would be ignored: set one of them to true, or remove the "
                 "reach");
    }
    if (c.coupling.inner_fluid == InnerFluidSource::volume &&
        (c.coupling.is_wall_marker_off || c.coupling.is_body_marker_off)) {
        const char* option = c.coupling.is_wall_marker_off ? "coupling.markers_off_at_walls"
                                                           : "coupling.markers_off_between_bodies";
        doc.fail("coupling.inner_fluid", doc.node("coupling", "inner_fluid"),
                 fmt::format("\"volume\" integrates the fluid inside a body as it is, so the "
                             "markers {} silences would not have their fluid taken as the body's: "
                             "use one option or the other",
                             option));
    }
    if (c.coupling.inner_fluid == InnerFluidSource::volume && has_free_body(c) &&
        c.time.scheme == TimeScheme::bdf2) {
        doc.fail("coupling.inner_fluid", doc.node("coupling", "inner_fluid"),
                 "\"volume\" takes the inner fluid at the step's start, which BDF2's "
                 "extrapolated level-n motion does not have: use time.scheme = \"euler\" with "
                 "it, or coupling.inner_fluid = \"markers\"");
    }
}

} // namespace fddem
