// SPDX-License-Identifier: MIT
// The fluid inside a body over the cells it covers (coupling/inner_fluid.hpp) on a grid split
// across MPI ranks: each face is counted by the one rank that owns it, so the sum over the ranks
// is the one-process integral to round-off, for a body across rank faces and one across a
// periodic seam. Run under mpirun -n 1, 2 and 4.

#include "fddem/coupling/inner_fluid.hpp"
#include "fddem/grid/grid_partition.hpp"
#include "fddem/grid/loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

namespace fddem {
namespace {

template <class T>
class SplitInnerFluidTest : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SplitInnerFluidTest, Dimensions);

/// A smooth velocity with no symmetry about the bodies, on every face `grid` stores.
template <int Dim>
FaceField<Dim> smooth_field(const MacGrid<Dim>& grid)
{
    FaceField<Dim> u(grid);
    for (int a = 0; a < Dim; ++a) {
        // Every stored face, ghosts too (as a halo fill leaves them): a face counted by a rank
        // that does not own it would then count twice.
        const Box<Dim> faces = grid.storage_box();
        for_each_cell_in_vtk_order<Dim>(faces, [&](const Index<Dim>& i) {
            const Vec<Dim> x = grid.face_centre(a, i);
            double value = 1.0 + a;
            for (int d = 0; d < Dim; ++d) {
                value += std::sin(2.0 * (d + 1) * x[d] + 0.3 * a);
            }
            u[a](i) = value;
        });
    }
    return u;
}

template <int Dim>
Particle<Dim> ball_at(const Vec<Dim>& centre, double diameter)
{
    Particle<Dim> p;
    p.shape = Ball<Dim>{diameter};
    p.centre = centre;
    return p;
}

TYPED_TEST(SplitInnerFluidTest, EveryFaceIsCountedOnceByTheRankThatOwnsIt)
{
    constexpr int Dim = TypeParam::value;
    const Communicator world = Communicator::world();
    Index<Dim> cells;
    cells.fill(24);
    const Vec<Dim> origin = Vec<Dim>::Zero();
    const Vec<Dim> length = Vec<Dim>::Ones();
    std::array<bool, Dim> periodic{};
    periodic[0] = true; // the seam x = 0 ≡ 1
    // Slabs along x (so the seam is a rank face too), then the automatic layout.
    Index<Dim> slabs;
    slabs.fill(1);
    slabs[0] = world.size();
    for (const Index<Dim>& ranks : {slabs, choose_rank_layout<Dim>(cells, world.size())}) {
        const MacGrid<Dim> whole(cells, origin, length, periodic);
        const MacGrid<Dim> split(cells, origin, length, periodic,
                                 partition_grid<Dim>(world, cells, periodic, ranks));
        const FaceField<Dim> u_whole = smooth_field<Dim>(whole);
        const FaceField<Dim> u_split = smooth_field<Dim>(split);
        // Across the middle (a rank face of the slabs), across the seam, and off both.
        std::vector<Particle<Dim>> bodies{ball_at<Dim>(Vec<Dim>::Constant(0.51), 0.3),
                                          ball_at<Dim>(Vec<Dim>::Constant(0.02), 0.25),
                                          ball_at<Dim>(Vec<Dim>::Constant(0.27), 0.2)};
        const std::vector<std::size_t> members{0, 1, 2};
        const auto one = inner_fluid_of<Dim>(bodies, members, whole, u_whole);
        const auto many = inner_fluid_of<Dim>(bodies, members, split, u_split);
        for (std::size_t b = 0; b < members.size(); ++b) {
            const double scale = one[b].momentum.norm();
            EXPECT_GT(scale, 0.5 * bodies[b].volume()) << b; // the integrand is about 1 or more
            EXPECT_LE((many[b].momentum - one[b].momentum).norm(), 1e-13 * scale) << b;
            EXPECT_LE(magnitude<Dim>(AngularVec<Dim>(many[b].moment - one[b].moment)),
                      1e-13 * scale * bodies[b].radius())
                << b;
        }
    }
}

} // namespace
} // namespace fddem
