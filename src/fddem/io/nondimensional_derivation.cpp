// SPDX-License-Identifier: MIT
#include "fddem/io/nondimensional_derivation.hpp"

#include "fddem/io/case_document.hpp"
#include "fddem/io/nondimensional.hpp"

#include <algorithm>
#include <cmath>

namespace fddem {
namespace {

/// What the derived values come from, for messages.
constexpr const char* inputs =
    "the values of [nondimensional] with fluid.density and the first body's diameter";

/// D: the first body's diameter is the length scale.
double length_scale(const CaseConfig& c)
{
    return c.bodies.front().diameter;
}

/// Re alone: μ = ρf U_c D / Re.
void derive_viscosity(CaseDocument& /*doc*/, CaseConfig& c)
{
    c.fluid.viscosity =
        c.fluid.density * c.nondimensional.velocity * length_scale(c) / *c.nondimensional.reynolds;
}

/// Re and ρr, the paper's settling cases: μ, every body's ρs, and g from eq. (21) with the
/// Happel & Brenner wall factor K of eq. (20) for the channel width (eq. (22) in the paper's
/// units).
void derive_settling(CaseDocument& doc, CaseConfig& c)
{
    const NondimensionalConfig& given = c.nondimensional;
    if (c.domain.dimension == 3) {
        // Eqs. (20)–(22) are the paper's 2D settling scales: a cylinder's wall factor in a
        // channel of width x and gravity along −y. A sphere's would need its own drag law and
        // wall correction; rather than a silently wrong g, a 3D case gives them itself.
        doc.fail("nondimensional.density_ratio", doc.node("nondimensional", "density_ratio"),
                 "the settling scales of eqs. (20)–(22) are those of a disk in a 2D channel; in "
                 "3D give fluid.gravity and bodies.density instead (nondimensional.reynolds "
                 "alone, which sets the viscosity, is fine)");
    }
    if (std::abs(*given.density_ratio - 1.0) < 1e-12) {
        doc.fail("nondimensional.density_ratio", doc.node("nondimensional", "density_ratio"),
                 "a density ratio of 1 gives no settling velocity scale (eq. 21); give "
                 "fluid.viscosity, fluid.gravity and bodies.density instead");
    }
    if (doc.is_given("fluid", "gravity")) {
        doc.fail("fluid.gravity", doc.node("fluid", "gravity"),
                 "fluid.gravity is derived from [nondimensional] (eq. 21); do not give both");
    }
    // The case as run records it in [derived] only: its zero default, left in [fluid], would
    // read back as a gravity given with [nondimensional].
    doc.erase("fluid", "gravity");
    const double diameter = length_scale(c);
    const DerivedScales scales =
        derive_scales(*given.reynolds, *given.density_ratio, c.domain.size[0] / diameter,
                      c.fluid.density, diameter, given.velocity);
    check_derived(doc, "nondimensional", "body density", scales.body_density, inputs);
    check_derived(doc, "nondimensional", "gravity", scales.gravity, inputs);
    check_derived(doc, "nondimensional", "wall factor", scales.wall_factor, inputs);
    c.fluid.viscosity = scales.viscosity;
    c.nondimensional.wall_factor = scales.wall_factor;
    for (BodyConfig& b : c.bodies) {
        b.density = scales.body_density;
    }
    c.fluid.gravity.assign(static_cast<std::size_t>(c.domain.dimension), 0.0);
    c.fluid.gravity[1] = -scales.gravity; // settling along −y
    toml::array g;
    for (const double x : c.fluid.gravity) {
        g.push_back(x);
    }
    doc.record_derived("gravity", std::move(g));
    doc.record_derived("body_density", scales.body_density);
    doc.record_derived("wall_factor", scales.wall_factor);
}

/// Each of viscosity and body density given once: as itself, or through [nondimensional].
void check_given_once(const CaseDocument& doc, const CaseConfig& c)
{
    const NondimensionalConfig& given = c.nondimensional;
    const bool has_viscosity = doc.node("fluid", "viscosity") != nullptr;
    if (given.reynolds && has_viscosity) {
        doc.fail("fluid.viscosity", doc.node("fluid", "viscosity"),
                 "give either fluid.viscosity or nondimensional.reynolds, not both");
    }
    if (!given.reynolds && !has_viscosity) {
        doc.fail("fluid.viscosity", doc.node("fluid"),
                 "missing required key 'fluid.viscosity' (or give nondimensional.reynolds)");
    }
    if (given.density_ratio && !given.reynolds) {
        doc.fail("nondimensional.density_ratio", doc.node("nondimensional", "density_ratio"),
                 "nondimensional.density_ratio needs nondimensional.reynolds (eq. 22 uses both)");
    }
    for (const BodyConfig& b : c.bodies) {
        const toml::table& t = doc.entry("bodies", b.entry);
        if (b.file_line > 0) {
            if (given.density_ratio) {
                doc.fail("bodies.file", t.get("file"),
                         "a file gives its bodies' densities: nondimensional.density_ratio "
                         "would replace them");
            }
            continue;
        }
        if (given.density_ratio && t.contains("density")) {
            doc.fail("bodies.density", t.get("density"),
                     "give either bodies.density or nondimensional.density_ratio, not both");
        }
        if (!given.density_ratio && !t.contains("density")) {
            doc.fail("bodies.density", &(*doc.table_array("bodies"))[b.entry],
                     "missing required key 'density' in [[bodies]] (or give "
                     "nondimensional.density_ratio)");
        }
    }
}

/// The set whose keys are exactly those of the sets' keys that the case gives; none for a
/// dimensional case.
const NondimensionalSet* given_set(const std::vector<NondimensionalSet>& sets,
                                   const CaseDocument& doc)
{
    std::vector<std::string_view> given;
    for (const NondimensionalSet& set : sets) {
        for (const std::string_view key : set.keys) {
            const bool is_new = std::find(given.begin(), given.end(), key) == given.end();
            if (is_new && doc.node("nondimensional", std::string(key)) != nullptr) {
                given.push_back(key);
            }
        }
    }
    for (const NondimensionalSet& set : sets) {
        const bool is_exact =
            set.keys.size() == given.size() &&
            std::all_of(set.keys.begin(), set.keys.end(), [&](std::string_view key) {
                return std::find(given.begin(), given.end(), key) != given.end();
            });
        if (is_exact) {
            return &set;
        }
    }
    return nullptr;
}

} // namespace

std::vector<NondimensionalSet> nondimensional_sets()
{
    return {
        {"Re: the viscosity", {"reynolds"}, derive_viscosity},
        {"Re and ρr: a settling case (eqs. 19–22)", {"reynolds", "density_ratio"}, derive_settling},
    };
}

void derive_nondimensional(CaseDocument& doc, CaseConfig& c)
{
    check_given_once(doc, c);
    const std::vector<NondimensionalSet> sets = nondimensional_sets();
    const NondimensionalSet* set = given_set(sets, doc);
    if (set == nullptr) {
        return; // a dimensional case
    }
    if (c.bodies.empty()) {
        doc.fail("nondimensional.reynolds", doc.node("nondimensional", "reynolds"),
                 "[nondimensional] needs a body: its diameter is the length scale");
    }
    set->derive(doc, c);
    check_derived(doc, "nondimensional", "viscosity", c.fluid.viscosity, inputs);
    doc.record_derived("viscosity", c.fluid.viscosity);
}

} // namespace fddem
