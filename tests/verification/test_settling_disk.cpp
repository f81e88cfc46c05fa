// SPDX-License-Identifier: MIT
// The fictitious-domain coupling (eqs. (13)–(17)) on the paper's Fig. 3 case and on bodies
// whose motion is known without any fluid computation.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/run_to_end.hpp"

namespace fddem {
namespace {

const std::string fig03 =
    std::string(FDDEM_SOURCE_DIR) + "/cases/paper/fig03_settling_channel/case.toml";

TEST(SettlingDisk, TerminalVelocityInTheChannelIsTheAnalyticOne)
{
    // Paper Fig. 3 (Re = 0.1, W/D = 4, ρr = 1.2, h = D/16, N_a = 6, Δt = 5e-4), 0.25 time
    // units: the disk reaches its terminal velocity within about 0.1 (the paper: < 200 steps).
    const CaseConfig config = read_case(fig03, {"time.end=0.25"});
    Simulation<2> sim(config);
    test::run_to_end(sim);
    const double v = -sim.bodies().front().velocity[1];
    std::printf("terminal velocity / U_c = %.4f (analytic 1, Happel & Brenner 1965)\n", v);
    // The wall-factor formula (eq. 20) is the Re → 0 limit; measured 1.03–1.04 at this
    // resolution (the diffuse interface and the unconverged marker constraint, see the
    // issue notes): 5 % bounds it and fails on any real regression of the coupling.
    EXPECT_NEAR(v, 1.0, 0.05);
    // It settles straight down the centre line.
    EXPECT_NEAR(sim.bodies().front().centre[0], 2.0, 1e-4);
}

TEST(SettlingDisk, TheSurfaceRingWithTheInnerFluidFromTheCellsSettlesAtTheAnalyticSpeed)
{
    // The same case with one marker ring 0.3 h inside the surface (coupling.markers =
    // "surface") and the fluid inside the disk integrated over the cells (coupling.inner_fluid =
    // "volume", Kempe & Fröhlich 2012; coupling/inner_fluid.hpp). Measured at t = 0.25: 1.0156
    // (1.0153 at t = 0.3, against the paper's layout's 1.0441 and the retracted layout's 0.9998;
    // docs/method.md §4, "The fluid inside a body"). 3 % bounds it; the paper's layout, 4.4 % fast,
    // would fail.
    const CaseConfig config = read_case(
        fig03, {"time.end=0.25", "coupling.markers=surface", "coupling.inner_fluid=volume"});
    Simulation<2> sim(config);
    test::run_to_end(sim);
    const double v = -sim.bodies().front().velocity[1];
    std::printf("surface ring, inner fluid over the cells: terminal velocity / U_c = %.4f\n", v);
    EXPECT_NEAR(v, 1.0, 0.03);
    EXPECT_NEAR(sim.bodies().front().centre[0], 2.0, 1e-4);
}

CaseConfig quiescent_box(double body_density)
{
    CaseConfig c = read_case_string(R"([domain]
size = [2.0, 2.0]
cells = [32, 32]
[fluid]
density = 1.0
viscosity = 0.1
gravity = [0.0, -10.0]
[[bodies]]
diameter = 0.5
density = 1.0
position = [1.0, 1.0]
[time]
dt = 0.005
end = 0.1
)",
                                    "test");
    c.bodies.front().density = body_density;
    return c;
}

TEST(SettlingDisk, NeutrallyBuoyantDiskInStillFluidStaysAtRest)
{
    Simulation<2> sim(quiescent_box(1.0));
    test::run_to_end(sim);
    EXPECT_LT(sim.bodies().front().velocity.norm(), 1e-12);
    EXPECT_LT(std::abs(sim.bodies().front().omega), 1e-12);
    EXPECT_LT((sim.bodies().front().centre - Vec<2>(1.0, 1.0)).norm(), 1e-12);
}

TEST(SettlingDisk, LightDiskRisesAndHeavyDiskSinks)
{
    Simulation<2> light(quiescent_box(0.5));
    test::run_to_end(light);
    Simulation<2> heavy(quiescent_box(1.5));
    test::run_to_end(heavy);
    const double rise = light.bodies().front().velocity[1];
    const double sink = heavy.bodies().front().velocity[1];
    std::printf("light disk v = %.4f, heavy disk v = %.4f\n", rise, sink);
    EXPECT_GT(rise, 0.0);
    EXPECT_LT(sink, 0.0);
    EXPECT_TRUE(std::isfinite(rise));
    // Early on inertia dominates: |a| ≈ |ρs − ρf| g / (ρs + ρf C_a) with added mass C_a = 1
    // for a disk, so the light disk accelerates faster than the heavy one of equal |Δρ|.
    EXPECT_GT(std::abs(rise), std::abs(sink));
}

/// A disk of D = 0.5 at ρs/ρf = `density` released at rest in the middle of a closed 2 × 4 box
/// (D/8, Δt 0.001, g = 980), run to `end`: its vertical velocity then, how many of its steps
/// ended unconverged, and how far the force it reports at the last step is from its equation of
/// motion, |ρs V ΔU/Δt − F_H − (ρs − ρf) V g| / |(ρs − ρf) V g|.
struct LightDiskRun {
    double velocity;
    int unconverged;
    double imbalance;
};

LightDiskRun run_light_disk(double density, double end, std::vector<std::string> settings = {})
{
    settings.push_back("bodies.density=" + std::to_string(density));
    settings.push_back("time.end=" + std::to_string(end));
    const CaseConfig c = read_case_string(R"([domain]
size = [2.0, 4.0]
cells = [32, 64]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -980.0]
[time]
dt = 0.001
end = 0.01
[simple]
tolerance = 1e-4
[[bodies]]
diameter = 0.5
density = 1.0
position = [1.0, 2.0]
)",
                                          "light.toml", settings);
    Simulation<2> sim(c);
    StepReport report;
    int unconverged = 0;
    do {
        report = sim.advance();
        unconverged += report.is_converged ? 0 : 1;
    } while (!sim.is_finished(report));
    const Particle<2>& disk = sim.bodies().front();
    const Vec<2> weight = (disk.density - 1.0) * disk.volume() * Vec<2>(0.0, -980.0);
    const Vec<2> inertia = disk.mass() * (disk.velocity - disk.velocity_n) / sim.clock().dt;
    return {disk.velocity[1] * end / sim.clock().time, unconverged,
            (inertia - disk.force - weight).norm() / weight.norm()};
}

TEST(SettlingDisk, VeryLightDisksAccelerateAtTheAddedMassRate)
{
    // ρs/ρf = 0.3 and 0.1: beyond the partitioned coupling's added-mass limit (about 0.4
    // without Anderson acceleration: 0.3 never converged, 0.1 blew up in the first step;
    // docs/method.md §4). With the acceleration every step converges, and over the first
    // 0.01 s the disk accelerates at a = (ρf − ρs) g / (ρs + C_a ρf): inertia dominates so
    // early (Δt = 0.001, 10 steps). C_a is the potential-flow added mass of the disk in this
    // box, 1.108 (tools/added_mass.py --box 2 4 --centre 1 2 --radius 0.25), not the unbounded
    // 1 this test compared with until 2026-11-28. Against it the paper's layout at D/8 is fast
    // by 6.4 % (ρs/ρf 0.3) and 7.9 % (0.1): its body is too light in inertia at D/8, as the
    // impulse of AddedMass.AnImpulsivelyStartedDiskTakesThePotentialFlowImpulse shows (5.8 % low
    // at D/8). The bound is 10 %; the retracted layout, 31 % slow here, fails it.
    for (const double density : {0.3, 0.1}) {
        const LightDiskRun run = run_light_disk(density, 0.01);
        const double acceleration = run.velocity / 0.01;
        std::printf("force off the equation of motion by %.1e of the buoyant weight\n",
                    run.imbalance);
        const double expected = (1.0 - density) * 980.0 / (density + 1.10839);
        std::printf("rho_s/rho_f = %.1f: a = %.1f cm/s^2 (added-mass estimate %.1f), %d "
                    "unconverged steps\n",
                    density, acceleration, expected, run.unconverged);
        EXPECT_EQ(run.unconverged, 0) << density;
        EXPECT_NEAR(acceleration, expected, 0.10 * expected) << density;
    }
}

TEST(SettlingDisk, WithTheInnerFluidFromTheCellsANeutralDiskStaysAtRestAndLightOnesRiseStably)
{
    // eq. (13'): ρs V (U^{n+1} − U^n)/Δt = (ρs − ρf) V g + ρf (∫u − ∫u^n)/Δt − ρf Σ ΔV λ*: a
    // body as dense as the fluid, in fluid at rest, has nothing to move it.
    CaseConfig neutral = quiescent_box(1.0);
    neutral.coupling.markers = MarkerLayout::surface;
    neutral.coupling.inner_fluid = InnerFluidSource::volume;
    Simulation<2> sim(neutral);
    test::run_to_end(sim);
    EXPECT_LT(sim.bodies().front().velocity.norm(), 1e-12);
    // Light disks down to ρs/ρf = 0.1 (issue 13's stability limit for the paper's coupling):
    // the level-n inner fluid enters eq. (13') explicitly (Kempe & Fröhlich report stability to
    // about 0.3 with it), but the outer iterations converge every step here.
    for (const double density : {0.3, 0.1}) {
        const std::vector<std::string> surface = {"coupling.markers=\"surface\"",
                                                  "coupling.inner_fluid=\"volume\""};
        // Over the first 0.01 s (inertia dominates, VeryLightDisksAccelerateAtTheAddedMassRate):
        // the ring carries more fluid than the disk (its kernel reaches about 0.7 h past the
        // surface), less than the retracted layout, whose outer ring it is, does with the rings
        // inside. Bounds: the potential-flow added mass in this box, C_m 1.108, and the retracted
        // layout's measured impulse at D/8, C_m 1.619 (docs/method.md §4, "The inertia of the
        // marker layouts"). Measured: 384 and 554 cm/s² (bounds 357–487 and 513–730).
        const LightDiskRun early = run_light_disk(density, 0.01, surface);
        const double acceleration = early.velocity / 0.01;
        std::printf("rho_s/rho_f = %.1f, surface ring: a = %.1f cm/s^2, force off its equation of "
                    "motion by %.1e of the buoyant weight\n",
                    density, acceleration, early.imbalance);
        EXPECT_LT(acceleration, (1.0 - density) * 980.0 / (density + 1.10839)) << density;
        EXPECT_GT(acceleration, (1.0 - density) * 980.0 / (density + 1.619)) << density;
        // The force it reports is the one eq. (13') moved it with (the inner fluid's change over
        // the step, not ρf V ΔU), to the step's convergence.
        EXPECT_LT(early.imbalance, 1e-3) << density; // measured 3.6e-4 and 9.3e-5
        const LightDiskRun later = run_light_disk(density, 0.05, surface);
        std::printf("rho_s/rho_f = %.1f, surface ring: v(0.05) = %.2f cm/s, %d unconverged\n",
                    density, later.velocity, later.unconverged);
        EXPECT_EQ(later.unconverged, 0) << density;
        EXPECT_GT(later.velocity, early.velocity) << density; // still rising
    }
}

TEST(SettlingDisk, TheSurfaceRingWithTheRomaKernelSettlesWithinIssue13sBoundAndLightDisksRise)
{
    // Issue 13 asks of one layout both Fig. 3 within 1.5 % of the analytic speed at D/16 and
    // light disks as stable as the paper's down to ρs/ρf = 0.1. The surface ring with the inner
    // fluid over the cells and the hat kernel gives 1.0153 (fails the 1.5 %); with the
    // three-point kernel of Roma, Peskin & Berger (1999), the one Breugem's (2012) 0.3 h
    // retraction was made with, and the markers h apart (Uhlmann 2005), it gives 0.9952 at
    // t = 0.3 (0.9958 at the default 1.4 h; docs/method.md §4, "The surface ring's kernel at
    // D/20").
    const CaseConfig config = read_case(
        fig03, {"time.end=0.25", "coupling.markers=surface", "coupling.inner_fluid=volume",
                "coupling.kernel=roma3", "coupling.marker_spacing_ratio=1.0"});
    Simulation<2> sim(config);
    test::run_to_end(sim);
    const double v = -sim.bodies().front().velocity[1];
    std::printf("surface ring, roma3, inner fluid over the cells: U / U_c = %.4f\n", v);
    EXPECT_NEAR(v, 1.0, 0.015);
    EXPECT_NEAR(sim.bodies().front().centre[0], 2.0, 1e-4);
    // The lightest disk of the rule, to t = 0.05: every step converges and it is still rising.
    const LightDiskRun light =
        run_light_disk(0.1, 0.05,
                       {"coupling.markers=\"surface\"", "coupling.inner_fluid=\"volume\"",
                        "coupling.kernel=\"roma3\"", "coupling.marker_spacing_ratio=1.0"});
    std::printf("rho_s/rho_f = 0.1, surface ring, roma3: v(0.05) = %.2f cm/s, %d unconverged\n",
                light.velocity, light.unconverged);
    EXPECT_EQ(light.unconverged, 0);
    EXPECT_GT(light.velocity, 15.0); // measured 20.25 at t = 0.05 (to t = 0.1 in docs/method.md)
}

/// The largest Courant number over the first 30 steps of a lone disk of the DKT set-up (d 0.25,
/// ρs/ρf 1.5, ν 0.01, d/h 16, Δt 2.5e-4) released at rest with its centre at (1.0, 4.5): on a
/// grid node, on the box's mirror line.
double lone_disk_start_courant(std::vector<std::string> settings = {})
{
    const CaseConfig c = read_case_string(R"([domain]
size = [2.0, 6.0]
cells = [128, 384]
[fluid]
density = 1.0
viscosity = 0.01
gravity = [0.0, -981.0]
[[bodies]]
shape = "disk"
diameter = 0.25
density = 1.5
position = [1.0, 4.5]
[time]
dt = 2.5e-4
end = 0.0075
[simple]
tolerance = 1e-4
)",
                                          "lone.toml", std::move(settings));
    Simulation<2> sim(c);
    StepReport report;
    double courant = 0.0;
    do {
        report = sim.advance();
        courant = std::max(courant, report.courant);
    } while (!sim.is_finished(report));
    return courant;
}

TEST(SettlingDisk, ALoneDiskOnAGridNodeOfTheMirrorLineStartsCleanlyWithTheMixing)
{
    // Before 2026-11-30 this start blew up with the Anderson mixing on (Courant number 5.7 by
    // step 26, |u| ≈ 350 beside a disk falling at 1 cm/s) and was clean without it (0.029):
    // a step that passed its test ended on the mixing's extrapolation x_{k+1}, not on the
    // G(x_k) the test had measured, and γ of 40–118 threw the fluid (docs/method.md §4, "The
    // mixing's step bounded"). The disk falls at about 2 cm/s by t = 0.0075 s, 0.0125 cells a
    // step: a Courant number of a few hundredths is the flow it drives.
    const double mixed = lone_disk_start_courant();
    const double plain = lone_disk_start_courant({"simple.acceleration_depth=0"});
    const double bounded = lone_disk_start_courant({"simple.acceleration_max_step=100"});
    std::printf("largest Courant number of 30 steps: %.4f mixed, %.4f plain, %.4f bounded\n", mixed,
                plain, bounded);
    // 0.05: the step's bound alone (a diagnostic build without the kept iterate) gives 0.075,
    // so this pins the kept iterate, which gives what the plain iteration gives (0.0285).
    EXPECT_LT(plain, 0.05);
    EXPECT_LT(mixed, 0.05);
    EXPECT_LT(bounded, 0.05);
}

} // namespace
} // namespace fddem
