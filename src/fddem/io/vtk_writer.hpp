// SPDX-License-Identifier: MIT
#pragma once
/// Field output for ParaView: VTK XML RectilinearGrid files (.vtr) with cell data (velocity at
/// cell centres, pressure, vorticity), and a .pvd collection listing them by time.
/// Data are appended raw binary (little-endian Float64, UInt64 headers): exact values, ~3×
/// smaller and much faster to write and read than ASCII.

#include "fddem/grid/fields.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// Writes `path` (.vtr) from the fields; ghosts of u must be filled. Atomic.
template <int Dim>
void write_vtr(const std::filesystem::path& path, const MacGrid<Dim>& grid, const FaceField<Dim>& u,
               const CellField<Dim>& p);

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
/// Glyph filter scaled by "radius"; open_in_paraview.py does). Atomic.
void write_vtp(const std::filesystem::path& path, const ParticlePoints& bodies);

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
