// SPDX-License-Identifier: MIT
#include "fddem/contact/contact_models.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <tuple>

namespace fddem {
namespace {

std::optional<AnyContactModel> make_linear(const ContactModelInput& input)
{
    return LinearSpringDashpot(input.linear, input.reference_mass);
}

std::optional<AnyContactModel> make_hertz_mindlin(const ContactModelInput& /*input*/)
{
    return HertzMindlin{};
}

std::optional<AnyContactModel> make_adaptive(const ContactModelInput& input)
{
    return AdaptiveCollision(input.adaptive);
}

std::optional<AnyContactModel> make_none(const ContactModelInput& /*input*/)
{
    return std::nullopt;
}

constexpr std::array registry{
    ContactModelEntry{ContactModelKind::linear, "linear", "paper eq. (18): F = kα + cα̇",
                      make_linear},
    ContactModelEntry{ContactModelKind::hertz_mindlin, "hertz_mindlin",
                      "Hertz (Johnson 1985), Tsuji et al. (1992) dashpot with Antypov & Elliott "
                      "(2011) restitution, Mindlin (1949) tangential stiffness",
                      make_hertz_mindlin},
    ContactModelEntry{ContactModelKind::adaptive, "adaptive",
                      "Kempe & Fröhlich (2012): F = k α^{3/2} + d α̇ with k, d chosen per contact "
                      "for a duration of N_c time steps and the dry restitution",
                      make_adaptive},
    ContactModelEntry{ContactModelKind::none, "none", "no collisions", make_none},
};

auto side_order(const PairSide& s)
{
    const Material& m = s.material;
    return std::tuple(s.inverse_mass, s.inverse_inertia, s.curvature, m.young_modulus,
                      m.poisson_ratio, m.friction, m.rolling_friction, m.restitution);
}

} // namespace

std::span<const ContactModelEntry> contact_models()
{
    return registry;
}

std::vector<std::string> contact_model_names()
{
    std::vector<std::string> names;
    names.reserve(registry.size());
    for (const ContactModelEntry& entry : registry) {
        names.emplace_back(entry.name);
    }
    return names;
}

std::optional<AnyContactModel> make_contact_model(ContactModelKind kind,
                                                  const ContactModelInput& input)
{
    for (const ContactModelEntry& entry : registry) {
        if (entry.kind == kind) {
            return entry.make(input);
        }
    }
    throw InternalError("make_contact_model: a contact model kind without a registry row");
}

double shortest_collision(const AnyContactModel& model, std::span<const PairSide> bodies,
                          const std::optional<Material>& wall, double impact_speed)
{
    // Alike bodies give alike collisions: test each kind once (a case may hold thousands).
    std::vector<PairSide> kinds(bodies.begin(), bodies.end());
    const auto less = [](const PairSide& a, const PairSide& b) {
        return side_order(a) < side_order(b);
    };
    std::sort(kinds.begin(), kinds.end(), less);
    kinds.erase(std::unique(kinds.begin(), kinds.end(),
                            [&](const PairSide& a, const PairSide& b) {
                                return !less(a, b) && !less(b, a);
                            }),
                kinds.end());
    double shortest = std::numeric_limits<double>::infinity();
    const auto consider = [&](const PairSide& a, const PairSide& b) {
        if (a.inverse_mass + b.inverse_mass == 0.0) {
            return; // neither can move
        }
        const ContactPair pair = make_contact_pair(a, b);
        shortest = std::min(
            shortest,
            std::visit([&](const auto& m) { return m.elastic_collision_time(pair, impact_speed); },
                       model));
    };
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        for (std::size_t j = i; j < kinds.size(); ++j) {
            consider(kinds[i], kinds[j]);
        }
        if (wall) {
            consider(kinds[i], wall_side(*wall));
        }
    }
    return shortest;
}

} // namespace fddem
