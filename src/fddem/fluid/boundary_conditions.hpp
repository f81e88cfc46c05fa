// SPDX-License-Identifier: MIT
#pragma once
/// Boundary conditions of the box: no-slip walls (possibly sliding, e.g. a lid) or periodic
/// pairs, and the ghost-layer filling that carries them to the stencils.

#include "fddem/core/vec.hpp"
#include "fddem/grid/fields.hpp"
#include "fddem/grid/mac_grid.hpp"

#include <array>

namespace fddem {

template <int Dim>
struct BoundaryConditions {
    /// is_periodic[axis]: both sides of that axis are one periodic pair.
    std::array<bool, Dim> is_periodic{};
    /// wall_velocity[axis][side] (side 0 = low, 1 = high) [m/s]; only the tangential
    /// components may be non-zero (a sliding wall); ignored on periodic axes.
    std::array<std::array<Vec<Dim>, 2>, Dim> wall_velocity{};

    [[nodiscard]] bool periodic(int axis) const noexcept
    {
        return is_periodic[static_cast<std::size_t>(axis)];
    }
    [[nodiscard]] const Vec<Dim>& wall(int axis, int side) const noexcept
    {
        return wall_velocity[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)];
    }

    /// All axes walled, walls at rest.
    [[nodiscard]] static BoundaryConditions closed_box()
    {
        BoundaryConditions bc;
        for (auto& axis : bc.wall_velocity) {
            for (auto& side : axis) {
                side = Vec<Dim>::Zero();
            }
        }
        return bc;
    }
};

/// The faces of component `axis` that are unknowns of the momentum equations: all faces
/// except those lying on a wall (their normal velocity is the wall's, zero). On a periodic
/// axis face n is the image of face 0 and is a ghost.
template <int Dim>
[[nodiscard]] Box<Dim> unknown_faces(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                     int axis) noexcept
{
    Box<Dim> box = grid.cell_box();
    if (!bc.periodic(axis)) {
        box.lo[static_cast<std::size_t>(axis)] = 1;
    }
    return box;
}

/// Sets the wall-normal velocity on wall faces and fills every ghost layer of `u`:
/// periodic images across periodic axes; across a wall, tangential ghosts such that the
/// quadratic through the wall value and the first two interior values is continued
/// (u_g = (8 u_w − 6 u_0 + u_1)/3), which makes the wall treatment exact for quadratic
/// profiles (Poiseuille); outer ghost layers mirror the interior (odd about the wall).
template <int Dim>
void fill_velocity_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          FaceField<Dim>& u);

/// Fills only the periodic images of one array (cell field or one velocity component).
template <int Dim>
void fill_periodic_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          GridArray<Dim>& a);

/// Fills the ghost layers of a cell field: periodic images, or a zero normal gradient at
/// walls (the pressure condition of SIMPLE at a no-slip wall).
template <int Dim>
void fill_cell_ghosts(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                      CellField<Dim>& phi);

} // namespace fddem
