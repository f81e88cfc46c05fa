// SPDX-License-Identifier: MIT
#pragma once
/// Field output for ParaView: VTK XML RectilinearGrid files (.vtr) with cell data (velocity at
/// cell centres, pressure, vorticity), and a .pvd collection listing them by time.
/// Data are appended raw binary (little-endian Float64, UInt64 headers): exact values, ~3×
/// smaller and much faster to write and read than ASCII.
///
/// On a grid split across MPI ranks (issue 15) every rank writes its own block as one piece
/// (a .vtr, a .vtp) and rank 0 a parallel master file (.pvtr, .pvtp) that lists the pieces
/// and their arrays: ParaView opens the master as one dataset. A piece holds the cells its rank
/// owns; in point indices (the extents of VTK's structured data) neighbouring pieces share the
/// node plane between them, so the pieces' cells tile the whole grid without overlap.

#include "fddem/grid/fields.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// One Float64 array of a VTK file: its name and number of components.
struct VtkArray {
    std::string name;
    int n_components = 1;
};

/// A structured extent in VTK's order: first and last node index along x, y, z
/// ("x0 x1 y0 y1 z0 z1"; 0 0 along z in 2D).
using VtkExtent = std::array<int, 6>;

/// The node extent of the cells [lo, hi): nodes lo to hi along each axis (a cell i lies between
/// nodes i and i + 1).
template <int Dim>
[[nodiscard]] VtkExtent point_extent(const Box<Dim>& cells);

/// Writes `path` (.vtr) from the fields: the cells this process owns, with the whole grid's
/// WholeExtent (one process: the whole grid; a split grid: this rank's piece). Ghosts of u must
/// be filled. Atomic. Returns the cell arrays written, in order (for the .pvtr).
template <int Dim>
std::vector<VtkArray> write_vtr(const std::filesystem::path& path, const MacGrid<Dim>& grid,
                                const FaceField<Dim>& u, const CellField<Dim>& p);

/// One piece of a parallel master file: its node extent (.pvtr only) and its file, relative to
/// the master's folder.
struct VtkPiece {
    VtkExtent extent{};
    std::string source;
};

/// Writes the master `path` (.pvtr) of a grid of node extent `whole` written as `pieces`
/// (write_vtr on each rank), whose cell arrays are `cell_arrays`. Atomic.
void write_pvtr(const std::filesystem::path& path, const VtkExtent& whole,
                const std::vector<VtkArray>& cell_arrays, const std::vector<VtkPiece>& pieces);

/// The bodies of one particles frame, one entry per body, padded to 3D.
struct ParticlePoints {
    std::vector<double> ids;
    std::vector<std::array<double, 3>> centres;            ///< [m]
    std::vector<double> radii;                             ///< [m]
    std::vector<std::array<double, 3>> velocities;         ///< [m/s]
    std::vector<std::array<double, 3>> angular_velocities; ///< [rad/s]
    std::vector<std::array<double, 4>> orientations;       ///< q_w, q_x, q_y, q_z (2D: about z)
    /// The body frame's x axis in the world frame: a unit vector that turns with the body
    /// (glyph it as an arrow to see a sphere roll).
    std::vector<std::array<double, 3>> body_axes;
    /// Further 3-component point data, each named (the forces and torques apart: hydrodynamic,
    /// contact, lubrication), one value per body.
    std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>> vectors;
};

/// Particles for ParaView: a PolyData (.vtp) of the body centres with point data id, radius,
/// velocity, angular velocity, orientation, body axis and `vectors` (draw disks or spheres with the
/// Glyph filter scaled by "radius"; open_in_paraview.py does). Atomic. Returns the point arrays
/// written, in order (for the .pvtp).
std::vector<VtkArray> write_vtp(const std::filesystem::path& path, const ParticlePoints& bodies);

/// Writes the master `path` (.pvtp) of the particles written as `pieces` (write_vtp on each
/// rank, the bodies it owns), whose point arrays are `point_arrays`. Atomic.
void write_pvtp(const std::filesystem::path& path, const std::vector<VtkArray>& point_arrays,
                const std::vector<VtkPiece>& pieces);

/// The .pvd collection: (time, file relative to the .pvd) pairs, rewritten atomically.
class PvdCollection {
public:
    explicit PvdCollection(std::filesystem::path path) : path_(std::move(path)) {}
    void add(double time, const std::string& relative_file);
    /// Replaces the entries (a restarted run: those of its checkpoint) and rewrites the file.
    void assign(std::vector<std::pair<double, std::string>> entries);
    [[nodiscard]] const std::vector<std::pair<double, std::string>>& entries() const noexcept
    {
        return entries_;
    }

private:
    void write() const;

    std::filesystem::path path_;
    std::vector<std::pair<double, std::string>> entries_;
};

} // namespace fddem
