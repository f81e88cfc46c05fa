// SPDX-License-Identifier: MIT
// The orientation update (bodies/orientation.hpp) and the inertia tensor of eq. (14)
// (bodies/inertia.hpp, coupling/rigid_coupling.hpp) in 3D, against exact rigid-body motion.
#include "fddem/bodies/inertia.hpp"
#include "fddem/bodies/orientation.hpp"
#include "fddem/coupling/rigid_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace fddem {
namespace {

constexpr double pi = std::numbers::pi;

TEST(Orientation, ConstantSpinTurnsTheQuaternionByTheExactAngleAndKeepsItUnit)
{
    // A turn at ω = 2π/5 rad/s about (1, 2, 2)/3 for 10⁵ steps of 1e-3 s (20 turns): the body's
    // x axis is where the exact rotation by |ω| t puts it, and |q| = 1 to round-off.
    const Vec<3> axis = Vec<3>(1.0, 2.0, 2.0) / 3.0;
    const Vec<3> omega = 0.4 * pi * axis;
    Orientation<3> q = unturned<3>();
    const int steps = 100000;
    const double dt = 1e-3;
    for (int n = 0; n < steps; ++n) {
        q = turned<3>(q, omega, dt);
    }
    const Eigen::AngleAxisd exact(0.4 * pi * steps * dt, axis);
    const Vec<3> x_axis = to_world<3>(q, Vec<3>::UnitX());
    EXPECT_LT((x_axis - exact * Vec<3>::UnitX()).norm(), 1e-9);
    EXPECT_NEAR(q.norm(), 1.0, 1e-14);
    // A quarter turn about z moves x to y, as the 2D angle does.
    const Orientation<3> quarter = turned<3>(unturned<3>(), Vec<3>(0.0, 0.0, 0.5 * pi), 1.0);
    EXPECT_LT((to_world<3>(quarter, Vec<3>::UnitX()) - Vec<3>::UnitY()).norm(), 1e-15);
    EXPECT_LT(
        (to_world<2>(turned<2>(0.0, 0.5 * pi, 1.0), Vec<2>::UnitX()) - Vec<2>::UnitY()).norm(),
        1e-15);
    // No spin: the same orientation bit for bit.
    EXPECT_EQ(turned<3>(quarter, Vec<3>::Zero(), 1.0).coeffs(), quarter.coeffs());
}

TEST(Orientation, SecondMomentTensorOfPointsTurnsWithTheBody)
{
    // Four unit masses on the x and y axes: J = diag(2, 2, 4); turned a quarter about x it is
    // diag(2, 4, 2), computed either way.
    const std::vector<Vec<3>> r{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    const std::vector<double> v(4, 1.0);
    const Inertia<3> body = second_moment_tensor<3>(r, v);
    EXPECT_LT((body - Vec<3>(2.0, 2.0, 4.0).asDiagonal().toDenseMatrix()).norm(), 1e-15);
    const Orientation<3> q(Eigen::AngleAxisd(0.5 * pi, Vec<3>::UnitX()));
    std::vector<Vec<3>> turned_r;
    for (const Vec<3>& x : r) {
        turned_r.push_back(to_world<3>(q, x));
    }
    const Inertia<3> world = inertia_in_world<3>(q, body);
    EXPECT_LT((world - second_moment_tensor<3>(turned_r, v)).norm(), 1e-14);
    EXPECT_LT((world - Vec<3>(2.0, 4.0, 2.0).asDiagonal().toDenseMatrix()).norm(), 1e-14);
}

/// ω after `steps` steps of eq. (14) of a torque-free body (no markers, no fluid) of inertia J.
Vec<3> spin_after(const Inertia<3>& inertia, Vec<3> omega, double dt, int steps)
{
    for (int n = 0; n < steps; ++n) {
        RigidUpdateInput<3> in{.velocity_n = Vec<3>::Zero(),
                               .omega_n = omega,
                               .body_density = 1.0,
                               .volume = 1.0,
                               .body_inertia = inertia,
                               .fluid_density = 0.0,
                               .fluid_second_moment = isotropic_inertia<3>(0.0),
                               .gravity = Vec<3>::Zero(),
                               .dt = dt};
        omega = rigid_velocity<3>(in, {}, {}, {}, {}).omega;
    }
    return omega;
}

TEST(RigidRotation, GyroscopicTermMakesASymmetricTopPrecessAtTheExactRateToFirstOrder)
{
    // Euler's equations for a torque-free symmetric top J = diag(J1, J1, J3): ω_z stays, and
    // (ω_x, ω_y) turns at Ω = (J3 − J1) ω_z / J1 (Landau & Lifshitz, Mechanics §33). Eq. (14)'s
    // −ω^n × (J·ω^n) is explicit, so the error falls as Δt: observed order 1 ± 0.1.
    const Inertia<3> j = Vec<3>(1.0, 1.0, 2.5).asDiagonal();
    const Vec<3> omega0(0.3, 0.0, 2.0);
    const double t_end = 2.0;
    const double rate = (2.5 - 1.0) * 2.0 / 1.0;
    const Vec<3> exact(0.3 * std::cos(rate * t_end), 0.3 * std::sin(rate * t_end), 2.0);
    std::vector<double> errors;
    for (const int steps : {2000, 4000, 8000}) {
        errors.push_back((spin_after(j, omega0, t_end / steps, steps) - exact).norm());
    }
    EXPECT_LT(errors.back(), 2e-3);
    for (std::size_t k = 1; k < errors.size(); ++k) {
        EXPECT_NEAR(std::log2(errors[k - 1] / errors[k]), 1.0, 0.1);
    }
    // ω_z of a symmetric top is exactly constant (the gyroscopic term has no z component).
    EXPECT_NEAR(spin_after(j, omega0, 1e-3, 2000).z(), 2.0, 1e-12);
    // An isotropic body (a ball) keeps its spin exactly.
    EXPECT_LT((spin_after(isotropic_inertia<3>(0.4), omega0, 1e-3, 2000) - omega0).norm(), 1e-14);
}

} // namespace
} // namespace fddem
