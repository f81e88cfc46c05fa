// SPDX-License-Identifier: MIT
#pragma once
// The issue-15 tests' comparison of an array on a split grid with the one-process array.

#include "fddem/bodies/particles.hpp"
#include "fddem/coupling/marker_routes.hpp"
#include "fddem/grid/communicator.hpp"
#include "fddem/grid/fields.hpp"
#include "fddem/grid/loops.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace fddem::test {

/// The axes whose bit is set in `code` are periodic (bit d: axis d), for tests that go over
/// every combination.
template <int Dim>
std::array<bool, Dim> periodic_from(int code)
{
    std::array<bool, Dim> periodic{};
    for (int d = 0; d < Dim; ++d) {
        periodic[static_cast<std::size_t>(d)] = ((code >> d) & 1) != 0;
    }
    return periodic;
}

/// The largest |split − whole| over the entries `owned` of each rank, and the largest |whole|
/// there, both over all ranks of `world`.
template <int Dim>
std::pair<double, double> compare_owned(const Communicator& world, const Box<Dim>& owned,
                                        const GridArray<Dim>& split, const GridArray<Dim>& whole)
{
    double worst = 0.0;
    double largest = 0.0;
    for_each_cell_in_vtk_order(owned, [&](const Index<Dim>& i) {
        worst = std::max(worst, std::abs(split(i) - whole(i)));
        largest = std::max(largest, std::abs(whole(i)));
    });
    return {world.max(worst), world.max(largest)};
}

/// The largest difference of the bodies' centres, velocities (U, and ω R at the rim) and
/// hydrodynamic loads (F, and T / R) between a split run's copies and the one-process run's,
/// each relative to the largest value of its kind among the one-process bodies (a rim speed
/// to the largest speed, a torque to the largest force: a disk that falls straight has ω ≈ 0,
/// which is no scale), over all ranks (each holds every body).
template <int Dim>
double body_difference(const Particles<Dim>& split, const Particles<Dim>& whole)
{
    struct Kind {
        double worst = 0.0;
        double largest = 0.0;
        void add(double difference, double reference)
        {
            worst = std::max(worst, std::abs(difference));
            largest = std::max(largest, std::abs(reference));
        }
    };
    std::array<Kind, 3> kinds; // centre, speed, load
    for (std::size_t k = 0; k < whole.size(); ++k) {
        const Particle<Dim>& a = split[k];
        const Particle<Dim>& b = whole[k];
        const double r = b.radius();
        kinds[0].add((a.centre - b.centre).norm(), b.centre.norm());
        kinds[1].add((a.velocity - b.velocity).norm(), b.velocity.norm());
        kinds[1].add(magnitude<Dim>(a.omega - b.omega) * r, magnitude<Dim>(b.omega) * r);
        kinds[2].add((a.force - b.force).norm(), b.force.norm());
        kinds[2].add(magnitude<Dim>(a.torque - b.torque) / r, magnitude<Dim>(b.torque) / r);
    }
    double worst = 0.0;
    for (const Kind& kind : kinds) {
        if (kind.largest > 0.0) {
            worst = std::max(worst, kind.worst / kind.largest);
        }
    }
    return whole.empty() ? 0.0 : split.empty() ? 1.0 : worst;
}

/// The largest difference of the bodies' λ and λ* at any marker, relative to the largest |λ|
/// of the one-process run.
template <int Dim>
double marker_force_difference(const Particles<Dim>& split, const Particles<Dim>& whole)
{
    double worst = 0.0;
    double largest = 0.0;
    for (std::size_t k = 0; k < whole.size(); ++k) {
        const MarkerCoupling<Dim>& a = split[k].coupling;
        const MarkerCoupling<Dim>& b = whole[k].coupling;
        for (std::size_t l = 0; l < b.lambda.size(); ++l) {
            worst = std::max({worst, (a.lambda[l] - b.lambda[l]).norm(),
                              (a.lambda_star[l] - b.lambda_star[l]).norm()});
            largest = std::max(largest, b.lambda[l].norm());
        }
    }
    return largest > 0.0 ? worst / largest : worst;
}

/// The largest difference between the two runs' forcing gains (coupling.normalised_forcing;
/// both empty without it), or infinity when a body's gain lists differ in length.
template <int Dim>
double gain_difference(const Particles<Dim>& split, const Particles<Dim>& whole,
                       const MacGrid<Dim>& split_grid)
{
    double worst = 0.0;
    for (std::size_t k = 0; k < whole.size(); ++k) {
        if (!holds_markers_of(split_grid, split[k])) {
            continue; // this rank neither owns the body nor holds any of its markers
        }
        const std::vector<Vec<Dim>>& a = split[k].coupling.gains;
        const std::vector<Vec<Dim>>& b = whole[k].coupling.gains;
        if (a.size() != b.size()) {
            return std::numeric_limits<double>::infinity();
        }
        for (std::size_t l = 0; l < b.size(); ++l) {
            worst = std::max(worst, (a[l] - b[l]).cwiseAbs().maxCoeff());
        }
    }
    return worst;
}

} // namespace fddem::test
