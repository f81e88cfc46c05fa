// SPDX-License-Identifier: MIT
// The contact-model registry (contact/contact_models.cpp) and the pair rules of
// contact/material.hpp.

#include "fddem/contact/contact_models.hpp"
#include "fddem/core/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fddem {
namespace {

TEST(ContactModels, RegistryNamesTheCaseFileChoices)
{
    EXPECT_EQ(contact_model_names(),
              (std::vector<std::string>{"linear", "hertz_mindlin", "adaptive", "none"}));
    for (const ContactModelEntry& entry : contact_models()) {
        EXPECT_FALSE(entry.citation.empty()) << entry.name;
    }
    const ContactModelInput input{{1e6, 10.0}, 0.1};
    EXPECT_FALSE(make_contact_model(ContactModelKind::none, input).has_value());
    const auto linear = make_contact_model(ContactModelKind::linear, input);
    ASSERT_TRUE(linear.has_value());
    EXPECT_TRUE(std::holds_alternative<LinearSpringDashpot>(*linear));
    EXPECT_TRUE(std::holds_alternative<HertzMindlin>(
        *make_contact_model(ContactModelKind::hertz_mindlin, input)));
    ContactModelInput adaptive = input;
    adaptive.adaptive = {0.9, 10, 0.01, 1e-3};
    EXPECT_TRUE(std::holds_alternative<AdaptiveCollision>(
        *make_contact_model(ContactModelKind::adaptive, adaptive)));
    // The linear model checks its coefficients as before (ζ ≥ 1 for m = 1e-6: overdamped).
    EXPECT_THROW((void)make_contact_model(ContactModelKind::linear, {{1e6, 10.0}, 1e-6}),
                 InputError);
}

TEST(ContactModels, ShortestCollisionIsTheLightestPair)
{
    // Linear: π √(m*/k), shortest for two of the lightest bodies (m* = m/2); a fixed body and
    // the walls give longer ones.
    const Material none;
    const std::vector<PairSide> sides{
        ball_side(2.0, 1.0, 0.1, none, true), ball_side(0.5, 1.0, 0.1, none, true),
        ball_side(0.5, 1.0, 0.1, none, true), ball_side(0.01, 1.0, 0.1, none, false)};
    const AnyContactModel linear = LinearSpringDashpot({1e4, 0.0}, 0.25);
    EXPECT_NEAR(shortest_collision(linear, sides, none, 1.0),
                std::numbers::pi * std::sqrt(0.25 / 1e4), 1e-15);
    // Hertz: t_c ∝ (m*²/(R* E*²))^{1/5}; a much stiffer wall makes the wall collision shorter
    // than a pair's: m*²/R* is 4 × 1/(2 × 2) larger for the pair, E*² 4 × smaller for it.
    const Material soft{1e8, 0.0, 0.0, 0.0, 1.0};
    const Material stiff{1e12, 0.0, 0.0, 0.0, 1.0};
    const std::vector<PairSide> balls{ball_side(1.0, 1.0, 0.1, soft, true)};
    const HertzMindlin hertz;
    const double wall =
        hertz.elastic_collision_time(make_contact_pair(balls[0], wall_side(stiff)), 2.0);
    const double pair = hertz.elastic_collision_time(make_contact_pair(balls[0], balls[0]), 2.0);
    EXPECT_LT(wall, pair);
    EXPECT_NEAR(shortest_collision(HertzMindlin{}, balls, stiff, 2.0), wall, 1e-15);
    EXPECT_NEAR(shortest_collision(HertzMindlin{}, balls, std::nullopt, 2.0), pair, 1e-15);
}

TEST(Material, PairRulesTreatWallsAndImmovableBodiesAsInfinitelyHeavy)
{
    const Material a{2e9, 0.3, 0.4, 0.1, 0.9};
    const Material b{1e9, 0.2, 0.1, 0.0, 0.4};
    const ContactPair wall = make_contact_pair(ball_side(2.0, 0.5, 0.1, a, true), wall_side(b));
    EXPECT_EQ(wall.effective_mass, 2.0);
    EXPECT_EQ(wall.effective_inertia, 0.5);
    EXPECT_EQ(wall.effective_radius, 0.1);
    EXPECT_NEAR(wall.friction, 0.2, 1e-15);    // √(0.4 · 0.1)
    EXPECT_EQ(wall.rolling_friction, 0.0);     // a surface without rolling friction
    EXPECT_NEAR(wall.restitution, 0.6, 1e-15); // √(0.9 · 0.4)
    const ContactPair fixed =
        make_contact_pair(ball_side(2.0, 0.5, 0.1, a, true), ball_side(1.0, 0.1, 0.3, b, false));
    EXPECT_EQ(fixed.effective_mass, 2.0);
    EXPECT_NEAR(fixed.effective_radius, 0.075, 1e-15);
    // Without E (the linear model's surfaces) the moduli stay 0, with no division by zero.
    const ContactPair plain =
        make_contact_pair(ball_side(1.0, 1.0, 0.1, Material{}, true), wall_side(Material{}));
    EXPECT_EQ(plain.young_modulus, 0.0);
    EXPECT_EQ(plain.shear_modulus, 0.0);
}

} // namespace
} // namespace fddem
