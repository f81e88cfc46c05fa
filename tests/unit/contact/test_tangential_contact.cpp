// SPDX-License-Identifier: MIT
// Friction and rolling resistance (contact/tangential_contact.hpp): the tangential spring, its
// Coulomb limit and the rolling torque against their definitions, then a ball thrown along a
// floor without spin, for both contact models and both dimensions, against the analytic
// rigid-body answer: it slides a distance v0² (1 + 2κ) / (2 μ g (1 + κ)²) (κ = m r²/J: 5/(18 μ g)
// v0² for a solid disk) and then rolls at v0 κ/(1 + κ) (2 v0/3 for the disk); with rolling
// resistance it stops after the slide plus v1² (1 + κ)/(2 μ_r g κ).

#include "fddem/contact/tangential_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/dem_bodies.hpp"

namespace fddem {
namespace {

TEST(TangentialForce, SticksBelowTheCoulombLimit)
{
    const ContactLaw law{10.0, 1000.0, 2.0};
    Vec<2> xi(0.001, 0.0);
    const Vec<2> f = tangential_force<2>(Vec<2>(0.0, 1.0), Vec<2>(0.1, 0.0), law, 0.5, 0.01, xi);
    // ξ = 0.001 + 0.1 · 0.01; F = −k_t ξ − c_t v_t = −2 − 0.2, below μ F_n = 5.
    EXPECT_NEAR(xi.x(), 0.002, 1e-15);
    EXPECT_NEAR(f.x(), -2.2, 1e-12);
    EXPECT_EQ(f.y(), 0.0);
}

TEST(TangentialForce, SlidesAtTheCoulombLimitWithTheSpringCarryingIt)
{
    const ContactLaw law{10.0, 1000.0, 2.0};
    Vec<2> xi(0.001, 0.0);
    const Vec<2> f = tangential_force<2>(Vec<2>(0.0, 1.0), Vec<2>(0.1, 0.0), law, 0.1, 0.01, xi);
    EXPECT_NEAR(f.x(), -1.0, 1e-12);   // μ F_n
    EXPECT_NEAR(xi.x(), 0.001, 1e-15); // −F_t / k_t
    // An attractive normal force (end of a damped contact) carries no friction.
    const ContactLaw pulling{-1.0, 1000.0, 2.0};
    const Vec<2> none =
        tangential_force<2>(Vec<2>(0.0, 1.0), Vec<2>(0.1, 0.0), pulling, 0.5, 0.01, xi);
    EXPECT_EQ(none.norm(), 0.0);
    EXPECT_EQ(xi.norm(), 0.0);
}

TEST(TangentialForce, SpringTurnsWithTheContactKeepingItsLength)
{
    const ContactLaw law{10.0, 1000.0, 0.0};
    Vec<3> xi(0.003, 0.0, 0.004); // the normal turned from x–z to z
    const Vec<3> f =
        tangential_force<3>(Vec<3>(0.0, 0.0, 1.0), Vec<3>::Zero(), law, 100.0, 0.0, xi);
    EXPECT_NEAR(xi.x(), 0.005, 1e-15);
    EXPECT_NEAR(xi.z(), 0.0, 1e-15);
    EXPECT_NEAR(f.x(), -5.0, 1e-12);
}

TEST(RollingTorque, OpposesTheRelativeRollingWithMuRTimesRTimesFn)
{
    ContactPair pair;
    pair.rolling_friction = 0.1;
    pair.effective_radius = 0.05;
    pair.effective_inertia = 1.0;
    EXPECT_NEAR(rolling_torque<2>(3.0, Vec<2>(0.0, -1.0), 10.0, pair, 1e-3), -0.05, 1e-15);
    EXPECT_NEAR(rolling_torque<2>(-3.0, Vec<2>(0.0, -1.0), 10.0, pair, 1e-3), 0.05, 1e-15);
    // Nearly stopped: no more than what stops it within the sub-step, J* ω / Δt_i.
    EXPECT_NEAR(rolling_torque<2>(1e-5, Vec<2>(0.0, -1.0), 10.0, pair, 1e-3), -0.01, 1e-15);
    EXPECT_EQ(rolling_torque<2>(0.0, Vec<2>(0.0, -1.0), 10.0, pair, 1e-3), 0.0);
    // 3D: the twist about the normal is not rolling.
    const Vec<3> m =
        rolling_torque<3>(Vec<3>(1.0, 2.0, 5.0), Vec<3>(0.0, 0.0, 1.0), 10.0, pair, 1e-3);
    EXPECT_NEAR((m + 0.05 * Vec<3>(1.0, 2.0, 0.0).normalized()).norm(), 0.0, 1e-15);
}

/// ω about z (the axis a ball rolling along x on the floor y = 0 turns about).
template <int Dim>
double spin_z(const AngularVec<Dim>& omega)
{
    if constexpr (Dim == 2) {
        return omega;
    } else {
        return omega.z();
    }
}

struct Throw {
    double slip_distance; ///< travelled until the contact point stopped slipping [m]
    double roll_speed;    ///< speed at t_end [m/s]
    double final_slip;    ///< slip speed at t_end [m/s]
    double distance;      ///< travelled by t_end [m]
};

constexpr double gravity = 9.81;  // [m/s²]
constexpr double radius = 0.05;   // [m]
constexpr double density = 2500.; // [kg/m³]

/// A ball on the floor (at its static overlap), thrown along x at v0 without spin, under
/// gravity, followed for `duration` in sub-steps of 2e-5 s (about 50 per tangential
/// oscillation period of the contact).
template <int Dim>
Throw throw_ball(const AnyContactModel& model, const Material& surface, double v0, double duration)
{
    using test::along;
    std::vector<Particle<Dim>> bodies{
        test::ball<Dim>(Vec<Dim>::Zero(), along<Dim>(0, v0), radius, density, surface)};
    Particle<Dim>& b = bodies[0];
    b.contact.steady_force = along<Dim>(1, -b.mass() * gravity);
    // A box long enough along x for the throw; small across (the cell list spans it).
    DemWalls<Dim> floor = test::box<Dim>(along<Dim>(0, 4.0, 2.0), {}, surface);
    floor.has_walls[1] = true;
    // Static overlap: F_n(α) = m g, by bisection on the model's law.
    const ContactPair pair = make_contact_pair(
        ball_side(b.mass(), b.inertia(), radius, surface, true), wall_side(surface));
    const double low = test::static_overlap(model, pair, b.mass() * gravity, 0.1 * radius);
    b.centre = along<Dim>(1, radius - low, 1.0);
    const double x0 = b.centre.x();
    const double step = 2e-5;
    Throw out{-1.0, 0.0, 0.0, 0.0};
    ContactHistory<Dim> history;
    test::run_substeps<Dim>(
        bodies, floor, DemSettings{model, 0.0, 1}, step, std::lround(duration / step), history,
        [&](const auto& now, const auto&) {
            const double slip = now[0].velocity.x() + spin_z<Dim>(now[0].omega) * radius;
            if (out.slip_distance < 0.0 && slip <= 0.0) {
                out.slip_distance = now[0].centre.x() - x0;
            }
            return true;
        });
    out.roll_speed = b.velocity.x();
    out.final_slip = b.velocity.x() + spin_z<Dim>(b.omega) * radius;
    out.distance = b.centre.x() - x0;
    return out;
}

/// The contact models under test, with the same surface: Hertz–Mindlin with E = 1e10 Pa (2D:
/// per unit depth), and the linear model with k = 1e7 N/m; both keep the overlap below 0.05 % of
/// the radius, so that the lever arm is the radius to that accuracy.
template <int Dim>
std::vector<std::pair<const char*, AnyContactModel>> models()
{
    const double mass = density * Ball<Dim>{2.0 * radius}.volume();
    const double k = 1e7;
    const double zeta = 0.2; // e ≈ 0.53
    return {{"hertz_mindlin", HertzMindlin{}},
            {"linear", LinearSpringDashpot({k, 2.0 * zeta * std::sqrt(k * mass)}, mass)}};
}

template <class D>
class ThrownBall : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(ThrownBall, Dimensions);

TYPED_TEST(ThrownBall, SlidesThenRollsAtTheRigidBodyDistanceAndSpeed)
{
    constexpr int Dim = TypeParam::value;
    const double mu = 0.3;
    const double v0 = 1.0;
    const double kappa = Dim == 2 ? 2.0 : 2.5; // m r²/J
    const double slide =
        v0 * v0 / (mu * gravity) * (1.0 + 2.0 * kappa) / (2.0 * (1.0 + kappa) * (1.0 + kappa));
    const double roll = v0 * kappa / (1.0 + kappa);
    const Material surface{1e10, 0.25, mu, 0.0, 0.5};
    for (const auto& [name, model] : models<Dim>()) {
        const Throw t = throw_ball<Dim>(model, surface, v0, 0.35);
        std::printf("%dD %s: slides %.5f m (analytic %.5f), rolls at %.5f m/s (analytic %.5f)\n",
                    Dim, name, t.slip_distance, slide, t.roll_speed, roll);
        // Issue 4: within 1 %.
        EXPECT_NEAR(t.slip_distance / slide, 1.0, 0.01) << name;
        EXPECT_NEAR(t.roll_speed / roll, 1.0, 0.01) << name;
        // Rolling without slipping: v = ω r (the tangential spring's oscillation is damped).
        EXPECT_LT(std::abs(t.final_slip), 1e-3 * v0) << name;
    }
}

TYPED_TEST(ThrownBall, StopsAtTheDistanceOfTheConstantRollingTorque)
{
    constexpr int Dim = TypeParam::value;
    const double mu = 0.3;
    const double mu_r = 0.05;
    const double v0 = 1.0;
    const double kappa = Dim == 2 ? 2.0 : 2.5;
    // Sliding: friction −μ m g and the rolling torque μ_r r m g against the spin; then rolling
    // under the rolling torque alone, decelerating at μ_r g κ/(1 + κ).
    const double t1 = v0 / (gravity * (mu * (1.0 + kappa) - mu_r * kappa));
    const double v1 = v0 - mu * gravity * t1;
    const double slide = v0 * t1 - 0.5 * mu * gravity * t1 * t1;
    const double rolled = v1 * v1 * (1.0 + kappa) / (2.0 * mu_r * gravity * kappa);
    const double stop_time = t1 + v1 * (1.0 + kappa) / (mu_r * gravity * kappa);
    const Material surface{1e10, 0.25, mu, mu_r, 0.5};
    for (const auto& [name, model] : models<Dim>()) {
        const Throw t = throw_ball<Dim>(model, surface, v0, stop_time + 0.3);
        std::printf("%dD %s: stops after %.4f m (analytic %.4f), final speed %.2g m/s\n", Dim, name,
                    t.distance, slide + rolled, t.roll_speed);
        EXPECT_NEAR(t.distance / (slide + rolled), 1.0, 0.01) << name;
        EXPECT_NEAR(t.slip_distance / slide, 1.0, 0.01) << name;
        EXPECT_LT(std::abs(t.roll_speed), 1e-4 * v0) << name; // at rest, not creeping
    }
}

} // namespace
} // namespace fddem
