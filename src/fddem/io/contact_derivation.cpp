// SPDX-License-Identifier: MIT
#include "fddem/io/contact_derivation.hpp"

#include "fddem/bodies/ball.hpp"
#include "fddem/core/errors.hpp"
#include "fddem/io/case_document.hpp"
#include "fddem/io/case_names.hpp"
#include "fddem/simulation/contact_model_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace fddem {
namespace {

// ---- linear spring–dashpot (the paper's eq. (18))

/// The linear model takes k (and c), or e and t_c.
void check_linear_keys(const CaseDocument& doc)
{
    const toml::node* stiffness = doc.node("contact", "stiffness");
    const toml::node* damping = doc.node("contact", "damping");
    const toml::node* restitution = doc.node("contact", "restitution");
    const toml::node* duration = doc.node("contact", "duration");
    if (stiffness != nullptr && (restitution != nullptr || duration != nullptr)) {
        doc.fail(restitution != nullptr ? "contact.restitution" : "contact.duration",
                 restitution != nullptr ? restitution : duration,
                 "give either contact.stiffness (and damping) or contact.restitution and "
                 "contact.duration, not both");
    }
    if (damping != nullptr && stiffness == nullptr) {
        doc.fail("contact.damping", damping,
                 "contact.damping needs contact.stiffness (with restitution and duration "
                 "fddem derives it)");
    }
}

/// k and c from stiffness and damping, or from the restitution and duration of the reference
/// collision (default: e = 1, t_c = Δt).
void derive_linear(CaseDocument& doc, CaseConfig& c, const ReferenceCollision& reference)
{
    const ContactConfig& given = c.contact;
    ContactDerived& derived = c.contact.derived;
    const double lightest = reference.mass;
    LinearSpringDashpot::Params law{};
    try {
        if (given.stiffness) {
            law = {*given.stiffness, given.damping.value_or(0.0)};
        } else {
            law =
                LinearSpringDashpot::from_restitution(given.surface.restitution.value_or(1.0),
                                                      given.duration.value_or(c.time.dt), lightest);
        }
        const std::string inputs = fmt::format(
            "the contact parameters and the lightest free body's mass ({:g} kg)", lightest);
        check_derived(doc, "contact", "contact stiffness", law.stiffness, inputs);
        if (!std::isfinite(law.damping)) {
            check_derived(doc, "contact", "contact damping", law.damping, inputs);
        }
        law.tangential_ratio = given.tangential_stiffness_ratio;
        const LinearSpringDashpot model(law, lightest);
        derived.stiffness = law.stiffness;
        derived.damping = law.damping;
        derived.duration = model.contact_time(lightest);
        derived.restitution = model.restitution(lightest);
    } catch (const InputError& e) {
        const toml::node* stiffness = doc.node("contact", "stiffness");
        const toml::node* damping = doc.node("contact", "damping");
        doc.fail(e.key(),
                 stiffness != nullptr ? (damping != nullptr ? damping : stiffness)
                                      : doc.node("contact"),
                 e.what());
    }
    doc.record_derived("contact_stiffness", derived.stiffness);
    doc.record_derived("contact_damping", derived.damping);
}

// ---- Hertz–Mindlin

/// Hertz–Mindlin needs E for every body, and for the walls if there are any.
void check_young_moduli(const CaseDocument& doc, const CaseConfig& c, bool has_walls)
{
    const std::string message = "hertz_mindlin needs a Young's modulus: give "
                                "contact.young_modulus (or young_modulus in every [[bodies]]"
                                " and in [walls])";
    for (const BodyConfig& b : c.bodies) {
        if (!(b.material.young_modulus > 0.0)) {
            doc.fail("contact.young_modulus", &(*doc.table_array("bodies"))[b.entry], message);
        }
    }
    if (has_walls && !(c.walls.material.young_modulus > 0.0)) {
        doc.fail("contact.young_modulus", doc.node("walls"), message);
    }
}

double norm(const std::vector<double>& v)
{
    double sum = 0.0;
    for (const double x : v) {
        sum += x * x;
    }
    return std::sqrt(sum);
}

/// The fastest impact to expect, when contact.impact_velocity is not given: falling the
/// largest box side under gravity, plus twice the fastest initial body (head-on) and the
/// fastest wall. t_c ∝ v^(−1/5), so a generous estimate costs few sub-steps.
double impact_velocity(const CaseDocument& doc, const CaseConfig& c)
{
    if (c.contact.impact_velocity) {
        return *c.contact.impact_velocity;
    }
    double body = 0.0;
    for (const BodyConfig& b : c.bodies) {
        body = std::max(body, norm(b.velocity));
    }
    double wall = 0.0;
    for (const auto& axis : c.walls.velocity) {
        wall = std::max({wall, norm(axis[0]), norm(axis[1])});
    }
    const std::vector<double>& size = c.domain.size;
    const double fall =
        std::sqrt(2.0 * norm(c.fluid.gravity) * *std::max_element(size.begin(), size.end()));
    const double v = fall + 2.0 * body + wall;
    if (!(v > 0.0)) {
        doc.fail("contact.impact_velocity", doc.node("contact"),
                 "cannot estimate the fastest impact (no gravity, bodies and walls at "
                 "rest): give contact.impact_velocity");
    }
    return v;
}

/// The surfaces' E, ν and e, and the impact speed: the duration of the reference collision at
/// that speed (undamped) and its restitution.
void derive_hertz_mindlin(CaseDocument& doc, CaseConfig& c, const ReferenceCollision& reference)
{
    check_young_moduli(doc, c, reference.has_walls);
    const double impact_speed = impact_velocity(doc, c);
    ContactDerived& derived = c.contact.derived;
    derived.impact_velocity = impact_speed;
    derived.duration = HertzMindlin::elastic_collision_time(reference.pair, impact_speed);
    derived.restitution = HertzMindlin::restitution(reference.pair);
    doc.record_derived("contact_impact_velocity", impact_speed);
    doc.record_derived("contact_damping_constant",
                       HertzMindlin::damping_constant(reference.pair.restitution));
}

// ---- adaptive collision model (Kempe & Fröhlich 2012)

/// T_c = N_c Δt and e_dry; the floor v_min of the impact speed (contact.minimum_impact_velocity,
/// default |g| T_c / 1000: see contact/adaptive_collision.hpp).
void derive_adaptive(CaseDocument& doc, CaseConfig& c, const ReferenceCollision& /*reference*/)
{
    const ContactConfig& given = c.contact;
    ContactDerived& derived = c.contact.derived;
    const double duration = given.collision_steps * c.time.dt;
    const double floor = given.minimum_impact_velocity.value_or(norm(c.fluid.gravity) * duration /
                                                                AdaptiveCollision::floor_ratio);
    if (!(floor > 0.0) || !std::isfinite(floor)) {
        doc.fail("contact.minimum_impact_velocity", doc.node("contact"),
                 fmt::format("the adaptive model needs a finite floor for slow impacts, whose "
                             "stiffness grows without bound as the impact speed falls: the "
                             "default |g| N_c time.dt / {:g} is {:g} m/s; give "
                             "contact.minimum_impact_velocity",
                             AdaptiveCollision::floor_ratio, floor));
    }
    derived.minimum_impact_velocity = floor;
    derived.duration = duration;
    derived.restitution = given.surface.restitution.value_or(1.0);
    doc.record_derived("contact_minimum_impact_velocity", floor);
}

// ---- common to all models

/// Keys that belong to another contact model stop the case: they would be ignored. (None of
/// them has a default filled in, so a case as run reads back.)
void check_model_keys(const CaseDocument& doc, const CaseConfig& c,
                      const std::vector<ContactModelKeys>& rows, const ContactModelKeys& own)
{
    const auto is_own = [&](const std::string& key) {
        return std::find(own.keys.begin(), own.keys.end(), key) != own.keys.end();
    };
    for (const ContactModelKeys& other : rows) {
        for (const std::string& key : other.keys) {
            if (other.model == own.model || is_own(key)) {
                continue;
            }
            const auto dot = key.find('.');
            const std::string section = key.substr(0, dot);
            const std::string name = key.substr(dot + 1);
            std::string takers; // every model that takes the key, "a" or "b"
            for (const ContactModelKeys& row : rows) {
                if (std::find(row.keys.begin(), row.keys.end(), key) != row.keys.end()) {
                    takers += (takers.empty() ? "\"" : "\" or \"") + name_of(row.model);
                }
            }
            const std::string message = "only contact.model = " + takers +
                                        "\" takes this key (the case uses \"" + name_of(own.model) +
                                        "\")";
            if (section != "bodies") {
                if (const toml::node* n = doc.node(section, name)) {
                    doc.fail(key, n, message);
                }
                continue;
            }
            for (const BodyConfig& b : c.bodies) {
                if (const toml::node* n = doc.entry("bodies", b.entry).get(name)) {
                    doc.fail(key, n, message);
                }
            }
        }
    }
}

/// One surface: its own keys, else [contact]'s, else the defaults (ν 0.3, e 1, no friction).
Material surface(const SurfaceKeys& own, const SurfaceKeys& common)
{
    const auto value = [](const std::optional<double>& mine, const std::optional<double>& all,
                          double fallback) { return mine ? *mine : all.value_or(fallback); };
    constexpr double typical_poisson_ratio = 0.3; // the schema's documented default
    Material m;
    m.young_modulus = value(own.young_modulus, common.young_modulus, 0.0);
    m.poisson_ratio = value(own.poisson_ratio, common.poisson_ratio, typical_poisson_ratio);
    m.friction = value(own.friction, common.friction, 0.0);
    m.rolling_friction = value(own.rolling_friction, common.rolling_friction, 0.0);
    m.restitution = value(own.restitution, common.restitution, 1.0);
    return m;
}

/// A body as one side of a contact, with its mass: its ball's (bodies/ball.hpp).
struct BodySide {
    double mass; ///< [kg] (2D: per unit depth)
    PairSide side;
};

template <int Dim>
BodySide body_side(const BodyConfig& b)
{
    const Ball<Dim> ball{b.diameter};
    const double mass = b.density * ball.volume();
    return {mass, ball_side(mass, b.density * ball.second_moment(), ball.radius(), b.material,
                            moves_freely(b))};
}

/// N_i: `contact.substeps`, or enough for 80 sub-steps in the shortest collision `shortest`
/// [s] (at most max_dem_substeps); at least 10 are required.
void set_substeps(const CaseDocument& doc, CaseConfig& c, const ContactModelKeys& row,
                  double shortest)
{
    constexpr double min_per_collision = 10.0;
    constexpr double auto_per_collision = 80.0;
    const double dt = c.time.dt;
    ContactDerived& derived = c.contact.derived;
    const bool is_resolvable = shortest > 0.0 && std::isfinite(shortest) &&
                               std::ceil(min_per_collision * dt / shortest) <= max_dem_substeps;
    if (!is_resolvable || !(derived.duration > 0.0) || !std::isfinite(derived.duration)) {
        doc.fail("contact", doc.node("contact"),
                 fmt::format("the contact parameters give a shortest collision of {:.3g} s and a "
                             "contact_duration of {:.3g} s; {:g} sub-steps per collision need a "
                             "finite duration of at least {:.3g} s (time.dt / {:.0f}, the most "
                             "DEM sub-steps allowed): change the contact parameters ({}) or "
                             "time.dt",
                             shortest, derived.duration, min_per_collision,
                             min_per_collision * dt / max_dem_substeps, max_dem_substeps,
                             row.duration_keys));
    }
    const int given = c.contact.substeps;
    if (given == 0) {
        derived.substeps = static_cast<int>(
            std::clamp(std::ceil(auto_per_collision * dt / shortest), 1.0, max_dem_substeps));
        return;
    }
    derived.substeps = given;
    const double per_collision = shortest / (dt / static_cast<double>(given));
    if (per_collision < min_per_collision) {
        doc.fail("contact.substeps", doc.node("contact", "substeps"),
                 fmt::format("{} DEM sub-steps per time step resolve a collision "
                             "(duration {:.3g} s) with only {:.1f} sub-steps; at least "
                             "{:g} are needed: use substeps >= {:.0f} (or 0 for automatic)",
                             given, shortest, per_collision, min_per_collision,
                             std::ceil(min_per_collision * dt / shortest)));
    }
}

} // namespace

std::vector<ContactModelKeys> contact_model_keys()
{
    return {
        {ContactModelKind::linear,
         {"contact.stiffness", "contact.damping", "contact.duration",
          "contact.tangential_stiffness_ratio"},
         "contact.stiffness, or contact.restitution and duration",
         check_linear_keys,
         derive_linear},
        {ContactModelKind::hertz_mindlin,
         {"contact.young_modulus", "contact.poisson_ratio", "contact.impact_velocity",
          "walls.young_modulus", "bodies.young_modulus", "walls.poisson_ratio",
          "bodies.poisson_ratio", "walls.restitution", "bodies.restitution"},
         "young_modulus, contact.impact_velocity",
         nullptr,
         derive_hertz_mindlin},
        {ContactModelKind::adaptive,
         {"contact.collision_steps", "contact.minimum_impact_velocity",
          "contact.tangential_stiffness_ratio"},
         "contact.collision_steps",
         nullptr,
         derive_adaptive},
    };
}

void derive_contact(CaseDocument& doc, CaseConfig& c)
{
    const std::vector<ContactModelKeys> rows = contact_model_keys();
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const ContactModelKeys& r) {
        return r.model == c.contact.model;
    });
    if (row == rows.end()) {
        return; // contact.model = "none": no collisions to resolve; [contact] keys are ignored
    }
    check_model_keys(doc, c, rows, *row);
    if (row->check != nullptr) {
        row->check(doc);
    }
    for (BodyConfig& b : c.bodies) {
        b.material = surface(b.surface, c.contact.surface);
    }
    c.walls.material = surface(c.walls.surface, c.contact.surface);
    ReferenceCollision reference;
    reference.has_walls =
        std::any_of(c.domain.periodic.begin(), c.domain.periodic.end(), [](bool p) { return !p; });

    std::vector<PairSide> sides;
    double lightest = std::numeric_limits<double>::infinity();
    PairSide lightest_side;
    for (const BodyConfig& b : c.bodies) {
        const BodySide body = c.domain.dimension == 2 ? body_side<2>(b) : body_side<3>(b);
        sides.push_back(body.side);
        if (moves_freely(b) && body.mass < lightest) {
            lightest = body.mass;
            lightest_side = body.side;
        }
    }
    if (!std::isfinite(lightest)) {
        return; // no collisions to resolve
    }
    ContactDerived& derived = c.contact.derived;
    derived.reference_mass = lightest;
    reference.mass = lightest;
    reference.pair = make_contact_pair(
        lightest_side, reference.has_walls ? wall_side(c.walls.material) : lightest_side);
    row->derive(doc, c, reference);
    const std::optional<AnyContactModel> model =
        make_contact_model(c.contact.model, contact_model_input(c));
    const std::optional<Material> walls =
        reference.has_walls ? std::optional<Material>(c.walls.material) : std::nullopt;
    set_substeps(doc, c, *row, shortest_collision(*model, sides, walls, derived.impact_velocity));
    doc.record_derived("contact_duration", derived.duration);
    doc.record_derived("contact_restitution", derived.restitution);
    doc.record_derived("contact_substeps", static_cast<std::int64_t>(derived.substeps));
}

} // namespace fddem
