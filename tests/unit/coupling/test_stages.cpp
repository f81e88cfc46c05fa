// SPDX-License-Identifier: MIT
// The coupling stages of the time step applied to the grid: marker placement, the body force
// ρf D(λ), the rigid update (13)–(16) and the hydrodynamic force.

#include "fddem/core/errors.hpp"
#include "fddem/coupling/force_spreading.hpp"
#include "fddem/coupling/hydrodynamic_force.hpp"
#include "fddem/coupling/marker_placement.hpp"
#include "fddem/coupling/markers.hpp"
#include "fddem/coupling/rigid_update.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace fddem {
namespace {

MacGrid<2> unit_box()
{
    return MacGrid<2>(Index<2>{32, 32}, Vec<2>::Zero(), Vec<2>(1.0, 1.0));
}

Particle<2> disk_at(const Vec<2>& centre, double diameter = 0.3)
{
    Particle<2> p;
    p.shape = Ball<2>{diameter};
    p.centre = centre;
    p.coupling = MarkerCoupling<2>(make_ball_markers(p.shape, 4));
    return p;
}

TEST(MarkerPlacement, TurnsTheLayoutWithTheBodyAndCarriesItToTheCentre)
{
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.5, 0.4))};
    bodies[0].orientation = 0.5 * std::numbers::pi;
    place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 0, 0.0);
    const MarkerCoupling<2>& c = bodies[0].coupling;
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        const Vec<2>& r = c.markers.offsets[l];
        EXPECT_NEAR(c.offsets[l].x(), -r.y(), 1e-15); // a quarter turn: (x, y) → (−y, x)
        EXPECT_NEAR(c.offsets[l].y(), r.x(), 1e-15);
        EXPECT_EQ(c.positions[l], bodies[0].centre + c.offsets[l]);
    }
}

TEST(MarkerPlacement, ABodyOutOfTheBoxIsANumericalErrorNamingIt)
{
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.5, 0.5)), disk_at(Vec<2>(1.2, 0.5))};
    bodies[1].id = 7;
    try {
        place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 12, 0.3);
        FAIL() << "no error";
    } catch (const NumericalError& e) {
        EXPECT_EQ(e.where(), "body 8"); // id 7 is the eighth body, as --set bodies.8 names it
        EXPECT_EQ(e.step(), 12);
    }
    bodies[1].centre = Vec<2>(0.5, std::nan(""));
    EXPECT_THROW(place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 12, 0.3),
                 NumericalError);
    // A turn that is not finite is caught from the motion alone, as a centre is: on a split
    // grid a rank that does not place the body must stop where a placing rank would.
    bodies[1].centre = Vec<2>(0.5, 0.5);
    bodies[1].omega = std::nan("");
    EXPECT_THROW(place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 12, 0.3),
                 NumericalError);
    bodies[1].omega = 0.0;
    bodies[1].orientation = std::numeric_limits<double>::infinity();
    EXPECT_THROW(place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 12, 0.3),
                 NumericalError);
}

TEST(MarkerPlacement, MarkersOfABodyAcrossAPeriodicSideAreOnBothSidesInsideTheBox)
{
    // Centred on the seam x = 0 ≡ 1: before the halo seam this stopped the run ("a marker of
    // the body left the box").
    const MacGrid<2> channel(Index<2>{32, 32}, Vec<2>::Zero(), Vec<2>(1.0, 1.0), {true, false});
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.0, 0.5))};
    place_markers<2>(bodies, channel, AnyKernel{Peskin4Kernel{}}, 0, 0.0);
    const MarkerCoupling<2>& c = bodies[0].coupling;
    int left = 0;
    int right = 0;
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        EXPECT_GE(c.positions[l].x(), 0.0);
        EXPECT_LT(c.positions[l].x(), 1.0);
        // the marker's image next to the centre is where the offset puts it
        const Vec<2> apart = channel.domain().minimum_image(c.positions[l] - bodies[0].centre);
        EXPECT_NEAR((apart - c.offsets[l]).norm(), 0.0, 1e-15);
        left += c.positions[l].x() > 0.5 ? 1 : 0;
        right += c.positions[l].x() < 0.5 && c.offsets[l].x() > 0.0 ? 1 : 0;
    }
    EXPECT_GT(left, 0);
    EXPECT_GT(right, 0);
}

TEST(ForceSpreading, AcrossAPeriodicSideTheFacesThereReceiveAllOfIt)
{
    // A body centred on the seam: its markers spread into the ghosts on both sides, and
    // accumulate adds that to the faces on the other side: Σ over the owned faces is the
    // uniform force over the box plus ρf Σ ΔV_l λ_l, as inside the box.
    const MacGrid<2> channel(Index<2>{32, 32}, Vec<2>::Zero(), Vec<2>(1.0, 1.0), {true, false});
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.01, 0.5))};
    place_markers<2>(bodies, channel, AnyKernel{Peskin4Kernel{}}, 0, 0.0);
    MarkerCoupling<2>& c = bodies[0].coupling;
    Vec<2> total = Vec<2>::Zero();
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        c.lambda[l] = Vec<2>(1.0 + std::sin(3.0 * l), std::cos(2.0 * l));
        total += c.markers.volumes[l] * c.lambda[l];
    }
    FaceField<2> force(channel);
    const Vec<2> uniform(0.5, -1.0);
    spread_marker_forces<2>(bodies, channel, AnyKernel{Peskin4Kernel{}}, 2.0, uniform, force);
    for (int a = 0; a < 2; ++a) {
        const double sum = sum_over(channel.communicator(), channel.owned_faces(a),
                                    [&](const Index<2>& f) { return force[a](f); });
        const double faces = static_cast<double>(channel.owned_faces(a).size());
        EXPECT_NEAR(sum * channel.cell_volume(),
                    uniform[a] * faces * channel.cell_volume() + 2.0 * total[a], 1e-12);
    }
    // The periodic ghosts are images of their faces again.
    EXPECT_EQ(force[0](Index<2>{32, 16}), force[0](Index<2>{0, 16}));
    EXPECT_EQ(force[1](Index<2>{-1, 16}), force[1](Index<2>{31, 16}));
}

TEST(ForceSpreading, AddsExactlyTheMarkersTotalForceToTheUniformOne)
{
    // Σ_faces f ΔV_cell = F_uniform V_box + ρf Σ_l ΔV_l λ_l: D conserves the force.
    const MacGrid<2> grid = unit_box();
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.31, 0.62))};
    place_markers<2>(bodies, grid, AnyKernel{Peskin4Kernel{}}, 0, 0.0);
    MarkerCoupling<2>& c = bodies[0].coupling;
    Vec<2> total = Vec<2>::Zero();
    for (std::size_t l = 0; l < c.markers.size(); ++l) {
        c.lambda[l] = Vec<2>(std::sin(3.0 * l), std::cos(2.0 * l));
        total += c.markers.volumes[l] * c.lambda[l];
    }
    const double rho = 2.5;
    FaceField<2> force(grid);
    spread_marker_forces<2>(bodies, grid, AnyKernel{Peskin4Kernel{}}, rho, Vec<2>(0.0, -1.0),
                            force);
    for (int a = 0; a < 2; ++a) {
        // Faces strictly inside the box carry a full cell of fluid; the markers are far from
        // the walls, so all their weight lands there. Subtract the uniform part on them.
        Box<2> inner = grid.face_box(a);
        inner.lo[static_cast<std::size_t>(a)] += 1;
        inner.hi[static_cast<std::size_t>(a)] -= 1;
        const double uniform = a == 1 ? -1.0 : 0.0;
        const double sum = sum_over(grid.communicator(), inner, [&](const Index<2>& f) {
            return (force[a](f) - uniform) * grid.cell_volume();
        });
        EXPECT_NEAR(sum, rho * total[a], 1e-12 * rho * c.markers.size());
    }
}

TEST(RigidUpdate, ABodyMovingWithTheFluidNeedsNoForce)
{
    // u uniform = U: eq. (13) gives U back (no λ* yet, fluid density = body density, no
    // gravity), eq. (15) gives λ = 0, eq. (16) leaves u unchanged.
    const MacGrid<2> grid = unit_box();
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.5, 0.5))};
    bodies[0].velocity_n = Vec<2>(0.2, -0.1);
    FaceField<2> u(grid);
    u[0].fill(0.2);
    u[1].fill(-0.1);
    place_markers<2>(bodies, grid, AnyKernel{HatKernel{}}, 0, 0.0);
    const double defect = update_rigid_bodies<2>(bodies, grid, AnyKernel{HatKernel{}},
                                                 {1.0, Vec<2>::Zero(), 0.01, false}, u);
    EXPECT_NEAR(defect, 0.0, 1e-14);
    EXPECT_NEAR((bodies[0].velocity - Vec<2>(0.2, -0.1)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(bodies[0].omega, 0.0, 1e-13);
    for (const Vec<2>& lambda : bodies[0].coupling.lambda) {
        EXPECT_NEAR(lambda.norm(), 0.0, 1e-11);
    }
    EXPECT_NEAR(u[0](Index<2>{16, 16}), 0.2, 1e-14);
}

/// Prescribed `bodies` moving up at 0.2 through the fluid at rest of `grid`, their markers
/// placed, after one rigid update (13)–(16) with `options` (Δt = 0.01: a marker that acts gets
/// λ = 20, the slip over Δt).
std::vector<Particle<2>> rising_after_one_update(std::vector<Particle<2>> bodies,
                                                 const MacGrid<2>& grid,
                                                 RigidUpdateSettings<2> options)
{
    for (Particle<2>& p : bodies) {
        p.motion = Motion::prescribed; // moves at its velocity whatever the fluid
        p.velocity = p.velocity_n = Vec<2>(0.0, 0.2);
    }
    FaceField<2> u(grid);
    place_markers<2>(bodies, grid, AnyKernel{HatKernel{}}, 0, 0.0);
    options.fluid_density = 1.0;
    options.gravity = Vec<2>::Zero();
    options.dt = 0.01;
    (void)update_rigid_bodies<2>(bodies, grid, AnyKernel{HatKernel{}}, options, u);
    return bodies;
}

TEST(RigidUpdate, MarkersReachingAWallAreOffOnlyWhenAsked)
{
    // coupling.markers_off_at_walls: a disk 0.01 above the floor of a box at rest, moving up; its
    // markers within the reach of a wall get no force, the others the slip's; without the option
    // every marker gets it. The reach: by default 1.5 h (the hat kernel's support + 0.5), or as
    // given (coupling.markers_off_reach; 1 h, the rule before 2026-12-01).
    const MacGrid<2> grid = unit_box();
    const double h = 1.0 / 32.0;
    for (const auto& [is_simultaneous, reach] :
         {std::pair{false, 0.0}, std::pair{true, 0.0}, std::pair{false, 1.0}}) {
        const double reach_h = (reach > 0.0 ? reach : 1.5) * h;
        const auto run = [&](bool is_off) {
            RigidUpdateSettings<2> options{1.0, Vec<2>::Zero(), 0.01, false};
            options.is_wall_marker_off = is_off;
            options.is_simultaneous = is_simultaneous;
            options.wall_marker_reach = reach;
            return rising_after_one_update({disk_at(Vec<2>(0.5, 0.16))}, grid, options)[0].coupling;
        };
        const MarkerCoupling<2> off = run(true);
        const MarkerCoupling<2> on = run(false);
        int near = 0;
        int between = 0; // within 1.5 h but not within 1 h: off by default only
        for (std::size_t l = 0; l < off.markers.size(); ++l) {
            const bool is_near = off.positions[l].y() < reach_h;
            between += off.positions[l].y() >= h && off.positions[l].y() < 1.5 * h ? 1 : 0;
            near += is_near ? 1 : 0;
            EXPECT_NEAR(on.lambda[l].y(), 20.0, 1e-12) << l; // the slip 0.2 over Δt = 0.01
            if (is_near) {
                EXPECT_EQ(off.lambda[l].norm(), 0.0) << l;
            } else {
                EXPECT_NEAR(off.lambda[l].y(), 20.0, 1e-12) << l;
            }
        }
        EXPECT_GT(near, 0);    // the test can tell
        EXPECT_GT(between, 0); // and the two reaches differ
    }
}

TEST(RigidUpdate, MarkersNearTheMidplaneBetweenTwoBodiesAreOffOnlyWhenAsked)
{
    // coupling.markers_off_between_bodies: two disks 0.02 apart (0.64 h), both moving up in a
    // fluid at rest; the markers of each closer than 1.5 h (the hat's default reach) to the
    // plane midway between the surfaces get no force, the others the slip's. Without the option
    // every marker gets it; with markers_off_at_walls alone none is off (no wall is near).
    const MacGrid<2> grid = unit_box();
    const double h = 1.0 / 32.0;
    const double diameter = 0.3;
    const double gap = 0.02;
    const double mid = 0.5; // the midplane x = 0.5
    for (const bool is_simultaneous : {false, true}) {
        const auto run = [&](bool is_between_off, bool is_wall_off) {
            RigidUpdateSettings<2> options{1.0, Vec<2>::Zero(), 0.01, false};
            options.is_body_marker_off = is_between_off;
            options.is_wall_marker_off = is_wall_off;
            options.is_simultaneous = is_simultaneous;
            return rising_after_one_update(
                {disk_at(Vec<2>(mid - 0.5 * (diameter + gap), 0.5), diameter),
                 disk_at(Vec<2>(mid + 0.5 * (diameter + gap), 0.5), diameter)},
                grid, options);
        };
        const std::vector<Particle<2>> off = run(true, false);
        const std::vector<Particle<2>> walls_only = run(false, true);
        int near = 0;
        for (std::size_t b = 0; b < 2; ++b) {
            const MarkerCoupling<2>& c = off[b].coupling;
            for (std::size_t l = 0; l < c.markers.size(); ++l) {
                const bool is_near = std::abs(c.positions[l].x() - mid) < 1.5 * h;
                near += is_near ? 1 : 0;
                EXPECT_NEAR(walls_only[b].coupling.lambda[l].y(), 20.0, 1e-12) << b << " " << l;
                if (is_near) {
                    EXPECT_EQ(c.lambda[l].norm(), 0.0) << b << " " << l;
                    // its fluid taken as the body's motion in (13)–(14)
                    EXPECT_NEAR(c.fluid[l].y(), 0.2, 1e-15) << b << " " << l;
                } else {
                    EXPECT_NEAR(c.lambda[l].y(), 20.0, 1e-12) << b << " " << l;
                }
            }
        }
        EXPECT_GT(near, 4); // markers of both disks (the test can tell)
    }
}

/// Two prescribed disks moving apart in a fluid at rest, `gap` between their surfaces, swept
/// `sweeps` times over the same u in the given order: the bodies' λ and the corrected u.
struct SweptPair {
    std::vector<Particle<2>> bodies;
    FaceField<2> u;
};

SweptPair sweep_pair(double gap, bool is_simultaneous, int sweeps,
                     Motion motion = Motion::prescribed)
{
    const MacGrid<2> grid = unit_box();
    const double diameter = 0.3;
    SweptPair out{{disk_at(Vec<2>(0.5 - 0.5 * (diameter + gap), 0.5), diameter),
                   disk_at(Vec<2>(0.5 + 0.5 * (diameter + gap), 0.5), diameter)},
                  FaceField<2>(grid)};
    for (int b = 0; b < 2; ++b) {
        Particle<2>& p = out.bodies[static_cast<std::size_t>(b)];
        p.motion = motion;
        p.density = 1.5;
        p.velocity = p.velocity_n = Vec<2>(b == 0 ? -0.1 : 0.1, 0.05 * b);
    }
    place_markers<2>(out.bodies, grid, AnyKernel{HatKernel{}}, 0, 0.0);
    RigidUpdateSettings<2> settings{1.0, Vec<2>(0.0, -1.0), 0.01, false};
    settings.is_simultaneous = is_simultaneous;
    for (int k = 0; k < sweeps; ++k) {
        (void)update_rigid_bodies<2>(out.bodies, grid, AnyKernel{HatKernel{}}, settings, out.u);
    }
    return out;
}

/// The largest difference of the two sweeps' λ over both bodies, relative to the largest λ.
double lambda_difference(const SweptPair& a, const SweptPair& b)
{
    double worst = 0.0;
    double largest = 0.0;
    for (std::size_t k = 0; k < 2; ++k) {
        for (std::size_t l = 0; l < a.bodies[k].coupling.lambda.size(); ++l) {
            worst = std::max(
                worst, (a.bodies[k].coupling.lambda[l] - b.bodies[k].coupling.lambda[l]).norm());
            largest = std::max(largest, a.bodies[k].coupling.lambda[l].norm());
        }
    }
    return worst / largest;
}

TEST(RigidUpdate, BodiesApartGetTheSameForcingFromEitherSweep)
{
    // 8 h apart, the hat kernels' supports (one h each side of a marker) do not meet: the
    // simultaneous sweep gives each body what the sequential one does, to the last bit, and the
    // same corrected fluid.
    // Free bodies (their U, ω from eqs. (13)–(14)), three sweeps, so that λ* and the motion of
    // the sweeps before enter too.
    const SweptPair sequential = sweep_pair(8.0 / 32.0, false, 3, Motion::free);
    const SweptPair simultaneous = sweep_pair(8.0 / 32.0, true, 3, Motion::free);
    EXPECT_EQ(lambda_difference(sequential, simultaneous), 0.0);
    for (std::size_t b = 0; b < 2; ++b) {
        const Particle<2>& p = sequential.bodies[b];
        const Particle<2>& q = simultaneous.bodies[b];
        EXPECT_EQ(p.velocity, q.velocity) << b;
        EXPECT_EQ(p.omega, q.omega) << b;
        EXPECT_NE(p.velocity, p.velocity_n) << b; // the fluid and gravity moved them
        EXPECT_EQ(p.coupling.lambda_star, q.coupling.lambda_star) << b;
        EXPECT_EQ(p.coupling.forcing_change, q.coupling.forcing_change) << b;
    }
    for (int a = 0; a < 2; ++a) {
        for (int i = 0; i < 33; ++i) {
            for (int j = 0; j < 32; ++j) {
                const Index<2> f = a == 0 ? Index<2>{i, j} : Index<2>{j, i};
                ASSERT_EQ(sequential.u[a](f), simultaneous.u[a](f)) << a << " " << i << " " << j;
            }
        }
    }
}

TEST(RigidUpdate, TouchingBodiesReachTheSameForcingFromEitherSweep)
{
    // Half an h apart the supports overlap: after one sweep the two orders differ (the second
    // body reads the first one's correction only in the sequential sweep), and as the sweeps
    // are repeated both converge to the one λ that makes I(u) the bodies' motion at every
    // marker.
    const double gap = 0.5 / 32.0;
    const double first = lambda_difference(sweep_pair(gap, false, 1), sweep_pair(gap, true, 1));
    EXPECT_GT(first, 1e-3);
    const double converged =
        lambda_difference(sweep_pair(gap, false, 400), sweep_pair(gap, true, 400));
    EXPECT_LT(converged, 1e-3 * first);
}

/// Two free disks 0.5 h apart sliding past each other (sweep_pair), joined by a film
/// (lubrication.coupling = "implicit"): c_n = 50 and c_t = 5 times m/Δt, one sweep.
SweptPair swept_linked_pair(bool is_simultaneous, bool is_linked)
{
    const MacGrid<2> grid = unit_box();
    SweptPair out = sweep_pair(0.5 / 32.0, is_simultaneous, 0, Motion::free);
    const double a = out.bodies[0].radius();
    const double rate = out.bodies[0].mass() / 0.01;
    const LubricationResistance film{50.0 * rate, 5.0 * rate};
    const Vec<2> x = Vec<2>::UnitX();
    if (is_linked) {
        out.bodies[0].contact.lubrication_links = {
            {1, x, Vec<2>(a * x), Vec<2>(-a * x), Vec<2>::Zero(), film}};
        out.bodies[1].contact.lubrication_links = {
            {0, Vec<2>(-x), Vec<2>(-a * x), Vec<2>(a * x), Vec<2>::Zero(), film}};
    }
    RigidUpdateSettings<2> settings{1.0, Vec<2>(0.0, -1.0), 0.01, false};
    settings.is_simultaneous = is_simultaneous;
    settings.is_lubrication_implicit = true;
    (void)update_rigid_bodies<2>(out.bodies, grid, AnyKernel{HatKernel{}}, settings, out.u);
    return out;
}

TEST(RigidUpdate, BodiesAFilmJoinsAreUpdatedTogetherInEitherSweep)
{
    // Both sweeps update the pair the film joins as one group from the same u: the same motion
    // and λ to the last bit. The film is internal: the pair's momentum is what it is without
    // it (the same u and λ* enter both; without it, the simultaneous sweep), the approach (along x)
    // and the slip (along y) are slowed, and eq. (14) turns both disks counter-clockwise by its
    // turning resistance alone (u = 0 and ω^n = 0 give no other moment): ω = a c_t Δv_y / (J/Δt +
    // c_t a²).
    const SweptPair sequential = swept_linked_pair(false, true);
    const SweptPair simultaneous = swept_linked_pair(true, true);
    const SweptPair unlinked = swept_linked_pair(true, false); // both from u = 0 too
    EXPECT_EQ(lambda_difference(sequential, simultaneous), 0.0);
    const auto& p = sequential.bodies;
    const auto& q = unlinked.bodies;
    for (std::size_t b = 0; b < 2; ++b) {
        EXPECT_EQ(p[b].velocity, simultaneous.bodies[b].velocity) << b;
        EXPECT_EQ(p[b].omega, simultaneous.bodies[b].omega) << b;
        EXPECT_EQ(q[b].omega, 0.0) << b;
    }
    const Vec<2> momentum = p[0].mass() * p[0].velocity + p[1].mass() * p[1].velocity;
    const Vec<2> free = q[0].mass() * q[0].velocity + q[1].mass() * q[1].velocity;
    EXPECT_LT((momentum - free).norm(), 1e-12 * free.norm());
    const Vec<2> relative = p[1].velocity - p[0].velocity;
    const Vec<2> relative_free = q[1].velocity - q[0].velocity;
    EXPECT_GT(relative.x(), 0.0); // still parting, more slowly
    EXPECT_LT(relative.x(), 0.1 * relative_free.x());
    EXPECT_GT(relative.y(), 0.0);
    EXPECT_LT(relative.y(), relative_free.y());
    const double a = p[0].radius();
    const double c_t = 5.0 * p[0].mass() / 0.01;
    for (std::size_t b = 0; b < 2; ++b) {
        const double expected = a * c_t * relative.y() / (p[b].inertia() / 0.01 + c_t * a * a);
        EXPECT_GT(p[b].omega, 0.0) << b;
        EXPECT_NEAR(p[b].omega, expected, 1e-12 * expected) << b;
    }
}

TEST(HydrodynamicForce, IsTheMomentumBalanceOfTheMarkers)
{
    // F_H = ρf V ΔU/Δt − ρf Σ ΔV_l λ_l; with λ uniform and U unchanged, F_H = −ρf V λ.
    std::vector<Particle<2>> bodies{disk_at(Vec<2>(0.5, 0.5))};
    place_markers<2>(bodies, unit_box(), AnyKernel{HatKernel{}}, 0, 0.0);
    for (Vec<2>& lambda : bodies[0].coupling.lambda) {
        lambda = Vec<2>(0.0, 3.0);
    }
    measure_hydrodynamic_forces<2>(bodies, 2.0, TimeLevels{0.01});
    const double volume = bodies[0].volume();
    EXPECT_NEAR(bodies[0].force.y(), -2.0 * volume * 3.0, 1e-12);
    EXPECT_NEAR(bodies[0].torque, 0.0, 1e-12); // uniform λ has no moment about the centre
}

} // namespace
} // namespace fddem
