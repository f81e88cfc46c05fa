// SPDX-License-Identifier: MIT
// A small pile in 3D, DEM only (no fluid): 20 spheres dropped into a closed box under gravity,
// with friction and rolling resistance.
//  - Hertz–Mindlin: they come to rest with overlaps below 1 % of the radius, none leaves the box,
//    and at rest the contact forces on the spheres add up to their weight (the floor carries the
//    pile; forces between spheres cancel in pairs).
//  - The linear model without rolling resistance: the pile comes to rest to round-off.
// "At rest" leaves out a twist about the vertical, which no torque of the model opposes.

#include "fddem/contact/dem_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

constexpr double r = 0.01; // [m]
constexpr double g = 9.81; // [m/s²]
const Vec<3> size(0.08, 0.08, 0.3);

/// Twenty spheres of radius r in five jittered layers of 2 × 2, 4 cm apart, falling at 0.5 m/s.
std::vector<Particle<3>> falling_spheres(const Material& grain)
{
    std::mt19937 rng(20);
    std::uniform_real_distribution<double> jitter(-0.003, 0.003);
    std::vector<Particle<3>> bodies;
    for (int k = 0; k < 20; ++k) {
        const Vec<3> at(0.025 + 0.03 * (k % 2) + jitter(rng),
                        0.025 + 0.03 * ((k / 2) % 2) + jitter(rng),
                        0.05 + 0.04 * (k / 4) + jitter(rng));
        bodies.push_back(
            test::ball<3>(at, Vec<3>(jitter(rng), jitter(rng), -0.5), r, 2500.0, grain));
        bodies.back().contact.steady_force = -bodies.back().mass() * g * Vec<3>::UnitZ();
    }
    return bodies;
}

/// The largest |v| and |ω_x,y| r of the spheres [m/s] (ω_z, a twist about the floor's normal,
/// left out).
double largest_speed(const std::vector<Particle<3>>& bodies)
{
    double speed = 0.0;
    for (const Particle<3>& b : bodies) {
        const Vec<3> rolling(b.omega.x(), b.omega.y(), 0.0);
        speed = std::max({speed, b.velocity.norm(), rolling.norm() * r});
    }
    return speed;
}

struct Pile {
    double time = 0.0;               ///< when it came to rest, or the end [s]
    double speed = 0.0;              ///< largest_speed then [m/s]
    double largest_overlap = 0.0;    ///< over the whole run, relative to r
    DemOutcome last;                 ///< of the last step
    std::vector<Particle<3>> bodies; ///< at the end
};

/// Drops the spheres into the box [0, size] and runs steps of 1 ms with 50 sub-steps until
/// `largest_speed` < `rest` (after 0.5 s) or `end`.
Pile drop(const AnyContactModel& model, const Material& grain, double rest, double end)
{
    Pile pile;
    pile.bodies = falling_spheres(grain);
    const DemWalls<3> walls = test::box<3>(size, {true, true, true}, grain);
    CellList<3> cells(walls.origin, walls.length, 2.0 * r + 0.004); // 4 mm of skin
    ContactHistory<3> history;
    const DemSettings settings{model, 0.0, 50};
    while (pile.time < end) {
        pile.last = test::step_dem<3>(pile.bodies, walls, settings, 1e-3, cells, history);
        pile.time += 1e-3;
        pile.largest_overlap = std::max(pile.largest_overlap, pile.last.max_relative_overlap);
        pile.speed = largest_speed(pile.bodies);
        if (pile.time > 0.5 && pile.speed < rest) {
            break;
        }
    }
    return pile;
}

TEST(SpherePile, TwentySpheresDroppedInABoxComeToRestInsideWithSmallOverlaps)
{
    // Glass-like but softer (E = 1e8 Pa): the static Hertz overlap under a few spheres' weight
    // is ≈ 0.1 % of r. Δt_i = 2e-5 s: ≈ 40 sub-steps per sphere–sphere collision at 1 m/s
    // (Hertz, t_c ≈ 0.8 ms).
    const Material grain{1e8, 0.25, 0.4, 0.05, 0.5};
    const Pile pile = drop(HertzMindlin{}, grain, 1e-4, 4.0);
    double escape = 0.0; // how far a centre is beyond the box shrunk by r [m]
    double weight = 0.0;
    double twist = 0.0; // largest |ω_z| r [m/s]
    Vec<3> carried = Vec<3>::Zero();
    double top = 0.0;
    for (const Particle<3>& b : pile.bodies) {
        for (int d = 0; d < 3; ++d) {
            escape = std::max({escape, r - b.centre[d], b.centre[d] - (size[d] - r)});
        }
        weight += b.mass() * g;
        twist = std::max(twist, std::abs(b.omega.z()) * r);
        carried += b.contact.mean_force;
        top = std::max(top, b.centre.z());
    }
    std::printf(
        "pile at rest after %.3f s (largest |v|, |ω_x,y| r %.1e m/s; twist |ω_z| r up to "
        "%.1e m/s): overlap %.3f %% of r at rest, %.3f %% during the drop; deepest into a "
        "wall %.2e m; contact forces carry %.6f of the weight (sideways %.1e); %d contacts, "
        "top centre at %.4f m\n",
        pile.time, pile.speed, twist, 100.0 * pile.last.max_relative_overlap,
        100.0 * pile.largest_overlap, escape, carried.z() / weight,
        (std::abs(carried.x()) + std::abs(carried.y())) / weight, pile.last.n_contacts, top);
    // At rest, but for a spin about the vertical: fddem has no twisting resistance
    // (docs/method.md), so a sphere touching only the floor keeps the twist the drop gave it
    // (1.3e-4 m/s at its surface in this run), as in DEM codes without a twisting model.
    EXPECT_LT(pile.speed, 1e-4);                     // at rest
    EXPECT_LT(pile.last.max_relative_overlap, 0.01); // the brief: < 1 % of the radius
    EXPECT_LT(escape, 0.01 * r);                     // inside the box, up to the wall overlap
    EXPECT_NEAR(carried.z() / weight, 1.0, 1e-3);    // the floor carries the pile
    // Sideways the walls' pushes cancel, up to what the residual jitter accelerates (measured
    // 1.8e-3 of the weight).
    EXPECT_LT(std::abs(carried.x()) + std::abs(carried.y()), 5e-3 * weight);
    EXPECT_GE(pile.last.n_contacts, 20); // a pile, not spheres lying apart
    EXPECT_LT(top, 0.05); // 20 spheres of 2 cm in an 8 × 8 cm box: two or three layers
}

TEST(SpherePile, ALinearPileWithoutRollingResistanceComesToRestToRoundOff)
{
    // k = 2.4e4 N/m, about the Hertz S_n of the test above at rest; ζ = 0.21 (e ≈ 0.5) for two
    // spheres (m* = 5.2e-3 kg). Friction alone holds the spheres in their pockets, and its
    // springs and dashpots take the pile to rest to round-off: no contact force pumps energy.
    const LinearSpringDashpot model({2.4e4, 4.8}, 5.2e-3);
    const Material grain{0.0, 0.0, 0.4, 0.0, 0.5};
    const Pile pile = drop(model, grain, 1e-12, 3.0);
    std::printf("linear pile without rolling resistance: largest |v|, |ω_x,y| r %.1e m/s after "
                "%.3f s, %d contacts\n",
                pile.speed, pile.time, pile.last.n_contacts);
    EXPECT_LT(pile.speed, 1e-9);
    EXPECT_GE(pile.last.n_contacts, 20);
    // With μ_r = 0.05 the same pile keeps moving at 1e-5 m/s after 3 s (docs/method.md: the
    // constant-torque rolling model, regularised as a viscous damper near rest, cannot hold a
    // sustained rolling load; each sphere's dampers also add up across its contacts).
}

} // namespace
} // namespace fddem
