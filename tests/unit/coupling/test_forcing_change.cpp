// SPDX-License-Identifier: MIT
// The convergence measure of prescribed bodies: the force change of one λ update, as a velocity.

#include "fddem/coupling/markers.hpp"
#include "fddem/coupling/rigid_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fddem {
namespace {

TEST(ForcingChange, UniformChangeIsTheVelocityItGivesFluidOfTheBodysVolume)
{
    const Ball<2> disk{0.5};
    const MarkerSet<2> set = make_ball_markers(disk, 4);
    const std::vector<Vec<2>> lambda_star(set.size(), Vec<2>(0.3, -0.1));
    const std::vector<Vec<2>> lambda(set.size(), Vec<2>(0.3 + 3.0, -0.1 + 4.0)); // |δλ| = 5
    const double dt = 0.01;
    const double volume = M_PI * 0.25 * 0.25;
    // Σ ΔV_l = V exactly, so the change is Δt |δλ| = 0.05; no moment about the centre.
    EXPECT_NEAR(forcing_change<2>(set.offsets, set.volumes, lambda, lambda_star, dt, volume, 0.25),
                0.05, 1e-12);
}

TEST(ForcingChange, RotationalChangeIsTakenAtTheRim)
{
    const Ball<2> disk{0.5};
    const MarkerSet<2> set = make_ball_markers(disk, 4);
    const double alpha = 2.0; // δλ = α ẑ × r: a change of angular acceleration
    std::vector<Vec<2>> lambda(set.size());
    const std::vector<Vec<2>> lambda_star(set.size(), Vec<2>::Zero());
    for (std::size_t l = 0; l < set.size(); ++l) {
        lambda[l] = alpha * Vec<2>(-set.offsets[l].y(), set.offsets[l].x());
    }
    const double dt = 0.01;
    const double r = 0.25;
    const double volume = M_PI * r * r;
    // Σ ΔV r × δλ = α Σ ΔV |r|² = α J_f/ρ; the measure is Δt · 2 α Σ ΔV |r|² / (V r).
    double second = 0.0;
    for (std::size_t l = 0; l < set.size(); ++l) {
        second += set.volumes[l] * set.offsets[l].squaredNorm();
    }
    EXPECT_NEAR(forcing_change<2>(set.offsets, set.volumes, lambda, lambda_star, dt, volume, r),
                dt * 2.0 * alpha * second / (volume * r), 1e-12);
    // And it is about Δt α r for the markers' second moment ≈ V r²/2 of a uniform disk.
    EXPECT_NEAR(forcing_change<2>(set.offsets, set.volumes, lambda, lambda_star, dt, volume, r),
                dt * alpha * r, 0.05 * dt * alpha * r);
}

} // namespace
} // namespace fddem
