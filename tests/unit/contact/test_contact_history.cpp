// SPDX-License-Identifier: MIT
// The contact history (contact/contact_history.hpp) is keyed by the bodies' ids, not by their
// places in the body store: two spheres pressed together with friction, their tangential spring
// loaded, give the same motion whether the store keeps them in one order or swaps them at every
// time step, and the spring is found under the same key (smaller id first) with the same
// displacement (that of the larger id's body relative to the smaller's).

#include "fddem/contact/dem_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

const Particle<3>& with_id(const std::vector<Particle<3>>& bodies, int id)
{
    return *std::find_if(bodies.begin(), bodies.end(),
                         [id](const Particle<3>& b) { return b.id == id; });
}

TEST(ContactHistory, SpringFollowsTheBodyIdsWhenTheStoreReordersThem)
{
    const Material rough{1e8, 0.25, 0.5, 0.02, 0.5};
    const Vec<3> n = Vec<3>(1.0, 2.0, 2.0) / 3.0;  // from body 7 to body 3
    const Vec<3> t = Vec<3>(2.0, 1.0, -2.0) / 3.0; // across n
    const double r7 = 0.05;
    const double r3 = 0.04;
    const double press = 20.0; // [N], along the line of centres: no couple on the pair
    // At about the static Hertz overlap under `press` (1.5e-4 m), body 3 slides across body 7.
    const Vec<3> c7 = Vec<3>::Constant(0.5);
    std::vector<Particle<3>> ordered{
        test::ball<3>(c7, Vec<3>::Zero(), r7, 2500.0, rough),
        test::ball<3>(c7 + (r7 + r3 - 1.5e-4) * n, 0.05 * t, r3, 2500.0, rough)};
    ordered[0].id = 7;
    ordered[1].id = 3;
    ordered[0].omega = Vec<3>(3.0, -1.0, 2.0);
    ordered[1].omega = Vec<3>(-2.0, 4.0, 1.0);
    ordered[0].contact.steady_force = press * n;
    ordered[1].contact.steady_force = -press * n;
    std::vector<Particle<3>> swapped = ordered;

    const DemWalls<3> open = test::box<3>(Vec<3>::Constant(1.0), {});
    CellList<3> cells_ordered(open.origin, open.length, 0.1);
    CellList<3> cells_swapped(open.origin, open.length, 0.1);
    ContactHistory<3> kept_ordered;
    ContactHistory<3> kept_swapped;
    const DemSettings settings{HertzMindlin{}, 0.0, 10};
    double largest_position_gap = 0.0;
    double largest_spring_gap = 0.0;
    double largest_spring = 0.0;
    for (int step = 0; step < 300; ++step) { // 0.03 s, about three normal periods
        std::swap(swapped[0], swapped[1]);
        (void)test::step_dem_keeping_ids<3>(ordered, open, settings, 1e-4, cells_ordered,
                                            kept_ordered);
        (void)test::step_dem_keeping_ids<3>(swapped, open, settings, 1e-4, cells_swapped,
                                            kept_swapped);
        ASSERT_EQ(kept_ordered.springs.size(), 1U) << "step " << step << ": the contact opened";
        ASSERT_EQ(kept_swapped.springs.size(), 1U) << "step " << step;
        EXPECT_EQ(kept_ordered.springs.front().key, (ContactKey{3, 7}));
        EXPECT_EQ(kept_swapped.springs.front().key, (ContactKey{3, 7}));
        const Vec<3>& xi = kept_ordered.springs.front().displacement;
        largest_spring = std::max(largest_spring, xi.norm());
        largest_spring_gap =
            std::max(largest_spring_gap,
                     (kept_swapped.springs.front().displacement - xi).norm() / xi.norm());
        for (const int id : {3, 7}) {
            largest_position_gap =
                std::max(largest_position_gap,
                         (with_id(swapped, id).centre - with_id(ordered, id).centre).norm());
        }
    }
    std::printf("store swapped every step: centres differ by at most %.1e m, the spring by %.1e "
                "of |ξ| (|ξ| up to %.1e m)\n",
                largest_position_gap, largest_spring_gap, largest_spring);
    // The spring carried friction: with the history keyed by places in the store (before the
    // fix) it was lost at every swap, and the centres drifted 2e-5 m apart.
    EXPECT_GT(largest_spring, 1e-6);
    EXPECT_LT(largest_position_gap, 1e-12);
    EXPECT_LT(largest_spring_gap, 1e-9);
}

} // namespace
} // namespace fddem
