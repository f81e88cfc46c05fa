// SPDX-License-Identifier: MIT
#include "fddem/run/body_snapshot.hpp"

namespace fddem {

template <int Dim>
std::vector<BodySnapshot<Dim>> body_snapshots(const Simulation<Dim>& sim)
{
    std::vector<BodySnapshot<Dim>> snapshots;
    snapshots.reserve(sim.bodies().size());
    for (const Particle<Dim>& body : sim.bodies()) {
        snapshots.push_back(
            {.id = body.id,
             .radius = body.shape.radius(),
             .centre = body.centre,
             .velocity = body.velocity,
             .omega = body.omega,
             .orientation = body.orientation,
             .force = body.force,
             .torque = body.torque,
             .contact_force = body.contact.mean_force - body.contact.lubrication_force,
             .contact_torque = body.contact.mean_torque - body.contact.lubrication_torque,
             .lubrication_force = body.contact.lubrication_force,
             .lubrication_torque = body.contact.lubrication_torque});
    }
    return snapshots;
}

template <int Dim>
std::size_t body_count(const Simulation<Dim>& sim)
{
    return sim.bodies().size();
}

template <int Dim>
std::size_t markers_per_body(const Simulation<Dim>& sim)
{
    return sim.bodies().empty() ? 0 : sim.bodies().front().coupling.markers.size();
}

template std::vector<BodySnapshot<2>> body_snapshots(const Simulation<2>&);
template std::vector<BodySnapshot<3>> body_snapshots(const Simulation<3>&);
template std::size_t body_count(const Simulation<2>&);
template std::size_t body_count(const Simulation<3>&);
template std::size_t markers_per_body(const Simulation<2>&);
template std::size_t markers_per_body(const Simulation<3>&);

} // namespace fddem
