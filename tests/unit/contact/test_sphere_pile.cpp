// SPDX-License-Identifier: MIT
// A small pile in 3D, DEM only (no fluid): 20 spheres dropped into a closed box under gravity,
// with Hertz–Mindlin, friction and rolling resistance, come to rest with overlaps below 1 % of
// the radius, none leaves the box, and at rest the contact forces on the spheres add up to their
// weight (the floor carries the pile; forces between spheres cancel in pairs). "At rest" leaves
// out a twist about the vertical, which no torque of the model opposes.

#include "fddem/contact/dem_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

TEST(SpherePile, TwentySpheresDroppedInABoxComeToRestInsideWithSmallOverlaps)
{
    const double r = 0.01; // [m]
    const double g = 9.81; // [m/s²]
    const Vec<3> size(0.08, 0.08, 0.3);
    // Glass-like but softer (E = 1e8 Pa): the static Hertz overlap under a few spheres' weight
    // is ≈ 0.1 % of r.
    const Material grain{1e8, 0.25, 0.4, 0.05, 0.5};
    std::mt19937 rng(20);
    std::uniform_real_distribution<double> jitter(-0.003, 0.003);
    std::vector<Particle<3>> bodies;
    for (int k = 0; k < 20; ++k) { // five layers of 2 × 2, 4 cm apart, jittered
        const Vec<3> at(0.025 + 0.03 * (k % 2) + jitter(rng),
                        0.025 + 0.03 * ((k / 2) % 2) + jitter(rng),
                        0.05 + 0.04 * (k / 4) + jitter(rng));
        bodies.push_back(
            test::ball<3>(at, Vec<3>(jitter(rng), jitter(rng), -0.5), r, 2500.0, grain));
        bodies.back().contact.steady_force = -bodies.back().mass() * g * Vec<3>::UnitZ();
    }
    const DemWalls<3> walls = test::box<3>(size, {true, true, true}, grain);
    CellList<3> cells(walls.origin, walls.length, 2.0 * r + 0.004); // 4 mm of skin
    ContactHistory<3> history;
    // Δt_i = 2e-5 s: ≈ 40 sub-steps per sphere–sphere collision at 1 m/s (Hertz, t_c ≈ 0.8 ms).
    const DemSettings settings{HertzMindlin{}, 0.0, 50};
    double largest_overlap = 0.0; // over the whole run, relative to r
    double speed = 0.0;           // largest |v| and |ω_x,y| r [m/s]
    double twist = 0.0;           // largest |ω_z| r [m/s]
    double time = 0.0;
    DemOutcome last;
    while (time < 4.0) {
        last = test::step_dem<3>(bodies, walls, settings, 1e-3, cells, history);
        time += 1e-3;
        largest_overlap = std::max(largest_overlap, last.max_relative_overlap);
        speed = 0.0;
        twist = 0.0;
        for (const Particle<3>& b : bodies) {
            const Vec<3> rolling(b.omega.x(), b.omega.y(), 0.0);
            speed = std::max({speed, b.velocity.norm(), rolling.norm() * r});
            twist = std::max(twist, std::abs(b.omega.z()) * r);
        }
        if (time > 0.5 && speed < 1e-4) {
            break;
        }
    }
    double escape = 0.0; // how far a centre is beyond the box shrunk by r [m]
    double weight = 0.0;
    Vec<3> carried = Vec<3>::Zero();
    double top = 0.0;
    for (const Particle<3>& b : bodies) {
        for (int d = 0; d < 3; ++d) {
            escape = std::max({escape, r - b.centre[d], b.centre[d] - (size[d] - r)});
        }
        weight += b.mass() * g;
        carried += b.contact.mean_force;
        top = std::max(top, b.centre.z());
    }
    std::printf(
        "pile at rest after %.3f s (largest |v|, |ω_x,y| r %.1e m/s; twist |ω_z| r up to "
        "%.1e m/s): overlap %.3f %% of r at rest, %.3f %% during the drop; deepest into a "
        "wall %.2e m; contact forces carry %.6f of the weight (sideways %.1e); %d contacts, "
        "top centre at %.4f m\n",
        time, speed, twist, 100.0 * last.max_relative_overlap, 100.0 * largest_overlap, escape,
        carried.z() / weight, (std::abs(carried.x()) + std::abs(carried.y())) / weight,
        last.n_contacts, top);
    // At rest, but for a spin about the vertical: fddem has no twisting resistance
    // (docs/method.md), so a sphere touching only the floor keeps the twist the drop gave it
    // (1.3e-4 m/s at its surface in this run), as in DEM codes without a twisting model.
    EXPECT_LT(speed, 1e-4);                       // at rest
    EXPECT_LT(last.max_relative_overlap, 0.01);   // the brief: < 1 % of the radius
    EXPECT_LT(escape, 0.01 * r);                  // inside the box, up to the wall overlap
    EXPECT_NEAR(carried.z() / weight, 1.0, 1e-3); // the floor carries the pile
    // Sideways the walls' pushes cancel, up to what the residual jitter accelerates (measured
    // 1.8e-3 of the weight).
    EXPECT_LT(std::abs(carried.x()) + std::abs(carried.y()), 5e-3 * weight);
    EXPECT_GE(last.n_contacts, 20); // a pile, not spheres lying apart
    EXPECT_LT(top, 0.05);           // 20 spheres of 2 cm in an 8 × 8 cm box: two or three layers
}

} // namespace
} // namespace fddem
