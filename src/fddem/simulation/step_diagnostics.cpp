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
    // The first non-finite value in storage order (serial) of a field, at `where`'s position.
    const auto first_in = [&](const GridArray<Dim>& field, const Box<Dim>& box, auto where,
                              const std::string& name) -> std::optional<std::string> {
        std::optional<Index<Dim>> found;
        for_each_cell_in_vtk_order(box, [&](const Index<Dim>& c) {
            if (!found && !std::isfinite(field(c))) {
                found = c;
            }
        });
        if (!found) {
            return std::nullopt;
        }
        return fmt::format("{} not finite at ({:.6g})", name, fmt::join(where(*found), ", "));
    };
    for (int a = 0; a < Dim; ++a) {
        const auto face = [&](const Index<Dim>& c) { return grid.face_centre(a, c); };
        if (auto at = first_in(state.u[a], grid.face_box(a), face,
                               fmt::format("velocity component {}", a))) {
            return *at;
        }
        if (auto at = first_in(state.body_force[a], grid.face_box(a), face,
                               fmt::format("body force component {} (the markers' λ)", a))) {
            return *at;
        }
    }
    const auto cell = [&](const Index<Dim>& c) { return grid.cell_centre(c); };
    if (auto at = first_in(state.p, grid.cell_box(), cell, "pressure")) {
        return *at;
    }
    // All finite: a residual overflowed. Where is the fastest fluid?
    double fastest = 0.0;
    std::string where;
    for (int a = 0; a < Dim; ++a) {
        for_each_cell_in_vtk_order(grid.face_box(a), [&](const Index<Dim>& c) {
            if (std::abs(state.u[a](c)) > fastest) {
                fastest = std::abs(state.u[a](c));
                where = fmt::format("{:.6g}", fmt::join(grid.face_centre(a, c), ", "));
            }
        });
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
