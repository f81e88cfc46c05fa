// SPDX-License-Identifier: MIT
#include "fddem/coupling/inner_fluid.hpp"

#include "fddem/grid/loops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace fddem {
namespace {

/// The number of doubles an InnerFluid packs into.
template <int Dim>
constexpr std::size_t packed_size = Dim + (Dim == 3 ? 3 : 1);

template <int Dim>
void pack(const InnerFluid<Dim>& v, double* out)
{
    for (int d = 0; d < Dim; ++d) {
        out[d] = v.momentum[d];
    }
    if constexpr (Dim == 2) {
        out[2] = v.moment;
    } else {
        for (int d = 0; d < 3; ++d) {
            out[3 + d] = v.moment[d];
        }
    }
}

template <int Dim>
InnerFluid<Dim> unpack(const double* in)
{
    InnerFluid<Dim> v;
    for (int d = 0; d < Dim; ++d) {
        v.momentum[d] = in[d];
    }
    if constexpr (Dim == 2) {
        v.moment = in[2];
    } else {
        for (int d = 0; d < 3; ++d) {
            v.moment[d] = in[3 + d];
        }
    }
    return v;
}

} // namespace

template <int Dim>
double ball_volume_fraction(const Vec<Dim>& lo, const Vec<Dim>& size, const Vec<Dim>& centre,
                            double radius) noexcept
{
    double inside = 0.0;
    double total = 0.0;
    for (int corner = 0; corner < (1 << Dim); ++corner) {
        Vec<Dim> x = lo;
        for (int d = 0; d < Dim; ++d) {
            if ((corner >> d) & 1) {
                x[d] += size[d];
            }
        }
        const double phi = (x - centre).norm() - radius; // signed distance, < 0 inside
        inside += std::max(-phi, 0.0);
        total += std::abs(phi);
    }
    return total > 0.0 ? inside / total : 1.0; // every corner on the surface: count it in
}

template <int Dim>
InnerFluid<Dim> inner_fluid_part(const MacGrid<Dim>& grid, const FaceField<Dim>& u,
                                 const Vec<Dim>& centre, double radius)
{
    InnerFluid<Dim> sum;
    if (!centre.allFinite() || !std::isfinite(radius)) {
        // Not reached from a run (place_markers stops a body that is not finite first); NaN
        // rather than a loop over indices cast from NaN.
        sum.momentum.fill(std::nan(""));
        return sum;
    }
    const Vec<Dim>& h = grid.spacing();
    const Vec<Dim>& origin = grid.origin();
    const double cell_volume = grid.cell_volume();
    for (int a = 0; a < Dim; ++a) {
        // Faces normal to a: x_d = origin_d + (i_d + s_d) h_d, s_a = 0 and 1/2 on the other axes;
        // each face's control volume is the cell [x − h/2, x + h/2] about it.
        Vec<Dim> shift = Vec<Dim>::Constant(0.5);
        shift[a] = 0.0;
        // The faces whose control volumes may meet the ball, one more on each side.
        Index<Dim> lo{};
        Index<Dim> hi{}; // past the last
        for (int d = 0; d < Dim; ++d) {
            const auto k = static_cast<std::size_t>(d);
            const double first = (centre[d] - radius - origin[d]) / h[d] - shift[d];
            const double last = (centre[d] + radius - origin[d]) / h[d] - shift[d];
            lo[k] = static_cast<int>(std::floor(first)) - 1;
            hi[k] = static_cast<int>(std::ceil(last)) + 2;
        }
        const Box<Dim> owned = grid.owned_faces(a);
        const GridArray<Dim>& component = u[a];
        // Serially, in a fixed order: the sum is then the same from run to run.
        for_each_cell_in_vtk_order<Dim>(Box<Dim>{lo, hi}, [&](const Index<Dim>& i) {
            Index<Dim> j = i; // the face itself, i its image about the body
            for (int d = 0; d < Dim; ++d) {
                const auto k = static_cast<std::size_t>(d);
                if (grid.is_periodic(d)) {
                    const int n = grid.cells(d);
                    j[k] = ((i[k] % n) + n) % n;
                }
            }
            if (!owned.contains(j)) {
                return; // another rank's, or outside the domain
            }
            Vec<Dim> x;
            for (int d = 0; d < Dim; ++d) {
                x[d] = origin[d] + (i[static_cast<std::size_t>(d)] + shift[d]) * h[d];
            }
            const double alpha = ball_volume_fraction<Dim>(x - 0.5 * h, h, centre, radius);
            if (alpha == 0.0) {
                return;
            }
            Vec<Dim> part = Vec<Dim>::Zero();
            part[a] = alpha * cell_volume * component(j);
            sum.momentum += part;
            sum.moment += cross(Vec<Dim>(x - centre), part);
        });
    }
    return sum;
}

template <int Dim>
std::vector<InnerFluid<Dim>> inner_fluid_of(std::span<const Particle<Dim>> bodies,
                                            std::span<const std::size_t> members,
                                            const MacGrid<Dim>& grid, const FaceField<Dim>& u)
{
    constexpr std::size_t n = packed_size<Dim>;
    std::vector<double> packed(n * members.size(), 0.0);
    for (std::size_t m = 0; m < members.size(); ++m) {
        const Particle<Dim>& body = bodies[members[m]];
        pack<Dim>(inner_fluid_part<Dim>(grid, u, grid.domain().wrap(body.centre), body.radius()),
                  &packed[n * m]);
    }
    grid.communicator().sum(packed); // in rank order; the identity on one process
    std::vector<InnerFluid<Dim>> result(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) {
        result[m] = unpack<Dim>(&packed[n * m]);
    }
    return result;
}

template <int Dim>
void take_inner_fluid_of_free_bodies(std::span<Particle<Dim>> bodies, const MacGrid<Dim>& grid,
                                     const FaceField<Dim>& u,
                                     InnerFluid<Dim> MarkerCoupling<Dim>::*field)
{
    std::vector<std::size_t> free;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (bodies[b].is_free()) {
            free.push_back(b);
        }
    }
    const std::vector<InnerFluid<Dim>> values =
        inner_fluid_of<Dim>(std::span<const Particle<Dim>>(bodies), free, grid, u);
    for (std::size_t m = 0; m < free.size(); ++m) {
        bodies[free[m]].coupling.*field = values[m];
    }
}

template double ball_volume_fraction<2>(const Vec<2>&, const Vec<2>&, const Vec<2>&,
                                        double) noexcept;
template double ball_volume_fraction<3>(const Vec<3>&, const Vec<3>&, const Vec<3>&,
                                        double) noexcept;
template InnerFluid<2> inner_fluid_part<2>(const MacGrid<2>&, const FaceField<2>&, const Vec<2>&,
                                           double);
template InnerFluid<3> inner_fluid_part<3>(const MacGrid<3>&, const FaceField<3>&, const Vec<3>&,
                                           double);
template std::vector<InnerFluid<2>> inner_fluid_of<2>(std::span<const Particle<2>>,
                                                      std::span<const std::size_t>,
                                                      const MacGrid<2>&, const FaceField<2>&);
template std::vector<InnerFluid<3>> inner_fluid_of<3>(std::span<const Particle<3>>,
                                                      std::span<const std::size_t>,
                                                      const MacGrid<3>&, const FaceField<3>&);
template void take_inner_fluid_of_free_bodies<2>(std::span<Particle<2>>, const MacGrid<2>&,
                                                 const FaceField<2>&,
                                                 InnerFluid<2> MarkerCoupling<2>::*);
template void take_inner_fluid_of_free_bodies<3>(std::span<Particle<3>>, const MacGrid<3>&,
                                                 const FaceField<3>&,
                                                 InnerFluid<3> MarkerCoupling<3>::*);

} // namespace fddem
