// SPDX-License-Identifier: MIT
// Bodies across a periodic side of the box (issue 12 part 6, issue 17 item 1): the markers of a
// body by the seam are placed on both sides, what they spread into the ghosts is added to the
// faces on the other side, I reads filled ghosts, and contacts are found between nearest images.
// Then the seam is invisible: a disk settling across it falls as it falls inside the box, two
// disks colliding across it bounce as they do inside, and the total momentum of a doubly periodic
// box is kept while a disk crosses one of its corners.
//
// Every comparison moves the bodies by a whole number of cells (an even one, so that the
// red-black colouring of the momentum sweeps moves with them): on the grid the runs are then the
// same problem, and they differ only by the order in which contributions at the seam are summed.

#include "fddem/grid/loops.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace fddem {
namespace {

/// The settling box of the paper's Fig. 5 case (ρf = 1, μ = 0.1, g = 980) at h = 1/32, 2 wide
/// and periodic across x, with the bodies (and contact model) of the TOML text `bodies`, each
/// moved by `shift` along x; Δt = 0.005 to `end` [s].
CaseConfig settling_box(const std::string& bodies, double end, double shift)
{
    CaseConfig c = read_case_string(R"([domain]
size = [2.0, 6.0]
cells = [64, 192]
periodic = [true, false]
[fluid]
density = 1.0
viscosity = 0.1
gravity = [0.0, -980.0]
)" + bodies + "[coupling]\nmarkers = \"paper\"\n[time]\ndt = 0.005\nend = " +
                                        std::to_string(end) + "\n[simple]\ntolerance = 1e-4\n",
                                    "test:bodies across the seam");
    for (BodyConfig& body : c.bodies) {
        body.position[0] += shift;
    }
    return c;
}

/// The paper's Fig. 5 disk (D = 0.25, ρs/ρf = 1.25) in the settling box, released at x = `x`.
CaseConfig settling_disk(double x)
{
    return settling_box(R"([[bodies]]
diameter = 0.25
density = 1.25
position = [0.0, 4.0]
n_rings = 3
)",
                        0.1, x);
}

/// of(body 0) after each step of the run of `config`.
template <class Of>
std::vector<double> record(const CaseConfig& config, Of of)
{
    Simulation<2> sim(config);
    std::vector<double> values;
    StepReport report;
    do {
        report = sim.advance();
        values.push_back(of(sim.bodies().front()));
    } while (!sim.is_finished(report));
    return values;
}

/// The vertical velocity of body 0 after each step.
std::vector<double> fall(const CaseConfig& config)
{
    return record(config, [](const Particle<2>& body) { return body.velocity.y(); });
}

/// max_k |a_k − b_k| / max_k |b_k|.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b)
{
    double difference = 0.0;
    double scale = 0.0;
    for (std::size_t k = 0; k < b.size(); ++k) {
        difference = std::max(difference, std::abs(a[k] - b[k]));
        scale = std::max(scale, std::abs(b[k]));
    }
    return difference / scale;
}

TEST(PeriodicSeam, ADiskSettlingAcrossThePeriodicSideFallsAsItDoesInside)
{
    // Pairs 32 cells (one unit) apart: the disk centred on the seam and in the middle, and the
    // three positions of issue 17 (x = 0.05 by the seam, 1.05 inside; 1.95 by the seam, 0.95
    // inside). Before the seam the disk at x = 0 stopped ("a marker of the body left the box")
    // and at t = 0.05 the three fell at -0.62, -2.33 and -0.39 (h = 1/64).
    for (const auto& [seam, inside] :
         {std::pair{0.0, 1.0}, std::pair{0.05, 1.05}, std::pair{1.95, 0.95}}) {
        const std::vector<double> by_seam = fall(settling_disk(seam));
        const std::vector<double> in_box = fall(settling_disk(inside));
        ASSERT_EQ(by_seam.size(), in_box.size());
        const double difference = relative_difference(by_seam, in_box);
        std::printf("x = %.2f: v = %.6f at t = 0.1; x = %.2f: %.6f; largest difference %.1e\n",
                    seam, by_seam.back(), inside, in_box.back(), difference);
        EXPECT_LT(in_box.back(), -2.0); // it does fall (about 3 by t = 0.1)
        // Issue 12 asks for 0.5 %. The runs are the same problem on the grid, so they agree
        // to round-off (measured 1e-11): 1e-8 leaves room for the outer iterations' stopping
        // test and still fails on any real difference (a missed ghost is percent-sized).
        EXPECT_LT(difference, 5e-3);
        EXPECT_LT(difference, 1e-8);
    }
}

/// A disk towed at 2 along x through fluid at rest (the prescribed motion of issue 17, which
/// crossing the seam stopped as a numerical failure advising a smaller Δt), from x = `x`.
CaseConfig towed_disk(double x)
{
    return settling_box(R"([[bodies]]
diameter = 0.25
density = 1.0
motion = "prescribed"
position = [0.0, 3.0]
velocity = [2.0, 0.0]
n_rings = 3
)",
                        0.05, x);
}

/// The hydrodynamic force along x on body 0 after each step.
std::vector<double> drag(const CaseConfig& config)
{
    return record(config, [](const Particle<2>& body) { return body.force.x(); });
}

TEST(PeriodicSeam, ADiskTowedThroughThePeriodicSideFeelsTheDragItFeelsInside)
{
    // From x = 1.95 it crosses x = 2 ≡ 0 at t = 0.025; inside, from x = 0.95, it does not.
    const std::vector<double> across = drag(towed_disk(1.95));
    const std::vector<double> inside = drag(towed_disk(0.95));
    ASSERT_EQ(across.size(), inside.size());
    const double difference = relative_difference(across, inside);
    std::printf("towed across the seam: F_x = %.6f at t = 0.05 (inside %.6f), largest "
                "difference %.1e\n",
                across.back(), inside.back(), difference);
    EXPECT_LT(inside.back(), 0.0); // drag against the motion
    EXPECT_LT(difference, 1e-8);   // the same problem on the grid (see the settling test)
}

/// Two disks of the Fig. 5 size and contact (k = 1e7, c = 560, β = 2, the paper's coupling) in
/// the settling box: a light one (ρs/ρf = 1.1) and 0.4 above it a heavy one (1.5) that catches
/// it up and strikes it at t ≈ 0.06. Inside: at x = 0.99 and 1.01; `shift` moves both along x
/// (the positions are wrapped into the box when the run is set up).
CaseConfig colliding_disks(double shift)
{
    return settling_box(R"([[bodies]]
diameter = 0.25
density = 1.1
position = [0.99, 4.0]
n_rings = 3
[[bodies]]
diameter = 0.25
density = 1.5
position = [1.01, 4.4]
n_rings = 3
[contact]
model = "linear"
stiffness = 1e7
damping = 560.0
velocity_damping = 2.0
)",
                        0.18, shift);
}

/// What a run of two bodies did: the velocity components of both after each step, one after
/// the other; the steps with a contact; the largest increase of the lower body's speed in one
/// step.
struct Collision {
    std::vector<double> velocities;
    int contact_steps = 0;
    double largest_kick = 0.0;
};

Collision collide(const CaseConfig& config)
{
    Simulation<2> sim(config);
    Collision out;
    StepReport report;
    double speed = 0.0;
    do {
        report = sim.advance();
        out.contact_steps += report.contacts > 0 ? 1 : 0;
        for (const Particle<2>& body : sim.bodies()) {
            out.velocities.push_back(body.velocity.x());
            out.velocities.push_back(body.velocity.y());
        }
        const double lower = sim.bodies()[0].velocity.norm();
        out.largest_kick = std::max(out.largest_kick, lower - speed);
        speed = lower;
    } while (!sim.is_finished(report));
    return out;
}

TEST(PeriodicSeam, TwoDisksCollidingAcrossThePeriodicSideBounceAsTheyDoInside)
{
    const Collision inside = collide(colliding_disks(0.0));
    // Moved by one unit (32 cells): at x = 1.99 and 0.01, the seam between them, so that
    // their contact is found only between nearest images.
    const Collision seam = collide(colliding_disks(1.0));
    // Moved by half a unit (16 cells), inside the box: how far this collision reproduces
    // under a translation at all.
    const Collision moved = collide(colliding_disks(0.5));
    ASSERT_EQ(seam.velocities.size(), inside.velocities.size());
    const double difference = relative_difference(seam.velocities, inside.velocities);
    const double spread = relative_difference(moved.velocities, inside.velocities);
    std::printf("steps in contact %d (inside %d), largest kick %.3f (inside %.3f); largest "
                "difference %.1e (inside, moved by 16 cells: %.1e)\n",
                seam.contact_steps, inside.contact_steps, seam.largest_kick, inside.largest_kick,
                difference, spread);
    // They collide: the heavy disk strikes the light one, which is kicked down faster by more
    // than 1 (from about 4 to 6) within a step.
    EXPECT_GT(inside.contact_steps, 0);
    EXPECT_GT(inside.largest_kick, 1.0);
    EXPECT_EQ(seam.contact_steps, inside.contact_steps);
    // Before the strike the runs agree to round-off, as the settling disks do. At it the outer
    // iterations stop at their tolerance (1e-4), where the result depends on round-off: moved
    // by 16 cells inside the box the pair differs by 1.5e-6, across the seam by 3.8e-6 (both
    // measured). A contact missed across the seam differs by O(1).
    EXPECT_LT(difference, 1e-4);
}

/// A disk (D = 0.5, ρs/ρf = 2) thrown at (−1, −0.7) through a fluid at rest (μ = 0.1) in a
/// doubly periodic 2 × 2 box, from (x, y); no gravity, so nothing outside acts on the box.
CaseConfig thrown_disk(double x, double y)
{
    CaseConfig c = read_case_string(R"([domain]
size = [2.0, 2.0]
cells = [64, 64]
periodic = [true, true]
[fluid]
density = 1.0
viscosity = 0.1
[[bodies]]
diameter = 0.5
density = 2.0
position = [1.0, 1.0]
velocity = [-1.0, -0.7]
n_rings = 5
[time]
dt = 0.005
end = 0.15
)",
                                    "test:momentum in a doubly periodic box");
    c.bodies.front().position = {x, y};
    return c;
}

/// The total momentum of the box [kg·m/s per unit depth]: the fluid's over the whole box, the
/// fictitious fluid inside the body included, ρf Σ u ΔV, plus the body's excess (ρs − ρf) V U.
Vec<2> total_momentum(const Simulation<2>& sim)
{
    const MacGrid<2>& grid = sim.grid();
    const double rho = sim.fluid_properties().density;
    Vec<2> p = Vec<2>::Zero();
    for (int a = 0; a < 2; ++a) {
        p[a] = rho * grid.cell_volume() *
               sum_over(grid.communicator(), grid.owned_faces(a),
                        [&](const Index<2>& f) { return sim.fluid().u[a](f); });
    }
    for (const Particle<2>& body : sim.bodies()) {
        p += (body.density - rho) * body.volume() * body.velocity;
    }
    return p;
}

/// The largest change of the total momentum from that after the first step, relative to it,
/// and the path of the disk (x, y, U, V after each step, x and y unwrapped).
std::pair<double, std::vector<double>> momentum_drift(const CaseConfig& config)
{
    Simulation<2> sim(config);
    std::vector<double> path;
    StepReport report = sim.advance(); // the fluid inside the disk takes its motion
    const Vec<2> first = total_momentum(sim);
    double drift = 0.0;
    Vec<2> start = sim.bodies().front().centre;
    Vec<2> travelled = Vec<2>::Zero();
    const PeriodicDomain<2> domain = sim.grid().domain();
    while (!sim.is_finished(report)) {
        report = sim.advance();
        drift = std::max(drift, (total_momentum(sim) - first).norm() / first.norm());
        const Particle<2>& body = sim.bodies().front();
        travelled += domain.minimum_image(body.centre - start);
        start = body.centre;
        path.insert(path.end(),
                    {travelled.x(), travelled.y(), body.velocity.x(), body.velocity.y()});
    }
    return {drift, path};
}

TEST(PeriodicSeam, MomentumIsKeptInADoublyPeriodicBoxWhileADiskCrossesACorner)
{
    // Its centre crosses x = 0 and y = 0 (the corner) in the first steps; markers are on all
    // four sides of it and spread into the ghosts of both axes and their corner.
    const auto [corner_drift, corner_path] = momentum_drift(thrown_disk(0.06, 0.04));
    // The same disk 32 cells along both axes: inside the box throughout; and 16 cells from
    // there, still inside: how far this run reproduces under a translation at all.
    const auto [inside_drift, inside_path] = momentum_drift(thrown_disk(1.06, 1.04));
    const auto [moved_drift, moved_path] = momentum_drift(thrown_disk(0.56, 0.54));
    const double difference = relative_difference(corner_path, inside_path);
    const double spread = relative_difference(moved_path, inside_path);
    std::printf("momentum drift %.1e across the corner, %.1e and %.1e inside; paths differ by "
                "%.1e (inside, moved by 16 cells: %.1e)\n",
                corner_drift, inside_drift, moved_drift, difference, spread);
    // Momentum is kept as well as the SIMPLE iterations keep it inside the box (they stop at
    // tolerance 1e-4; measured drift 3.4e-5 in all three runs): what is spread into the ghosts
    // reaches the fluid. Ghost contributions dropped instead of accumulated make it 0.17.
    EXPECT_LT(corner_drift, 2.0 * inside_drift + 1e-6);
    EXPECT_LT(corner_drift, 2e-4);
    // And the disk moves as it does inside. Without walls the box's mean flow is a slow mode
    // of the outer iterations, and a translation inside the box reproduces the path only to
    // 3.0e-5 (measured); across the corner 4.7e-5. Dropped ghost contributions: 0.2.
    EXPECT_LT(difference, 1e-3);
}

} // namespace
} // namespace fddem
