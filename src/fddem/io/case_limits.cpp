// SPDX-License-Identifier: MIT
#include "fddem/io/case_limits.hpp"

#include "fddem/io/case_document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fddem {
namespace {

/// A cell spans at least this many doubles at the box's far end: positions within a cell (the
/// markers, the delta kernel's weights) then keep six significant digits. With fewer, the cells
/// of a box far from the origin (domain.origin = [1e308, 0]) have zero floating-point width.
constexpr double min_doubles_per_cell = 1e6;

/// A fixed time step lands on time.end when time.end / time.dt is within this (relative) of a
/// whole number: the clock sums the steps, which costs a few roundings per step.
constexpr double whole_steps_tolerance = 1e-9;

/// Every cell of the box spans enough doubles at its coordinates.
void check_box(const CaseDocument& doc, const DomainConfig& box)
{
    const std::string key = doc.is_given("domain", "origin") ? "origin" : "size";
    for (std::size_t d = 0; d < static_cast<std::size_t>(box.dimension); ++d) {
        const double low = box.origin[d];
        const double high = low + box.size[d];
        const double h = box.size[d] / box.cells[d];
        const double far = std::max(std::abs(low), std::abs(high));
        const double spacing = std::nextafter(far, std::numeric_limits<double>::infinity()) - far;
        if (!std::isfinite(high) || !(h >= min_doubles_per_cell * spacing)) {
            doc.fail("domain." + key, doc.node("domain", key),
                     fmt::format("the box spans [{:g}, {:g}] on axis {} in cells {:.3g} wide, "
                                 "where doubles are {:.3g} apart: a cell must span {:g} of them "
                                 "to place points within it; move domain.origin nearer 0 or use "
                                 "larger cells",
                                 low, high, d, h, spacing, min_doubles_per_cell));
        }
    }
}

/// The steps to time.end: no more than time.max_steps (unless it is given as the stop), and a
/// whole number of them for a fixed time.dt (else the run would stop short of time.end or step
/// past it). An adaptive step (time.max_courant) lands on time.end by itself; time.dt is then
/// its largest, so the count is a least one.
void check_steps(const CaseDocument& doc, const TimeConfig& time)
{
    if (!time.end || time.is_steady) {
        return;
    }
    const double steps = *time.end / time.dt;
    if (steps < 1.0) {
        return; // a time step longer than the run: check_case says so
    }
    if (steps > static_cast<double>(time.max_steps) && !doc.is_given("time", "max_steps")) {
        doc.fail("time.dt", doc.node("time", "dt"),
                 fmt::format("time.end / time.dt = {:g} / {:g} = {:.3g} steps, more than "
                             "time.max_steps = {}; use a longer time.dt, or give time.max_steps "
                             "to run that many",
                             *time.end, time.dt, steps, time.max_steps));
    }
    const double whole = std::round(steps);
    if (!time.max_courant &&
        std::abs(steps - whole) > whole_steps_tolerance * std::max(1.0, steps)) {
        doc.fail("time.end", doc.node("time", "end"),
                 fmt::format("{:g} s is not a whole number of time steps of {:g} s ({:.6g} "
                             "steps): a fixed time.dt ends exactly at time.end; use time.end = "
                             "{:g} or {:g} s, or a time.dt that divides it",
                             *time.end, time.dt, steps, std::floor(steps) * time.dt,
                             std::ceil(steps) * time.dt));
    }
}

/// A fixed time.dt releases a body (bodies.release_time) at the start of a step: the release
/// must be a whole number of steps, as time.end must.
void check_releases(const CaseDocument& doc, const CaseConfig& c)
{
    const TimeConfig& time = c.time;
    if (time.max_courant || time.is_steady) {
        return; // the controlled step lands on the release
    }
    for (const BodyConfig& b : c.bodies) {
        if (!b.release_time) {
            continue;
        }
        const double steps = *b.release_time / time.dt;
        const double whole = std::round(steps);
        if (std::abs(steps - whole) > whole_steps_tolerance * std::max(1.0, steps)) {
            const toml::table& entry = doc.entry("bodies", b.entry);
            doc.fail("bodies.release_time", entry.get("release_time"),
                     fmt::format("{:g} s is not a whole number of time steps of {:g} s ({:.6g} "
                                 "steps): a fixed time.dt releases a body at the start of a "
                                 "step; use {:g} or {:g} s, or time.max_courant (whose step "
                                 "lands on the release)",
                                 *b.release_time, time.dt, steps, std::floor(steps) * time.dt,
                                 std::ceil(steps) * time.dt));
        }
    }
}

} // namespace

void check_limits(const CaseDocument& doc, const CaseConfig& c)
{
    check_box(doc, c.domain);
    check_steps(doc, c.time);
    check_releases(doc, c);
}

} // namespace fddem
