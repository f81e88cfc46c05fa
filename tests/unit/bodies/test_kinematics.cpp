// SPDX-License-Identifier: MIT
// eq. (17): the trapezoidal position update, and who moves.

#include "fddem/bodies/kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace fddem {
namespace {

TEST(Kinematics, TrapezoidalRuleIsExactForConstantAcceleration)
{
    // x(t) = x0 + v0 t + a t²/2: with U^n = v0 + a t_n, U^{n+1} = v0 + a t_{n+1}, eq. (17) is
    // exact at every step.
    const double a = -9.81;
    const double v0 = 2.0;
    const double dt = 0.01;
    std::vector<Particle<2>> bodies(1);
    Particle<2>& body = bodies[0];
    for (int n = 0; n < 100; ++n) {
        body.velocity_n = Vec<2>(0.0, v0 + a * n * dt);
        body.velocity = Vec<2>(0.0, v0 + a * (n + 1) * dt);
        move_bodies<2>(bodies, dt, false);
    }
    const double t = 100 * dt;
    EXPECT_NEAR(body.centre.y(), v0 * t + 0.5 * a * t * t, 1e-12);
}

TEST(Kinematics, AngleFollowsOmegaAndFixedBodiesStay)
{
    std::vector<Particle<2>> bodies(2);
    bodies[0].omega_n = 1.0;
    bodies[0].omega = 3.0;
    bodies[1].motion = Motion::fixed;
    bodies[1].velocity = Vec<2>(1.0, 1.0); // ignored: a fixed body does not move
    move_bodies<2>(bodies, 0.5, false);
    EXPECT_DOUBLE_EQ(bodies[0].orientation, 1.0); // Δt (ω^n + ω^{n+1})/2
    EXPECT_EQ(bodies[1].centre, Vec<2>::Zero());
}

TEST(Kinematics, PaperCouplingTakesTheDemPositionOfABodyInContact)
{
    std::vector<Particle<3>> bodies(2);
    for (Particle<3>& b : bodies) {
        b.velocity = Vec<3>(1.0, 0.0, 0.0);
        b.velocity_n = b.velocity;
        b.contact.centre = Vec<3>(0.0, 0.0, 7.0);
    }
    bodies[0].contact.is_in_contact = true;
    move_bodies<3>(bodies, 0.1, true);
    EXPECT_EQ(bodies[0].centre, Vec<3>(0.0, 0.0, 7.0));
    EXPECT_NEAR((bodies[1].centre - Vec<3>(0.1, 0.0, 0.0)).norm(), 0.0, 1e-15);
}

TEST(Kinematics, ABodyCrossingAPeriodicSideReentersOnTheOther)
{
    const PeriodicDomain<2> channel{Vec<2>::Zero(), Vec<2>(2.0, 6.0), {true, false}};
    std::vector<Particle<2>> bodies(3);
    bodies[0].centre = Vec<2>(-0.25, 3.0); // left through x = 0
    bodies[1].centre = Vec<2>(2.5, -0.5);  // right through x = 2; below the floor (no wrap)
    bodies[2].centre = Vec<2>(1.3, 4.1);   // inside: kept bit for bit
    wrap_centres<2>(bodies, channel);
    EXPECT_EQ(bodies[0].centre, Vec<2>(1.75, 3.0));
    EXPECT_EQ(bodies[1].centre, Vec<2>(0.5, -0.5));
    EXPECT_EQ(bodies[2].centre, Vec<2>(1.3, 4.1));
}

} // namespace
} // namespace fddem
