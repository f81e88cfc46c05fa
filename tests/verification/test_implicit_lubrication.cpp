// SPDX-License-Identifier: MIT
// lubrication.coupling = "implicit" (coupling/lubrication_coupling.hpp, docs/method.md §5,
// "Implicit coupling") on the paper's 2D cases: the eighteen disks, whose drafting pairs blew up
// when the DEM moved them within the lubrication range, stay bounded and are held apart by the
// film; a disk settling on the floor never touches it, and the film it rests on carries what the
// resolved flow does not of its buoyant weight, as reported in particles.csv's columns.

#include "fddem/io/case_reader.hpp"
#include "fddem/simulation/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

namespace fddem {
namespace {

const std::string paper_cases = std::string(FDDEM_SOURCE_DIR) + "/cases/paper/";

/// The smallest gap between two disks of the store [cm].
double smallest_gap(const Simulation<2>& sim)
{
    double gap = std::numeric_limits<double>::infinity();
    const auto& bodies = sim.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            const double d = (bodies[i].centre - bodies[j].centre).norm();
            gap = std::min(gap, d - bodies[i].radius() - bodies[j].radius());
        }
    }
    return gap;
}

TEST(ImplicitLubrication, EighteenDisksDraftingThroughTheFilmStayApartAndBounded)
{
    // Figs. 9–13 (h = 1/64, ρs/ρf = 1.25) with lubrication on, to t = 0.2 s. Without
    // lubrication the lower disk of a column drafts to 0.34 h below the one above by then; with
    // the DEM coupling of the film the run blew up at t = 0.13 s (Courant number 8.4). With the
    // film in eqs. (13)–(14) the pairs come within its range (2 h) and it holds them at about a
    // grid spacing, every disk below its terminal speed (about 6.5 cm/s in this box).
    const double h = 1.0 / 64.0;
    Simulation<2> sim(read_case(paper_cases + "fig09_eighteen_disks/case.toml",
                                {"lubrication.enabled=true", "lubrication.coupling=implicit",
                                 "time.end=0.2", "time.min_end=0.2", "output.field_interval=0"}));
    double closest = std::numeric_limits<double>::infinity();
    double fastest = 0.0;
    bool has_film = false;
    while (true) {
        const StepReport report = sim.advance();
        closest = std::min(closest, smallest_gap(sim));
        for (const Particle<2>& body : sim.bodies()) {
            fastest = std::max(fastest, body.velocity.norm());
            // the film on a disk eqs. (13)–(14) move: the links' force
            has_film = has_film ||
                       (!body.contact.is_in_contact && body.contact.lubrication_force.norm() > 0.0);
        }
        if (sim.is_finished(report)) {
            break;
        }
    }
    std::printf("closest gap %.4g h, fastest disk %.4g cm/s\n", closest / h, fastest);
    EXPECT_TRUE(has_film);
    EXPECT_LT(closest, 2.0 * h); // within the film's range
    EXPECT_GT(closest, 0.6 * h); // held apart
    EXPECT_LT(fastest, 7.0);
}

TEST(ImplicitLubrication, TheEighteenDisksUnderTheDefaultCouplingKeepTheirFluidConverged)
{
    // Figs. 9–13 with lubrication on and nothing else set, to t = 0.7 s: the default coupling
    // is "implicit", and the drafting pairs the film joins from t ≈ 0.085 s take their steps
    // without the Anderson mixing. Mixed, the steps passed the bodies' test while the fluid's
    // mass residual drifted up (a median of 0.012 over t = 0.4–0.5 s), the Courant number rose
    // from 2.3 to 14.6 and the residual reached 1 by t = 0.7 s (two disks then overlapped by
    // 9.4 % of the radius); unmixed, the largest residual is 0.012 and the Courant number 3.05
    // (without lubrication: 0.037 and 2.96). docs/method.md §5, "The default coupling of the
    // film".
    const CaseConfig config = read_case(paper_cases + "fig09_eighteen_disks/case.toml",
                                        {"lubrication.enabled=true", "time.end=0.7",
                                         "time.min_end=0.7", "output.field_interval=0"});
    ASSERT_EQ(config.lubrication.coupling, LubricationCoupling::implicit);
    Simulation<2> sim(config);
    double worst_mass = 0.0;
    double worst_courant = 0.0;
    while (true) {
        const StepReport report = sim.advance();
        worst_mass = std::max(worst_mass, report.mass_residual);
        worst_courant = std::max(worst_courant, report.courant);
        if (sim.is_finished(report)) {
            break;
        }
    }
    std::printf("to t = 0.7 s: largest mass residual %.3g, Courant number %.3g\n", worst_mass,
                worst_courant);
    EXPECT_LT(worst_mass, 0.05);
    EXPECT_LT(worst_courant, 4.5);
}

TEST(ImplicitLubrication, ADiskSettlesOnItsFilmAndTheFilmCarriesTheRestOfItsWeight)
{
    // The Fig. 5 disk at h = 1/32, released at rest 0.5 h above the floor: it never touches
    // (no contact force at any step), its gap only closes, and at the end it creeps so slowly
    // that the film and the resolved flow together carry its buoyant weight (ρs − ρf) V g
    // = 12.03 dyn/cm, each reported apart.
    const double h = 1.0 / 32.0;
    const double a = 0.125;
    Simulation<2> sim(
        read_case(paper_cases + "fig05_disk_in_box/case.toml",
                  {"domain.cells=[64,192]", "bodies.1.n_rings=0", "lubrication.enabled=true",
                   "lubrication.coupling=implicit", "time.end=0.5", "output.field_interval=0",
                   "bodies.1.position=[1.0," + std::to_string(a + 0.5 * h) + "]"}));
    double gap = 0.5 * h;
    while (true) {
        const StepReport report = sim.advance();
        const Particle<2>& disk = sim.bodies()[0];
        const double now = disk.centre.y() - a;
        EXPECT_GT(now, 0.0) << "t = " << sim.clock().time;
        EXPECT_LE(now, gap + 1e-12) << "t = " << sim.clock().time;
        EXPECT_EQ(disk.contact.mean_force - disk.contact.lubrication_force, Vec<2>::Zero());
        gap = now;
        if (sim.is_finished(report)) {
            break;
        }
    }
    const Particle<2>& disk = sim.bodies()[0];
    const double weight = 0.25 * 980.0 * std::numbers::pi * a * a;
    const double carried = disk.force.y() + disk.contact.lubrication_force.y();
    std::printf("gap %.3g h, film %.4g + resolved %.4g = %.4g of %.4g dyn/cm\n", gap / h,
                disk.contact.lubrication_force.y(), disk.force.y(), carried, weight);
    EXPECT_GT(disk.contact.lubrication_force.y(), 0.2 * weight); // the film does carry it
    EXPECT_NEAR(carried, weight, 0.02 * weight);
}

} // namespace
} // namespace fddem
