// SPDX-License-Identifier: MIT
// A step that blows up leaves the simulation exactly as it was before the step (Simulation::
// advance), so that the run can be checkpointed there and continued.

#include "fddem/core/errors.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <limits>

#include "support/case_builders.hpp"
#include "support/nans_allowed.hpp"

namespace {

using fddem::Simulation;
using fddem::Vec;

/// A cavity with a heavy disk settling in it.
fddem::CaseConfig cavity_with_disk()
{
    fddem::CaseConfig c = fddem::test::cavity_config(24, 100.0, 0.01, 1.0);
    c.fluid.gravity = {0.0, -10.0};
    fddem::BodyConfig disk;
    disk.diameter = 0.25;
    disk.density = 3.0;
    disk.position = {0.45, 0.6};
    disk.velocity = {0.0, 0.0};
    disk.n_rings = 3;
    c.bodies.push_back(disk);
    c.contact.model = fddem::ContactModelKind::none;
    return c;
}

bool same_bits(const fddem::FaceField<2>& a, const fddem::FaceField<2>& b)
{
    for (int d = 0; d < 2; ++d) {
        const auto x = a[d].values();
        const auto y = b[d].values();
        if (!std::equal(x.begin(), x.end(), y.begin(), y.end())) {
            return false;
        }
    }
    return true;
}

TEST(RollBack, AFailedStepLeavesTheStateOfItsStartAndTheNextStepIsTheCleanOne)
{
    const fddem::test::NansAllowed nans;
    const fddem::CaseConfig config = cavity_with_disk();
    Simulation<2> clean(config);
    Simulation<2> failing(config);
    for (int n = 0; n < 3; ++n) {
        (void)clean.advance();
        (void)failing.advance();
    }
    const fddem::FaceField<2> u = failing.fluid().u;
    const auto p = failing.fluid().p.values();
    const std::vector<double> pressure(p.begin(), p.end());
    const Vec<2> centre = failing.bodies()[0].centre;
    const Vec<2> velocity = failing.bodies()[0].velocity;

    const double nan = std::numeric_limits<double>::quiet_NaN();
    failing.set_uniform_body_force(Vec<2>(0.0, nan));
    try {
        (void)failing.advance();
        FAIL() << "a NaN force must stop the step";
    } catch (const fddem::NumericalError& e) {
        EXPECT_EQ(e.step(), 4);
        EXPECT_DOUBLE_EQ(e.time(), 0.04);
        EXPECT_NE(std::string(e.what()).find("blown up"), std::string::npos) << e.what();
    }
    EXPECT_EQ(failing.clock().step, 3);
    EXPECT_TRUE(same_bits(failing.fluid().u, u));
    const auto p_after = failing.fluid().p.values();
    EXPECT_TRUE(std::equal(p_after.begin(), p_after.end(), pressure.begin(), pressure.end()));
    EXPECT_EQ(failing.bodies()[0].centre, centre);
    EXPECT_EQ(failing.bodies()[0].velocity, velocity);

    // Without the NaN, the step is the one the clean run takes, bit for bit.
    failing.set_uniform_body_force(Vec<2>::Zero());
    clean.set_uniform_body_force(Vec<2>::Zero());
    (void)clean.advance();
    (void)failing.advance();
    EXPECT_TRUE(same_bits(failing.fluid().u, clean.fluid().u));
    EXPECT_EQ(failing.bodies()[0].centre, clean.bodies()[0].centre);
    EXPECT_EQ(failing.bodies()[0].omega, clean.bodies()[0].omega);
}

} // namespace
