// SPDX-License-Identifier: MIT
// coupling.adjoint_at_walls: spreading folded back through the walls' ghost fill
// (fluid/boundary_conditions.hpp, fold_wall_ghosts) is the exact adjoint of interpolating a
// ghost-filled field, so that a marker beside a wall is coupled to the fluid through a
// symmetric, non-negative I·D. Without the fold the coupling of a marker within h/6 of a wall
// turns negative along the wall: the forcing then feeds the slip it corrects (docs/method.md §5,
// the stall in contact).
#include "fddem/coupling/transfer.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <type_traits>
#include <vector>

namespace fddem {
namespace {

template <class T>
class WallFold : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(WallFold, Dimensions);

constexpr int n_cells = 8; // h = 1/8 on the unit box

/// Periodic along axis 0; axis 1 a wall below and an outflow above; in 3D axis 2 an inflow
/// (at rest, so that the fill is linear) below and a wall above: every kind of side.
template <int Dim>
std::pair<MacGrid<Dim>, BoundaryConditions<Dim>> mixed_box(int n = n_cells)
{
    BoundaryConditions<Dim> bc = BoundaryConditions<Dim>::closed_box();
    bc.is_periodic[0] = true;
    bc.kind[1][1] = BoundaryKind::outflow;
    if constexpr (Dim == 3) {
        bc.kind[2][0] = BoundaryKind::inflow;
    }
    Index<Dim> cells{};
    cells.fill(n);
    return {MacGrid<Dim>(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones(), bc.is_periodic), bc};
}

/// The entries fill_velocity_ghosts reads and does not set: the owned faces but the wall and
/// inflow faces (an outflow face is read by its ghosts and left as it is).
template <int Dim>
bool is_free(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, int a,
             const Index<Dim>& i)
{
    if (!grid.owned_faces(a).contains(i)) {
        return false;
    }
    const auto ax = static_cast<std::size_t>(a);
    if (bc.periodic(a)) {
        return true;
    }
    for (int side = 0; side < 2; ++side) {
        const int face = side == 0 ? 0 : grid.cells(a);
        if (i[ax] == face && bc.side_kind(a, side) != BoundaryKind::outflow) {
            return false;
        }
    }
    return true;
}

/// Every stored entry of every component drawn from U(−1, 1), ghosts included.
template <int Dim>
FaceField<Dim> random_field(const MacGrid<Dim>& grid, std::mt19937& rng)
{
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    FaceField<Dim> f(grid);
    for_each_index(grid.storage_box(), [&](const Index<Dim>& i) {
        for (int a = 0; a < Dim; ++a) {
            f[a](i) = value(rng);
        }
    });
    return f;
}

TYPED_TEST(WallFold, IsTheTransposeOfTheGhostFill)
{
    constexpr int Dim = TypeParam::value;
    const auto [grid, bc] = mixed_box<Dim>();
    std::mt19937 rng(5);
    const FaceField<Dim> v = random_field(grid, rng);
    const FaceField<Dim> f = random_field(grid, rng);
    FaceField<Dim> filled = v;
    fill_velocity_ghosts(grid, bc, filled); // G v
    FaceField<Dim> folded = f;
    fold_wall_ghosts(grid, bc, folded); // G^T f: the walls' transpose, then the periodic one
    HaloExchange<Dim>(grid).accumulate(folded);
    double lhs = 0.0; // ⟨G v, f⟩ over every stored entry
    double rhs = 0.0; // ⟨v, G^T f⟩ over the free entries
    double scale = 0.0;
    for_each_index(grid.storage_box(), [&](const Index<Dim>& i) {
        for (int a = 0; a < Dim; ++a) {
            lhs += filled[a](i) * f[a](i);
            scale += std::abs(filled[a](i) * f[a](i));
            if (is_free<Dim>(grid, bc, a, i)) {
                rhs += v[a](i) * folded[a](i);
            }
        }
    });
    EXPECT_NEAR(lhs, rhs, 1e-13 * scale);
    // And a wall's ghosts are left at zero, for the next spreading.
    const Index<Dim> below = with_axis(Index<Dim>{}, 1, -1);
    EXPECT_EQ(folded[0](below), 0.0);
}

/// Spreads `forces` at `positions` into a copy of `u` with the wall adjoint's zero, fold and
/// fill, over whole sides (window nullptr) or within a window.
template <int Dim, class Kernel>
FaceField<Dim> spread_with_adjoint(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                   const FaceField<Dim>& u, const std::vector<Vec<Dim>>& positions,
                                   const std::vector<Vec<Dim>>& forces, const Box<Dim>* window)
{
    FaceField<Dim> f = u;
    zero_wall_ghosts(grid, bc, f, window);
    for (std::size_t m = 0; m < positions.size(); ++m) {
        spread_vector<Dim, Kernel>(grid, f, positions[m], forces[m], 0.01);
    }
    fold_wall_ghosts(grid, bc, f, window);
    HaloExchange<Dim>(grid).accumulate(f);
    fill_velocity_ghosts(grid, bc, f, window);
    return f;
}

TYPED_TEST(WallFold, OnlyTheWindowAroundTheMarkersGivesTheWholeSidesResult)
{
    // The sequential sweep zeroes, folds and fills the sides only within support_window of a
    // body's markers (coupling/rigid_update.cpp): for markers beside a wall, beside a moving lid,
    // in edges and corners where two walls meet, beside the outflow and far from every side,
    // the spreading of eq. (16) must leave every stored entry as the whole sides' zero, fold and
    // fill do, bit for bit (signs of zero included). Two boxes: the mixed one (periodic along x)
    // and a closed one whose lid (y high) and, in 3D, floor (z low) slide.
    constexpr int Dim = TypeParam::value;
    using Kernel = Peskin4Kernel;
    auto [mixed_grid, mixed_bc] = mixed_box<Dim>(24);
    BoundaryConditions<Dim> closed = BoundaryConditions<Dim>::closed_box();
    closed.wall_velocity[1][1][0] = 1.0;
    if constexpr (Dim == 3) {
        closed.wall_velocity[2][0][1] = -0.5;
    }
    Index<Dim> cells{};
    cells.fill(24);
    const MacGrid<Dim> closed_grid(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones());
    std::vector<Vec<Dim>> centres(7, Vec<Dim>::Constant(0.5));
    centres[1][1] = 0.03;                  // beside the wall below (mixed: a wall)
    centres[2][1] = 0.975;                 // beside the lid, or the outflow
    centres[3] = Vec<Dim>::Constant(0.04); // a corner
    centres[4][0] = 0.96;                  // beside the wall at x high (mixed: the seam)
    centres[5][Dim - 1] = 0.03;            // beside the last axis's low side
    centres[6] = Vec<Dim>::Constant(0.5);  // an edge: x high, last axis low
    centres[6][0] = 0.965;
    centres[6][Dim - 1] = 0.035;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> offset(-0.05, 0.05);
    std::uniform_real_distribution<double> force(-1.0, 1.0);
    for (const bool is_closed : {false, true}) {
        const MacGrid<Dim>& grid = is_closed ? closed_grid : mixed_grid;
        const BoundaryConditions<Dim>& bc = is_closed ? closed : mixed_bc;
        FaceField<Dim> u = random_field(grid, rng);
        fill_velocity_ghosts(grid, bc, u); // a field as a step leaves it
        int n_windowed = 0;                // clusters whose window is smaller than the storage
        for (const Vec<Dim>& centre : centres) {
            std::vector<Vec<Dim>> positions(10);
            std::vector<Vec<Dim>> forces(positions.size());
            for (std::size_t m = 0; m < positions.size(); ++m) {
                for (int d = 0; d < Dim; ++d) {
                    positions[m][d] = std::clamp(centre[d] + offset(rng), 0.001, 0.999);
                    forces[m][d] = force(rng);
                }
            }
            const Box<Dim> window = support_window<Dim, Kernel>(grid, positions);
            n_windowed += window.size() < grid.storage_box().size() ? 1 : 0;
            const FaceField<Dim> whole =
                spread_with_adjoint<Dim, Kernel>(grid, bc, u, positions, forces, nullptr);
            const FaceField<Dim> part =
                spread_with_adjoint<Dim, Kernel>(grid, bc, u, positions, forces, &window);
            int n_different = 0;
            int n_changed = 0;
            for_each_index(grid.storage_box(), [&](const Index<Dim>& i) {
                for (int a = 0; a < Dim; ++a) {
                    n_different += std::bit_cast<std::uint64_t>(part[a](i)) ==
                                           std::bit_cast<std::uint64_t>(whole[a](i))
                                       ? 0
                                       : 1;
                    n_changed += whole[a](i) == u[a](i) ? 0 : 1;
                }
            });
            EXPECT_EQ(n_different, 0) << (is_closed ? "closed box" : "mixed box")
                                      << ", markers about " << centre.transpose();
            EXPECT_GT(n_changed, 0);
        }
        EXPECT_GE(n_windowed, 5); // the window does leave parts of the sides out
    }
}

TYPED_TEST(WallFold, ZeroedGhostsFoldNothingIntoTheFluid)
{
    // Before spreading into u (whose ghosts hold the boundary values) the walls' ghosts are
    // zeroed: every ghost the fold reads must be among them, or stale boundary values would be
    // folded into the fluid. And zeroing changes nothing the fill reads.
    constexpr int Dim = TypeParam::value;
    const auto [grid, bc] = mixed_box<Dim>();
    std::mt19937 rng(7);
    const FaceField<Dim> u = random_field(grid, rng);
    FaceField<Dim> zeroed = u;
    zero_wall_ghosts(grid, bc, zeroed);
    FaceField<Dim> folded = zeroed;
    fold_wall_ghosts(grid, bc, folded);
    FaceField<Dim> filled = u;
    fill_velocity_ghosts(grid, bc, filled);
    FaceField<Dim> filled_after_zeroing = zeroed;
    fill_velocity_ghosts(grid, bc, filled_after_zeroing);
    int zeroed_entries = 0;
    for_each_index(grid.storage_box(), [&](const Index<Dim>& i) {
        for (int a = 0; a < Dim; ++a) {
            if (is_free<Dim>(grid, bc, a, i)) {
                EXPECT_EQ(folded[a](i), u[a](i));
            }
            EXPECT_EQ(filled_after_zeroing[a](i), filled[a](i));
            zeroed_entries += zeroed[a](i) == 0.0 && u[a](i) != 0.0 ? 1 : 0;
        }
    });
    EXPECT_GT(zeroed_entries, 0);
}

/// Eq. (16) for a unit force at `x` along `component` (marker volume one cell), then I at
/// `y` along `along`: the entry of I·D that couples the two markers. With `walls`, the spreading
/// is folded back through their ghost fill; without, what lands in a wall's ghosts is dropped
/// (the fill overwrites it).
template <int Dim, class Kernel>
double coupling(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc, bool is_folded,
                const Vec<Dim>& x, int component, const Vec<Dim>& y, int along)
{
    FaceField<Dim> u(grid);
    Vec<Dim> force = Vec<Dim>::Zero();
    force[component] = 1.0;
    spread_vector<Dim, Kernel>(grid, u, x, force, grid.cell_volume());
    if (is_folded) {
        fold_wall_ghosts(grid, bc, u);
    }
    HaloExchange<Dim>(grid).accumulate(u);
    fill_velocity_ghosts(grid, bc, u);
    return interpolate_component<Dim, Kernel>(grid, u[along], along, y);
}

/// A marker at height s h above the floor (axis 1's low wall) of a closed box, in its middle
/// otherwise.
template <int Dim>
Vec<Dim> above_floor(double s)
{
    Vec<Dim> x = Vec<Dim>::Constant(0.5 + 0.3 / n_cells);
    x[1] = s / n_cells;
    return x;
}

template <int Dim, class Kernel>
void check_wall_coupling()
{
    const auto bc = BoundaryConditions<Dim>::closed_box();
    Index<Dim> cells{};
    cells.fill(n_cells);
    const MacGrid<Dim> grid(cells, Vec<Dim>::Zero(), Vec<Dim>::Ones());
    // From 0.45 h below the floor (a body pressed into it) to beyond the kernel's reach.
    const std::vector<double> heights{-0.45, -0.3, -0.1, 0.0, 0.05, 0.1, 0.15,
                                      0.2,   0.3,  0.5,  0.8, 1.2,  1.7, 2.5};
    double lowest_dropped = 1.0;
    for (const double s : heights) {
        const Vec<Dim> x = above_floor<Dim>(s);
        for (int a = 0; a < Dim; ++a) {
            const double folded = coupling<Dim, Kernel>(grid, bc, true, x, a, x, a);
            const double dropped = coupling<Dim, Kernel>(grid, bc, false, x, a, x, a);
            SCOPED_TRACE(::testing::Message() << "height " << s << " h, component " << a);
            EXPECT_GE(folded,
                      -1e-14); // zero, to round-off, where the kernel reaches only a wall face
            lowest_dropped = std::min(lowest_dropped, dropped);
            if (s >= Kernel::half_width) {
                EXPECT_EQ(folded, dropped); // beyond the kernel's reach nothing changes
                EXPECT_GT(folded, 0.0);
            }
        }
    }
    // The mechanism the fold removes: dropped, a marker close to the floor reads its own force
    // with the sign turned along the wall.
    EXPECT_LT(lowest_dropped, -0.01);
    // Symmetric: marker 1's force read at marker 2 is marker 2's read at marker 1, with the
    // fold (and not without it, beside the wall).
    const Vec<Dim> x1 = above_floor<Dim>(0.1);
    Vec<Dim> x2 = above_floor<Dim>(0.7);
    x2[0] += 0.4 / n_cells;
    const double c12 = coupling<Dim, Kernel>(grid, bc, true, x1, 0, x2, 0);
    const double c21 = coupling<Dim, Kernel>(grid, bc, true, x2, 0, x1, 0);
    EXPECT_NEAR(c12, c21, 1e-14);
    const double d12 = coupling<Dim, Kernel>(grid, bc, false, x1, 0, x2, 0);
    const double d21 = coupling<Dim, Kernel>(grid, bc, false, x2, 0, x1, 0);
    EXPECT_GT(std::abs(d12 - d21), 1e-3);
}

TYPED_TEST(WallFold, MakesTheCouplingBesideAWallSymmetricAndNonNegative)
{
    constexpr int Dim = TypeParam::value;
    check_wall_coupling<Dim, HatKernel>();
    check_wall_coupling<Dim, RomaPeskin3Kernel>();
    check_wall_coupling<Dim, Peskin4Kernel>();
}

} // namespace
} // namespace fddem
