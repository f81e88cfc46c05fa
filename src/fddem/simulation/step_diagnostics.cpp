// SPDX-License-Identifier: MIT
#include "fddem/simulation/step_diagnostics.hpp"

#include "fddem/grid/loops.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

namespace fddem {
namespace {

template <int Dim>
double max_speed(const MacGrid<Dim>& grid, const FaceField<Dim>& u)
{
    double result = 0.0;
    for (int a = 0; a < Dim; ++a) {
        result = std::max(result, max_over(grid.communicator(), grid.owned_faces(a),
                                           [&](const Index<Dim>& c) { return std::abs(u[a](c)); }));
    }
    return result;
}

/// The place of `c` in `box`'s storage order (x fastest), as a double (exact below 2^53).
template <int Dim>
double order_in(const Box<Dim>& box, const Index<Dim>& c)
{
    double order = 0.0;
    for (int d = Dim - 1; d >= 0; --d) {
        const auto sd = static_cast<std::size_t>(d);
        order = order * box.extent(d) + (c[sd] - box.lo[sd]);
    }
    return order;
}

/// The index at place `order` of `box`'s storage order: the inverse of order_in.
template <int Dim>
Index<Dim> index_in(const Box<Dim>& box, double order)
{
    auto rest = static_cast<long long>(order);
    Index<Dim> c{};
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        c[sd] = box.lo[sd] + static_cast<int>(rest % box.extent(d));
        rest /= box.extent(d);
    }
    return c;
}

} // namespace

template <int Dim>
double reference_velocity(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          const FaceField<Dim>& u)
{
    double wall = 0.0;
    for (int d = 0; d < Dim; ++d) {
        for (int side = 0; side < 2; ++side) {
            wall = std::max(wall, bc.wall(d, side).cwiseAbs().maxCoeff());
        }
    }
    return std::max({max_speed(grid, u), wall, std::numeric_limits<double>::min()});
}

template <int Dim>
double max_speed_per_cell(const MacGrid<Dim>& grid, const FaceField<Dim>& u)
{
    double result = 0.0;
    for (int a = 0; a < Dim; ++a) {
        result = std::max(
            result, max_over(grid.communicator(), grid.owned_faces(a), [&](const Index<Dim>& c) {
                return std::abs(u[a](c)) / grid.spacing(a);
            }));
    }
    return result;
}

template <int Dim>
StepChange measure_change(const MacGrid<Dim>& grid, const FluidState<Dim>& state, double dt)
{
    StepChange result;
    for (int a = 0; a < Dim; ++a) {
        const GridArray<Dim>& ua = state.u[a];
        const GridArray<Dim>& ua_n = state.u_n[a];
        result.courant =
            std::max(result.courant,
                     max_over(grid.communicator(), grid.owned_faces(a), [&](const Index<Dim>& c) {
                         return std::abs(ua(c)) * dt / grid.spacing(a);
                     }));
        result.largest_change =
            std::max(result.largest_change,
                     max_over(grid.communicator(), grid.owned_faces(a),
                              [&](const Index<Dim>& c) { return std::abs(ua(c) - ua_n(c)); }));
    }
    return result;
}

template <int Dim>
std::string locate_non_finite(const MacGrid<Dim>& grid, const FluidState<Dim>& state)
{
    // Every rank searches the entries it owns; the one first in the whole array's storage
    // order (x fastest) wins, through its index in that order, which every rank can turn back
    // into a position: the message is the one-process message, on every rank.
    const Communicator& ranks = grid.communicator();
    const double none = std::numeric_limits<double>::infinity();
    const auto lowest = [&](double local) { return -ranks.max(-local); };
    // The first entry of `owned` (in the order of `whole`) where `is_found`, over the ranks.
    const auto first_where = [&](const Box<Dim>& whole, const Box<Dim>& owned,
                                 auto is_found) -> std::optional<Index<Dim>> {
        double first = none;
        for_each_cell_in_vtk_order(owned, [&](const Index<Dim>& c) {
            if (is_found(c)) {
                first = std::min(first, order_in<Dim>(whole, c));
            }
        });
        first = lowest(first);
        if (first == none) {
            return std::nullopt;
        }
        return index_in<Dim>(whole, first);
    };
    const auto non_finite = [](const GridArray<Dim>& field) {
        return [&field](const Index<Dim>& c) { return !std::isfinite(field(c)); };
    };
    for (int a = 0; a < Dim; ++a) {
        const Box<Dim> whole = grid.face_box(a);
        const Box<Dim> owned = grid.owned_faces(a);
        const auto at = [&](const Index<Dim>& c) {
            return fmt::format("({:.6g})", fmt::join(grid.face_centre(a, c), ", "));
        };
        if (auto c = first_where(whole, owned, non_finite(state.u[a]))) {
            return fmt::format("velocity component {} not finite at {}", a, at(*c));
        }
        if (auto c = first_where(whole, owned, non_finite(state.body_force[a]))) {
            return fmt::format("body force component {} (the markers' λ) not finite at {}", a,
                               at(*c));
        }
    }
    if (auto c = first_where(grid.cell_box(), grid.owned_cells(), non_finite(state.p))) {
        return fmt::format("pressure not finite at ({:.6g})",
                           fmt::join(grid.cell_centre(*c), ", "));
    }
    // All finite: a residual overflowed. Where is the fastest fluid (the first such face)?
    double fastest = 0.0;
    std::string where;
    for (int a = 0; a < Dim; ++a) {
        const GridArray<Dim>& ua = state.u[a];
        const double largest = max_over(ranks, grid.owned_faces(a),
                                        [&](const Index<Dim>& c) { return std::abs(ua(c)); });
        if (largest <= fastest) {
            continue;
        }
        fastest = largest;
        const auto c = first_where(grid.face_box(a), grid.owned_faces(a),
                                   [&](const Index<Dim>& i) { return std::abs(ua(i)) == largest; });
        where = fmt::format("{:.6g}", fmt::join(grid.face_centre(a, *c), ", "));
    }
    if (where.empty()) {
        return "the momentum residual is not finite, with the velocity, the body force and the "
               "pressure finite and the fluid at rest (|u| = 0 everywhere)";
    }
    return fmt::format("the momentum residual is not finite (largest |u| {:.3g} at ({}))", fastest,
                       where);
}

template double reference_velocity<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                      const FaceField<2>&);
template double reference_velocity<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                      const FaceField<3>&);
template double max_speed_per_cell<2>(const MacGrid<2>&, const FaceField<2>&);
template double max_speed_per_cell<3>(const MacGrid<3>&, const FaceField<3>&);
template StepChange measure_change<2>(const MacGrid<2>&, const FluidState<2>&, double);
template StepChange measure_change<3>(const MacGrid<3>&, const FluidState<3>&, double);
template std::string locate_non_finite<2>(const MacGrid<2>&, const FluidState<2>&);
template std::string locate_non_finite<3>(const MacGrid<3>&, const FluidState<3>&);

} // namespace fddem
