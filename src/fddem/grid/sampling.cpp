// SPDX-License-Identifier: MIT
#include "fddem/grid/sampling.hpp"

#include "fddem/grid/loops.hpp"

#include <cmath>

namespace fddem {
namespace {

/// Multilinear interpolation of `a`, whose values sit at origin + (i + shift_d) h_d.
template <int Dim>
double interpolate(const MacGrid<Dim>& grid, const GridArray<Dim>& a, const Vec<Dim>& x,
                   const Vec<Dim>& shift)
{
    Index<Dim> base{};
    Vec<Dim> t;
    for (int d = 0; d < Dim; ++d) {
        const double s = (x[d] - grid.origin()[d]) / grid.spacing(d) - shift[d];
        // Clamp so the stencil stays inside the storage box (points on the boundary).
        const double clamped = std::clamp(s, -1.0, static_cast<double>(grid.cells(d)));
        const int i = std::min(static_cast<int>(std::floor(clamped)), grid.cells(d));
        base[static_cast<std::size_t>(d)] = i;
        t[d] = clamped - i;
    }
    double value = 0.0;
    for (int corner = 0; corner < (1 << Dim); ++corner) {
        Index<Dim> index = base;
        double weight = 1.0;
        for (int d = 0; d < Dim; ++d) {
            const bool is_high = ((corner >> d) & 1) != 0;
            index[static_cast<std::size_t>(d)] += is_high ? 1 : 0;
            weight *= is_high ? t[d] : 1.0 - t[d];
        }
        if (weight != 0.0) {
            value += weight * a(index);
        }
    }
    return value;
}

} // namespace

template <int Dim>
Vec<Dim> sample_velocity(const MacGrid<Dim>& grid, const FaceField<Dim>& u, const Vec<Dim>& x)
{
    Vec<Dim> result;
    for (int a = 0; a < Dim; ++a) {
        Vec<Dim> shift = Vec<Dim>::Constant(0.5);
        shift[a] = 0.0;
        result[a] = interpolate(grid, u[a], x, shift);
    }
    return result;
}

template <int Dim>
double sample_cell_field(const MacGrid<Dim>& grid, const CellField<Dim>& phi, const Vec<Dim>& x)
{
    return interpolate<Dim>(grid, phi, x, Vec<Dim>::Constant(0.5));
}

template <int Dim>
std::vector<std::vector<double>>
sample_line_owned(const MacGrid<Dim>& grid, const FaceField<Dim>& u, const CellField<Dim>& p,
                  const Vec<Dim>& from, const Vec<Dim>& to, int n_points)
{
    std::vector<std::vector<double>> rows;
    for (int k = 0; k < n_points; ++k) {
        const double s = n_points > 1 ? static_cast<double>(k) / (n_points - 1) : 0.0;
        const Vec<Dim> x = from + s * (to - from);
        if (!grid.owns_point(x)) {
            continue;
        }
        const Vec<Dim> velocity = sample_velocity(grid, u, x);
        std::vector<double> row{static_cast<double>(k)};
        for (int d = 0; d < Dim; ++d) {
            row.push_back(x[d]);
        }
        for (int d = 0; d < Dim; ++d) {
            row.push_back(velocity[d]);
        }
        row.push_back(sample_cell_field(grid, p, x));
        rows.push_back(std::move(row));
    }
    return rows;
}

template <int Dim>
void cell_centred_velocity(const MacGrid<Dim>& grid, const FaceField<Dim>& u, int axis,
                           CellField<Dim>& out)
{
    const std::ptrdiff_t s = grid.stride(axis);
    for_each_index(grid.owned_cells(), [&](const Index<Dim>& c) {
        const std::ptrdiff_t o = grid.offset(c);
        out[o] = 0.5 * (u[axis][o] + u[axis][o + s]);
    });
}

template <int Dim>
void cell_centred_vorticity(const MacGrid<Dim>& grid, const FaceField<Dim>& u, int a, int b,
                            CellField<Dim>& out)
{
    const std::ptrdiff_t sa = grid.stride(a);
    const std::ptrdiff_t sb = grid.stride(b);
    const double ha = grid.spacing(a);
    const double hb = grid.spacing(b);
    // Edge value at the low corner (in a and b) of the cell at offset o.
    const auto edge = [&](std::ptrdiff_t o) {
        return (u[b][o] - u[b][o - sa]) / ha - (u[a][o] - u[a][o - sb]) / hb;
    };
    for_each_index(grid.owned_cells(), [&](const Index<Dim>& c) {
        const std::ptrdiff_t o = grid.offset(c);
        out[o] = 0.25 * (edge(o) + edge(o + sa) + edge(o + sb) + edge(o + sa + sb));
    });
}

template Vec<2> sample_velocity<2>(const MacGrid<2>&, const FaceField<2>&, const Vec<2>&);
template Vec<3> sample_velocity<3>(const MacGrid<3>&, const FaceField<3>&, const Vec<3>&);
template double sample_cell_field<2>(const MacGrid<2>&, const CellField<2>&, const Vec<2>&);
template double sample_cell_field<3>(const MacGrid<3>&, const CellField<3>&, const Vec<3>&);
template std::vector<std::vector<double>> sample_line_owned<2>(const MacGrid<2>&,
                                                               const FaceField<2>&,
                                                               const CellField<2>&, const Vec<2>&,
                                                               const Vec<2>&, int);
template std::vector<std::vector<double>> sample_line_owned<3>(const MacGrid<3>&,
                                                               const FaceField<3>&,
                                                               const CellField<3>&, const Vec<3>&,
                                                               const Vec<3>&, int);
template void cell_centred_velocity<2>(const MacGrid<2>&, const FaceField<2>&, int, CellField<2>&);
template void cell_centred_velocity<3>(const MacGrid<3>&, const FaceField<3>&, int, CellField<3>&);
template void cell_centred_vorticity<2>(const MacGrid<2>&, const FaceField<2>&, int, int,
                                        CellField<2>&);
template void cell_centred_vorticity<3>(const MacGrid<3>&, const FaceField<3>&, int, int,
                                        CellField<3>&);

} // namespace fddem
