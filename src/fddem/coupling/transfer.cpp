// SPDX-License-Identifier: MIT
#include "fddem/coupling/transfer.hpp"

#include <array>
#include <cmath>

namespace fddem {
namespace {

/// The 1-D stencil along one axis: first index and the weights of the 2·half_width points.
template <DeltaKernel Kernel>
struct Stencil1d {
    int first = 0;
    std::array<double, 2 * Kernel::half_width> weight{};
};

template <int Dim, DeltaKernel Kernel>
Stencil1d<Kernel> stencil_along(const MacGrid<Dim>& grid, int d, int axis, double x)
{
    // Positions of component `axis` along d: faces (i h) if d == axis, else centres.
    const double shift = d == axis ? 0.0 : 0.5;
    const double s = (x - grid.origin()[d]) / grid.spacing(d) - shift;
    Stencil1d<Kernel> st;
    st.first = static_cast<int>(std::floor(s)) - Kernel::half_width + 1;
    for (int k = 0; k < 2 * Kernel::half_width; ++k) {
        st.weight[static_cast<std::size_t>(k)] = Kernel::weight(s - (st.first + k));
    }
    return st;
}

/// Calls f(offset, weight) for every grid point of the tensor-product stencil.
template <int Dim, DeltaKernel Kernel, class F>
void for_each_stencil_point(const MacGrid<Dim>& grid, int axis, const Vec<Dim>& x, F&& f)
{
    std::array<Stencil1d<Kernel>, Dim> st;
    for (int d = 0; d < Dim; ++d) {
        st[static_cast<std::size_t>(d)] = stencil_along<Dim, Kernel>(grid, d, axis, x[d]);
    }
    constexpr int width = 2 * Kernel::half_width;
    int n_points = 1;
    for (int d = 0; d < Dim; ++d) {
        n_points *= width;
    }
    for (int m = 0; m < n_points; ++m) {
        int code = m;
        Index<Dim> index{};
        double weight = 1.0;
        for (int d = 0; d < Dim; ++d) {
            const int k = code % width;
            code /= width;
            const auto dd = static_cast<std::size_t>(d);
            index[dd] = st[dd].first + k;
            weight *= st[dd].weight[static_cast<std::size_t>(k)];
        }
        if (weight != 0.0) {
            f(grid.offset(index), weight);
        }
    }
}

} // namespace

template <int Dim, DeltaKernel Kernel>
bool fits_in_box(const MacGrid<Dim>& grid, const Box<Dim>& storage, const Vec<Dim>& x)
{
    for (int axis = 0; axis < Dim; ++axis) {
        for (int d = 0; d < Dim; ++d) {
            const auto st = stencil_along<Dim, Kernel>(grid, d, axis, x[d]);
            const auto dd = static_cast<std::size_t>(d);
            if (st.first < storage.lo[dd] || st.first + 2 * Kernel::half_width > storage.hi[dd]) {
                return false;
            }
        }
    }
    return true;
}

template <int Dim, DeltaKernel Kernel>
double interpolate_component(const MacGrid<Dim>& grid, const GridArray<Dim>& a, int axis,
                             const Vec<Dim>& x)
{
    double value = 0.0;
    for_each_stencil_point<Dim, Kernel>(grid, axis, x,
                                        [&](std::ptrdiff_t o, double w) { value += w * a[o]; });
    return value;
}

template <int Dim, DeltaKernel Kernel>
void spread_component(const MacGrid<Dim>& grid, GridArray<Dim>& a, int axis, const Vec<Dim>& x,
                      double value)
{
    for_each_stencil_point<Dim, Kernel>(grid, axis, x,
                                        [&](std::ptrdiff_t o, double w) { a[o] += w * value; });
}

#define FDDEM_INSTANTIATE_TRANSFER(DIM, KERNEL)                                                    \
    template bool fits_in_box<DIM, KERNEL>(const MacGrid<DIM>&, const Box<DIM>&, const Vec<DIM>&); \
    template double interpolate_component<DIM, KERNEL>(const MacGrid<DIM>&, const GridArray<DIM>&, \
                                                       int, const Vec<DIM>&);                      \
    template void spread_component<DIM, KERNEL>(const MacGrid<DIM>&, GridArray<DIM>&, int,         \
                                                const Vec<DIM>&, double);
FDDEM_INSTANTIATE_TRANSFER(2, HatKernel)
FDDEM_INSTANTIATE_TRANSFER(3, HatKernel)
FDDEM_INSTANTIATE_TRANSFER(2, RomaPeskin3Kernel)
FDDEM_INSTANTIATE_TRANSFER(3, RomaPeskin3Kernel)
FDDEM_INSTANTIATE_TRANSFER(2, Peskin4Kernel)
FDDEM_INSTANTIATE_TRANSFER(3, Peskin4Kernel)
FDDEM_INSTANTIATE_TRANSFER(2, SmoothedRoma3Kernel)
FDDEM_INSTANTIATE_TRANSFER(3, SmoothedRoma3Kernel)
#undef FDDEM_INSTANTIATE_TRANSFER

} // namespace fddem
