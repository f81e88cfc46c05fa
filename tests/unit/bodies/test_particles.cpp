// SPDX-License-Identifier: MIT
// The body store keeps one record per body, ordered by id, and finds bodies by id.

#include "fddem/bodies/particles.hpp"

#include <gtest/gtest.h>

namespace fddem {
namespace {

Particle<2> with_id(int id)
{
    Particle<2> p;
    p.id = id;
    p.centre = Vec<2>(id, 0.0);
    return p;
}

TEST(Particles, KeepsIdOrderWhateverTheOrderOfArrival)
{
    Particles<2> store;
    for (const int id : {4, 1, 7, 0}) {
        store.add(with_id(id));
    }
    ASSERT_EQ(store.size(), 4U);
    int previous = -1;
    for (const Particle<2>& p : store) {
        EXPECT_GT(p.id, previous);
        EXPECT_EQ(p.centre.x(), p.id); // the record travelled whole
        previous = p.id;
    }
}

TEST(Particles, FindsAndRemovesByIdAndRefusesATakenId)
{
    Particles<2> store;
    store.add(with_id(2));
    store.add(with_id(5));
    EXPECT_EQ(store.find(5), &store[1]); // ids 2, 5: position 1
    EXPECT_EQ(store.find(3), nullptr);
    EXPECT_THROW(store.add(with_id(2)), InternalError);
    EXPECT_TRUE(store.remove(2));
    EXPECT_FALSE(store.remove(2));
    EXPECT_EQ(store.size(), 1U);
    EXPECT_EQ(store.front().id, 5);
}

TEST(Particles, KnowsWhetherAnyBodyIsFree)
{
    Particles<3> store;
    Particle<3> fixed;
    fixed.motion = Motion::fixed;
    store.add(fixed);
    EXPECT_FALSE(store.has_free_body());
    Particle<3> free;
    free.id = 1;
    store.add(free);
    EXPECT_TRUE(store.has_free_body());
}

TEST(Particle, MassAndInertiaOfADiskAndASphere)
{
    Particle<2> disk;
    disk.shape = Ball<2>{2.0};
    disk.density = 3.0;
    EXPECT_DOUBLE_EQ(disk.mass(), 3.0 * std::numbers::pi); // ρ π r²
    EXPECT_DOUBLE_EQ(disk.inertia(), 0.5 * disk.mass());   // m r²/2
    Particle<3> sphere;
    sphere.shape = Ball<3>{2.0};
    sphere.density = 3.0;
    EXPECT_DOUBLE_EQ(sphere.mass(), 4.0 * std::numbers::pi); // ρ 4/3 π r³
    EXPECT_DOUBLE_EQ(sphere.inertia(), 0.4 * sphere.mass()); // 2/5 m r²
}

} // namespace
} // namespace fddem
