// SPDX-License-Identifier: MIT
#include "fddem/run/field_frames.hpp"

#include "fddem/run/body_snapshot.hpp"

#include <fmt/format.h>

#include <array>
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

} // namespace

template <int Dim>
void write_frame(const Simulation<Dim>& sim, const fs::path& directory, PvdCollection& fields,
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
    const std::string file = fmt::format("particles/particles_{:06d}.vtp", frame);
    fs::create_directories(directory / "particles");
    write_vtp(directory / file, points);
    particles.add(sim.clock().time, file);
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
