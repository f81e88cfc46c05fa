// SPDX-License-Identifier: MIT
// The halo seam (grid/halo_exchange.hpp) on one process: fill makes every ghost across a
// periodic axis the image of its owner and touches nothing else; accumulate is fill's adjoint
// (⟨fill x, y⟩ = ⟨x, accumulate y⟩ over all entries, exactly), keeps the sum of all entries and
// leaves the image ghosts zero; zero_ghosts clears exactly the entries fill writes. Checked for
// every combination of periodic axes in 2D and 3D, with axes of 1, 2 and 5 cells (fewer cells
// than ghost layers: several ghosts share one owner). Integer values make every sum exact.

#include "fddem/core/errors.hpp"
#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>
#include <vector>

#include "support/storage_sums.hpp"

namespace fddem {
namespace {

template <class T>
class HaloExchangeTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(HaloExchangeTest, Dimensions);

/// Every combination of periodic axes (bit d of the code: axis d periodic), each with a grid of
/// `cells` per axis.
template <int Dim>
std::vector<MacGrid<Dim>> grids_with(const Index<Dim>& cells)
{
    std::vector<MacGrid<Dim>> grids;
    for (int code = 0; code < (1 << Dim); ++code) {
        std::array<bool, Dim> periodic{};
        for (int d = 0; d < Dim; ++d) {
            periodic[static_cast<std::size_t>(d)] = ((code >> d) & 1) != 0;
        }
        grids.emplace_back(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), periodic);
    }
    return grids;
}

template <int Dim>
std::vector<MacGrid<Dim>> test_grids()
{
    Index<Dim> mixed{};
    for (int d = 0; d < Dim; ++d) {
        mixed[static_cast<std::size_t>(d)] = d == 0 ? 5 : d; // 5, 1 (, 2)
    }
    Index<Dim> regular{};
    regular.fill(4);
    auto grids = grids_with<Dim>(mixed);
    for (auto& g : grids_with<Dim>(regular)) {
        grids.push_back(g);
    }
    return grids;
}

/// The index whose image `i` is: i mod n along each periodic axis, unchanged along the others.
template <int Dim>
Index<Dim> owner_of(const MacGrid<Dim>& grid, Index<Dim> i)
{
    for (int d = 0; d < Dim; ++d) {
        if (grid.is_periodic(d)) {
            const int n = grid.cells(d);
            auto& x = i[static_cast<std::size_t>(d)];
            x = ((x % n) + n) % n;
        }
    }
    return i;
}

template <int Dim>
GridArray<Dim> random_integers(const MacGrid<Dim>& grid, std::mt19937& rng)
{
    std::uniform_int_distribution<int> value(-50, 50);
    GridArray<Dim> a(grid);
    for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) { a(i) = value(rng); });
    return a;
}

TYPED_TEST(HaloExchangeTest, FillMakesEveryPeriodicGhostTheImageOfItsOwnerAndKeepsTheRest)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(1);
    for (const MacGrid<Dim>& grid : test_grids<Dim>()) {
        const GridArray<Dim> before = random_integers(grid, rng);
        GridArray<Dim> a = before;
        HaloExchange<Dim>(grid).fill(a);
        int n_images = 0;
        for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) {
            const Index<Dim> owner = owner_of<Dim>(grid, i);
            // Owners (and ghosts across walled sides) keep their values; images take them.
            EXPECT_EQ(a(i), before(owner));
            n_images += owner != i ? 1 : 0;
        });
        EXPECT_EQ(n_images > 0, grid.domain().has_periodic_axis());
    }
}

TYPED_TEST(HaloExchangeTest, AccumulateIsTheAdjointOfFill)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(2);
    for (const MacGrid<Dim>& grid : test_grids<Dim>()) {
        const HaloExchange<Dim> halo(grid);
        const GridArray<Dim> x = random_integers(grid, rng);
        const GridArray<Dim> y = random_integers(grid, rng);
        GridArray<Dim> filled = x;
        halo.fill(filled);
        GridArray<Dim> accumulated = y;
        halo.accumulate(accumulated);
        EXPECT_EQ(test::storage_dot(grid, filled, y), test::storage_dot(grid, x, accumulated));
        // Not trivially: with periodic axes both differ from ⟨x, y⟩.
        if (grid.domain().has_periodic_axis()) {
            EXPECT_NE(test::storage_dot(grid, filled, y), test::storage_dot(grid, x, y));
        }
    }
}

TYPED_TEST(HaloExchangeTest, AccumulateAddsEveryImageToItsOwnerZeroesItAndKeepsTheSum)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(3);
    for (const MacGrid<Dim>& grid : test_grids<Dim>()) {
        const GridArray<Dim> before = random_integers(grid, rng);
        // What each owner must receive: its own value and those of all its images.
        GridArray<Dim> expected(grid);
        for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) {
            expected(owner_of<Dim>(grid, i)) += before(i);
        });
        GridArray<Dim> a = before;
        HaloExchange<Dim>(grid).accumulate(a);
        for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) {
            EXPECT_EQ(a(i), owner_of<Dim>(grid, i) == i ? expected(i) : 0.0);
        });
        EXPECT_EQ(test::storage_total(grid, a), test::storage_total(grid, before));
    }
}

TYPED_TEST(HaloExchangeTest, ZeroGhostsClearsExactlyWhatFillWrites)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(5);
    for (const MacGrid<Dim>& grid : test_grids<Dim>()) {
        FaceField<Dim> u(grid);
        for (int a = 0; a < Dim; ++a) {
            u[a] = random_integers(grid, rng);
        }
        const FaceField<Dim> before = u;
        HaloExchange<Dim>(grid).zero_ghosts(u);
        for (int a = 0; a < Dim; ++a) {
            for_each_cell_in_vtk_order(grid.storage_box(), [&](const Index<Dim>& i) {
                EXPECT_EQ(u[a](i), owner_of<Dim>(grid, i) == i ? before[a](i) : 0.0);
            });
        }
    }
}

TYPED_TEST(HaloExchangeTest, FillPlaneOverEverySliceThenFillAlongTheLastAxisIsFill)
{
    constexpr int Dim = TypeParam::value;
    std::mt19937 rng(6);
    for (const MacGrid<Dim>& grid : test_grids<Dim>()) {
        const HaloExchange<Dim> halo(grid);
        ASSERT_TRUE(halo.keeps_slices_apart()); // one process: nothing is split
        GridArray<Dim> a = random_integers(grid, rng);
        GridArray<Dim> by_slices = a;
        const Box<Dim> storage = grid.storage_box();
        for (int k = storage.lo[Dim - 1]; k < storage.hi[Dim - 1]; ++k) {
            const GridArray<Dim> before = by_slices;
            halo.fill_plane(by_slices, k);
            // Only slice k changes.
            for_each_cell_in_vtk_order(storage, [&](const Index<Dim>& i) {
                if (i[Dim - 1] != k) {
                    EXPECT_EQ(by_slices(i), before(i));
                }
            });
        }
        halo.fill_axis(by_slices, Dim - 1);
        halo.fill(a);
        for_each_cell_in_vtk_order(storage,
                                   [&](const Index<Dim>& i) { EXPECT_EQ(by_slices(i), a(i)); });
    }
}

} // namespace
} // namespace fddem
