// SPDX-License-Identifier: MIT
#include "fddem/run/field_frames.hpp"

#include "fddem/io/atomic_file.hpp"
#include "fddem/run/body_snapshot.hpp"

#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <string>
#include <system_error>
#include <vector>

namespace fddem {
namespace {

namespace fs = std::filesystem;

/// `value` in the first Dim of three components (VTK points and vectors are 3D).
template <int Dim>
std::array<double, 3> padded(const Vec<Dim>& value)
{
    std::array<double, 3> xyz{};
    for (int d = 0; d < Dim; ++d) {
        xyz.at(static_cast<std::size_t>(d)) = value[d];
    }
    return xyz;
}

/// An angular velocity as a 3-vector: about z in 2D.
template <int Dim>
std::array<double, 3> spin_vector(const AngularVec<Dim>& omega)
{
    if constexpr (Dim == 2) {
        return {0.0, 0.0, omega};
    } else {
        return padded<3>(omega);
    }
}

/// An orientation as the unit quaternion q_w, q_x, q_y, q_z: a turn by θ about z in 2D.
template <int Dim>
std::array<double, 4> quaternion_of(const Orientation<Dim>& orientation)
{
    if constexpr (Dim == 2) {
        return {std::cos(0.5 * orientation), 0.0, 0.0, std::sin(0.5 * orientation)};
    } else {
        return {orientation.w(), orientation.x(), orientation.y(), orientation.z()};
    }
}

/// The points of `bodies` for a .vtp.
template <int Dim>
ParticlePoints particle_points(const std::vector<BodySnapshot<Dim>>& bodies)
{
    ParticlePoints points;
    const std::array<const char*, 6> vector_names = {"hydrodynamic_force", "hydrodynamic_torque",
                                                     "contact_force",      "contact_torque",
                                                     "lubrication_force",  "lubrication_torque"};
    for (const char* vector_name : vector_names) {
        points.vectors.emplace_back(vector_name, std::vector<std::array<double, 3>>{});
    }
    for (const BodySnapshot<Dim>& body : bodies) {
        const std::array<std::array<double, 3>, 6> values = {
            padded<Dim>(body.force),
            spin_vector<Dim>(body.torque),
            padded<Dim>(body.contact_force),
            spin_vector<Dim>(body.contact_torque),
            padded<Dim>(body.lubrication_force),
            spin_vector<Dim>(body.lubrication_torque)};
        for (std::size_t k = 0; k < values.size(); ++k) {
            points.vectors[k].second.push_back(values[k]);
        }
        points.ids.push_back(body.id);
        points.centres.push_back(padded<Dim>(body.centre));
        points.radii.push_back(body.radius);
        points.velocities.push_back(padded<Dim>(body.velocity));
        points.angular_velocities.push_back(spin_vector<Dim>(body.omega));
        points.orientations.push_back(quaternion_of<Dim>(body.orientation));
        points.body_axes.push_back(padded<Dim>(to_world<Dim>(body.orientation, Vec<Dim>::UnitX())));
    }
    return points;
}

/// Creates `folder` if it does not exist; several ranks may do so at once.
void create_folder(const fs::path& folder)
{
    std::error_code error;
    fs::create_directories(folder, error);
    if (!fs::is_directory(folder)) {
        throw OutputError("cannot create " + folder.string() + ": " + error.message());
    }
}

/// The frame of the current time on one process: fields/fields_NNNNNN.vtr and
/// particles/particles_NNNNNN.vtp.
template <int Dim>
void write_whole_frame(const Simulation<Dim>& sim, const fs::path& directory, PvdCollection& fields,
                       PvdCollection& particles)
{
    const std::size_t frame = next_frame_number(fields);
    const std::string name = fmt::format("fields/fields_{:06d}.vtr", frame);
    // Read-only access (sim is const): the mutable fluid() would invalidate the reusable
    // assembly and make the results depend on when outputs are written.
    write_vtr(directory / name, sim.grid(), sim.fluid().u, sim.fluid().p);
    fields.add(sim.clock().time, name);
    const std::vector<BodySnapshot<Dim>> bodies = body_snapshots(sim);
    if (bodies.empty()) {
        return;
    }
    const std::string file = fmt::format("particles/particles_{:06d}.vtp", frame);
    fs::create_directories(directory / "particles");
    write_vtp(directory / file, particle_points(bodies));
    particles.add(sim.clock().time, file);
}

/// The pieces of the parallel master of frame `stem` (fields_000007), one per rank of `ranks`:
/// each rank's file (piece_file) and, for a grid, the node extent it gives as `extent`.
/// Collective, and called after each rank has written its piece: when it returns on rank 0,
/// every piece is on disk, and the master that names them can be written.
std::vector<VtkPiece> collect_pieces(const Communicator& ranks, const std::string& stem,
                                     const std::string& piece_extension, const VtkExtent& extent)
{
    const auto n_ranks = static_cast<std::size_t>(ranks.size());
    const auto rank = static_cast<std::size_t>(ranks.rank());
    std::vector<double> extents(6 * n_ranks, 0.0); // node indices: exact in a double
    for (std::size_t k = 0; k < 6; ++k) {
        extents[6 * rank + k] = extent.at(k);
    }
    ranks.sum(extents);
    std::vector<VtkPiece> pieces(n_ranks);
    for (std::size_t r = 0; r < n_ranks; ++r) {
        for (std::size_t k = 0; k < 6; ++k) {
            pieces[r].extent.at(k) = static_cast<int>(extents[6 * r + k]);
        }
        pieces[r].source = piece_file(stem, static_cast<int>(r), piece_extension);
    }
    return pieces;
}

/// The frame of the current time on a grid split across ranks: every rank writes its piece of
/// fields/fields_NNNNNN.pvtr (its owned cells) and of particles/particles_NNNNNN.pvtp (the
/// bodies whose centre lies in its block), rank 0 the masters. Collective.
template <int Dim>
void write_split_frame(const Simulation<Dim>& sim, const fs::path& directory, PvdCollection& fields,
                       PvdCollection& particles)
{
    const MacGrid<Dim>& grid = sim.grid();
    const Communicator& ranks = grid.communicator();
    const bool is_root = ranks.rank() == 0;
    // Rank 0 alone holds the .pvd collections, and the frame's number with them.
    std::string number = is_root ? std::to_string(next_frame_number(fields)) : std::string();
    ranks.broadcast(number);
    const std::size_t frame = std::stoul(number);

    const std::string field_stem = fmt::format("fields_{:06d}", frame);
    create_folder(directory / "fields" / field_stem);
    const std::vector<VtkArray> cell_arrays =
        write_vtr(directory / "fields" / piece_file(field_stem, ranks.rank(), ".vtr"), grid,
                  sim.fluid().u, sim.fluid().p);
    const std::vector<VtkPiece> field_pieces =
        collect_pieces(ranks, field_stem, ".vtr", point_extent(grid.owned_cells()));
    if (is_root) {
        const std::string name = "fields/" + field_stem + ".pvtr";
        write_pvtr(directory / name, point_extent(grid.cell_box()), cell_arrays, field_pieces);
        fields.add(sim.clock().time, name);
    }

    std::vector<BodySnapshot<Dim>> bodies = body_snapshots(sim);
    if (bodies.empty()) {
        return;
    }
    // Every rank holds every body; each body goes to the piece of the one rank whose block
    // holds its centre (wrapped into the box across periodic sides).
    std::erase_if(bodies, [&](const BodySnapshot<Dim>& body) {
        return !grid.owns_point(grid.domain().wrap(body.centre));
    });
    const std::string body_stem = fmt::format("particles_{:06d}", frame);
    create_folder(directory / "particles" / body_stem);
    const std::vector<VtkArray> point_arrays =
        write_vtp(directory / "particles" / piece_file(body_stem, ranks.rank(), ".vtp"),
                  particle_points(bodies));
    const std::vector<VtkPiece> body_pieces = collect_pieces(ranks, body_stem, ".vtp", {});
    if (is_root) {
        const std::string name = "particles/" + body_stem + ".pvtp";
        write_pvtp(directory / name, point_arrays, body_pieces);
        particles.add(sim.clock().time, name);
    }
}

} // namespace

template <int Dim>
void write_frame(const Simulation<Dim>& sim, const fs::path& directory, PvdCollection& fields,
                 PvdCollection& particles)
{
    if (sim.grid().communicator().size() > 1) {
        write_split_frame(sim, directory, fields, particles);
    } else {
        write_whole_frame(sim, directory, fields, particles);
    }
}

std::string piece_file(const std::string& stem, int rank, const std::string& extension)
{
    return fmt::format("{}/{}_{:04d}{}", stem, stem, rank, extension);
}

std::size_t next_frame_number(const PvdCollection& fields)
{
    if (fields.entries().empty()) {
        return 0;
    }
    const std::string& last = fields.entries().back().second; // fields/fields_NNNNNN.vtr
    const std::size_t digits = last.rfind('_') + 1;
    return std::stoul(last.substr(digits, last.rfind('.') - digits)) + 1;
}

std::vector<std::string> drop_missing_frames(const fs::path& directory,
                                             std::vector<std::pair<double, std::string>>& frames)
{
    std::vector<std::string> missing;
    std::erase_if(frames, [&](const std::pair<double, std::string>& frame) {
        std::error_code error;
        const bool is_missing = !fs::exists(directory / frame.second, error);
        if (is_missing) {
            missing.push_back(frame.second);
        }
        return is_missing;
    });
    return missing;
}

template void write_frame(const Simulation<2>&, const fs::path&, PvdCollection&, PvdCollection&);
template void write_frame(const Simulation<3>&, const fs::path&, PvdCollection&, PvdCollection&);

} // namespace fddem
