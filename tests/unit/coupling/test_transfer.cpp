// SPDX-License-Identifier: MIT
#include "fddem/coupling/transfer.hpp"
#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>

namespace fddem {
namespace {

template <class T>
class Transfer : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Transfer, Dimensions);

template <int Dim>
MacGrid<Dim> grid_for_test()
{
    Index<Dim> cells{};
    Vec<Dim> length;
    for (int d = 0; d < Dim; ++d) {
        cells[static_cast<std::size_t>(d)] = 10;
        length[d] = 1.0;
    }
    return MacGrid<Dim>(cells, Vec<Dim>::Zero(), length);
}

TYPED_TEST(Transfer, HatInterpolationIsExactForLinearFields)
{
    constexpr int Dim = TypeParam::value;
    const auto grid = grid_for_test<Dim>();
    FaceField<Dim> u(grid);
    const Vec<Dim> g = Vec<Dim>::LinSpaced(0.5, 2.0);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            u[a](c) = a + g.dot(grid.face_centre(a, c));
        }
    });
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(0.2, 0.8);
    for (int k = 0; k < 100; ++k) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
            x[d] = coordinate(rng);
        }
        const Vec<Dim> v = interpolate_velocity<Dim, HatKernel>(grid, u, x);
        for (int a = 0; a < Dim; ++a) {
            EXPECT_NEAR(v[a], a + g.dot(x), 1e-12);
        }
    }
}

template <int Dim, class Kernel>
void check_adjoint_and_conservation()
{
    const auto grid = grid_for_test<Dim>();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_real_distribution<double> coordinate(0.3, 0.7);
    FaceField<Dim> u(grid);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            u[a](c) = value(rng);
        }
    });
    FaceField<Dim> spread(grid);
    double lagrangian = 0.0;
    Vec<Dim> total = Vec<Dim>::Zero();
    for (int l = 0; l < 20; ++l) {
        Vec<Dim> x;
        Vec<Dim> f;
        for (int d = 0; d < Dim; ++d) {
            x[d] = coordinate(rng);
            f[d] = value(rng);
        }
        const double volume = 0.001 * (1 + l);
        spread_vector<Dim, Kernel>(grid, spread, x, f, volume);
        lagrangian += volume * f.dot(interpolate_velocity<Dim, Kernel>(grid, u, x));
        total += volume * f;
    }
    double eulerian = 0.0;
    Vec<Dim> spread_total = Vec<Dim>::Zero();
    for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& c) {
        for (int a = 0; a < Dim; ++a) {
            eulerian += spread[a](c) * u[a](c) * grid.cell_volume();
            spread_total[a] += spread[a](c) * grid.cell_volume();
        }
    });
    // ⟨D F, u⟩ = ⟨F, I u⟩ with the ΔV weights: the same sums in another order.
    EXPECT_NEAR(eulerian, lagrangian, 1e-12 * std::abs(lagrangian) + 1e-15);
    // Momentum added by eq. (16) is Σ ΔV_l F_l exactly (partition of unity).
    EXPECT_LT((spread_total - total).norm(), 1e-14);
}

TYPED_TEST(Transfer, SpreadIsTheAdjointOfInterpolationAndConservesMomentum)
{
    constexpr int Dim = TypeParam::value;
    check_adjoint_and_conservation<Dim, HatKernel>();
    check_adjoint_and_conservation<Dim, RomaPeskin3Kernel>();
    check_adjoint_and_conservation<Dim, Peskin4Kernel>();
}

// Across a periodic seam (grid/halo_exchange.hpp): spreading into the ghosts and accumulating,
// and interpolating after a fill, give what the same marker gives away from the seam. The grid
// spacing and the marker positions are dyadic, so the kernel weights at the seam and away from
// it are the same doubles and the comparisons are exact.

constexpr int seam_cells = 8; // h = 1/8 on the unit box
constexpr int seam_shift = 3; // cells: a marker moved by 3 h is away from every seam

template <int Dim>
MacGrid<Dim> seam_grid(const std::array<bool, Dim>& periodic)
{
    Index<Dim> cells{};
    cells.fill(seam_cells);
    return MacGrid<Dim>(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic);
}

/// Doubly (triply) periodic, and periodic along axis 0 only.
template <int Dim>
std::vector<std::array<bool, Dim>> seam_layouts()
{
    std::array<bool, Dim> all{};
    all.fill(true);
    std::array<bool, Dim> first{};
    first[0] = true;
    return {all, first};
}

/// A point a quarter cell above the low side along every periodic axis (its kernel support
/// straddles the seam: a corner of a doubly periodic box) and mid-box along the others.
template <int Dim>
Vec<Dim> at_seam(const MacGrid<Dim>& grid)
{
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) {
        x[d] = grid.is_periodic(d) ? 0.25 * grid.spacing(d) : 0.5;
    }
    return x;
}

/// `x` moved by `cells` cells along every periodic axis.
template <int Dim>
Vec<Dim> shifted(const MacGrid<Dim>& grid, Vec<Dim> x, int cells)
{
    for (int d = 0; d < Dim; ++d) {
        if (grid.is_periodic(d)) {
            x[d] += cells * grid.spacing(d);
        }
    }
    return x;
}

/// The owned index `cells` cells further along every periodic axis, wrapped.
template <int Dim>
Index<Dim> shifted_index(const MacGrid<Dim>& grid, Index<Dim> i, int cells)
{
    for (int d = 0; d < Dim; ++d) {
        if (grid.is_periodic(d)) {
            auto& x = i[static_cast<std::size_t>(d)];
            x = (x + cells) % grid.cells(d);
        }
    }
    return i;
}

/// D for one marker (value `f`, volume ΔV), ghosts accumulated onto their owners.
template <int Dim, class Kernel>
FaceField<Dim> spread_and_accumulate(const MacGrid<Dim>& grid, const Vec<Dim>& x, const Vec<Dim>& f,
                                     double volume)
{
    FaceField<Dim> field(grid);
    spread_vector<Dim, Kernel>(grid, field, x, f, volume);
    HaloExchange<Dim>(grid).accumulate(field);
    return field;
}

template <int Dim, class Kernel>
void check_spreading_is_seam_invariant()
{
    const Vec<Dim> f = Vec<Dim>::LinSpaced(1.0, 2.0);
    for (const auto& periodic : seam_layouts<Dim>()) {
        const auto grid = seam_grid<Dim>(periodic);
        const Vec<Dim> x = at_seam(grid);
        const FaceField<Dim> seam = spread_and_accumulate<Dim, Kernel>(grid, x, f, 0.01);
        const FaceField<Dim> away =
            spread_and_accumulate<Dim, Kernel>(grid, shifted(grid, x, seam_shift), f, 0.01);
        // The marker's image one period up along axis 0 (outside the box, in the ghosts).
        Vec<Dim> image = x;
        image[0] += grid.length()[0];
        const FaceField<Dim> above = spread_and_accumulate<Dim, Kernel>(grid, image, f, 0.01);
        for (int a = 0; a < Dim; ++a) {
            Vec<Dim> total = Vec<Dim>::Zero();
            for_each_cell_in_vtk_order(grid.owned_faces(a), [&](const Index<Dim>& i) {
                EXPECT_EQ(seam[a](i), away[a](shifted_index<Dim>(grid, i, seam_shift)));
                EXPECT_EQ(seam[a](i), above[a](i));
                total[a] += seam[a](i) * grid.cell_volume();
            });
            // Nothing is lost in the ghosts: the owned faces hold f ΔV (partition of unity).
            EXPECT_NEAR(total[a], 0.01 * f[a], 1e-15);
        }
    }
}

TYPED_TEST(Transfer, SpreadingAcrossAPeriodicSeamGivesWhatItGivesAwayFromIt)
{
    constexpr int Dim = TypeParam::value;
    check_spreading_is_seam_invariant<Dim, HatKernel>();
    check_spreading_is_seam_invariant<Dim, RomaPeskin3Kernel>();
    check_spreading_is_seam_invariant<Dim, Peskin4Kernel>();
}

template <int Dim, class Kernel>
void check_interpolation_is_seam_invariant()
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (const auto& periodic : seam_layouts<Dim>()) {
        const auto grid = seam_grid<Dim>(periodic);
        const HaloExchange<Dim> halo(grid);
        // A random field, and the same field moved by seam_shift cells.
        FaceField<Dim> u(grid);
        FaceField<Dim> moved(grid);
        for (int a = 0; a < Dim; ++a) {
            for_each_cell_in_vtk_order(grid.storage_box(),
                                       [&](const Index<Dim>& i) { u[a](i) = value(rng); });
            for_each_cell_in_vtk_order(grid.owned_faces(a), [&](const Index<Dim>& i) {
                moved[a](shifted_index<Dim>(grid, i, seam_shift)) = u[a](i);
            });
        }
        halo.fill(u);
        halo.fill(moved);
        const Vec<Dim> x = at_seam(grid);
        Vec<Dim> image = x;
        image[0] += grid.length()[0];
        const Vec<Dim> at = interpolate_velocity<Dim, Kernel>(grid, u, x);
        EXPECT_EQ(at,
                  (interpolate_velocity<Dim, Kernel>(grid, moved, shifted(grid, x, seam_shift))));
        EXPECT_EQ(at, (interpolate_velocity<Dim, Kernel>(grid, u, image)));
    }
}

TYPED_TEST(Transfer, InterpolationAcrossAPeriodicSeamIsTheInterpolationAwayFromIt)
{
    constexpr int Dim = TypeParam::value;
    check_interpolation_is_seam_invariant<Dim, HatKernel>();
    check_interpolation_is_seam_invariant<Dim, RomaPeskin3Kernel>();
    check_interpolation_is_seam_invariant<Dim, Peskin4Kernel>();
}

template <int Dim, class Kernel>
void check_adjoint_across_the_seam()
{
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& periodic : seam_layouts<Dim>()) {
        const auto grid = seam_grid<Dim>(periodic);
        const HaloExchange<Dim> halo(grid);
        FaceField<Dim> u(grid);
        for (int a = 0; a < Dim; ++a) {
            for_each_cell_in_vtk_order(grid.owned_faces(a),
                                       [&](const Index<Dim>& i) { u[a](i) = value(rng); });
        }
        halo.fill(u); // I reads the periodic ghosts; the walled ones stay zero
        FaceField<Dim> spread(grid);
        double lagrangian = 0.0;
        for (int l = 0; l < 20; ++l) {
            // Anywhere along periodic axes (seams included), away from the walls elsewhere.
            Vec<Dim> x;
            Vec<Dim> f;
            for (int d = 0; d < Dim; ++d) {
                x[d] = grid.is_periodic(d) ? unit(rng) : 0.3 + 0.4 * unit(rng);
                f[d] = value(rng);
            }
            const double volume = 0.001 * (1 + l);
            spread_vector<Dim, Kernel>(grid, spread, x, f, volume);
            lagrangian += volume * f.dot(interpolate_velocity<Dim, Kernel>(grid, u, x));
        }
        halo.accumulate(spread);
        double eulerian = 0.0;
        for (int a = 0; a < Dim; ++a) {
            for_each_cell_in_vtk_order(grid.owned_faces(a), [&](const Index<Dim>& i) {
                eulerian += spread[a](i) * u[a](i) * grid.cell_volume();
            });
        }
        // ⟨accumulate D F, u⟩ over the owned faces = ⟨F, I fill u⟩: the same sums in another order.
        EXPECT_NEAR(eulerian, lagrangian, 1e-12 * std::abs(lagrangian));
    }
}

TYPED_TEST(Transfer, SpreadAndAccumulateIsTheAdjointOfFillAndInterpolate)
{
    constexpr int Dim = TypeParam::value;
    check_adjoint_across_the_seam<Dim, HatKernel>();
    check_adjoint_across_the_seam<Dim, RomaPeskin3Kernel>();
    check_adjoint_across_the_seam<Dim, Peskin4Kernel>();
}

} // namespace
} // namespace fddem
