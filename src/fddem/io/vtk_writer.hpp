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

/// Particles for ParaView: a PolyData (.vtp) of the body centres with point data radius,
/// velocity and angular velocity (draw disks with the Glyph filter scaled by "radius"). Atomic.
void write_vtp(const std::filesystem::path& path, const std::vector<std::array<double, 3>>& centres,
               const std::vector<double>& radii,
               const std::vector<std::array<double, 3>>& velocities,
               const std::vector<std::array<double, 3>>& angular_velocities);

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
