// SPDX-License-Identifier: MIT
#include "fddem/simulation/simulation_setup.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/coupling/markers.hpp"

#include <algorithm>
#include <string>

namespace fddem {

template <int Dim>
MacGrid<Dim> make_grid(const CaseConfig& config)
{
    if (config.dimension != Dim || config.size.size() != static_cast<std::size_t>(Dim) ||
        config.cells.size() != static_cast<std::size_t>(Dim)) {
        throw InputError(config.source_file, 0, "domain.size",
                         "the case is " + std::to_string(config.dimension) + "-dimensional, not " +
                             std::to_string(Dim) + "-dimensional");
    }
    Index<Dim> cells{};
    Vec<Dim> origin = Vec<Dim>::Zero();
    Vec<Dim> length;
    std::array<bool, Dim> is_periodic{};
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        cells[k] = config.cells[k];
        length[d] = config.size[k];
        if (config.origin.size() == static_cast<std::size_t>(Dim)) {
            origin[d] = config.origin[k];
        }
        is_periodic[k] = k < config.periodic.size() && config.periodic[k];
    }
    return MacGrid<Dim>(cells, origin, length, is_periodic);
}

template <int Dim>
BoundaryConditions<Dim> make_boundary_conditions(const CaseConfig& config)
{
    BoundaryConditions<Dim> bc = BoundaryConditions<Dim>::closed_box();
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        bc.is_periodic[k] = k < config.periodic.size() && config.periodic[k];
        for (std::size_t side = 0; side < 2 && k < config.boundary_kind.size(); ++side) {
            const std::string& kind = config.boundary_kind[k][side];
            bc.kind[k][side] = kind == "inflow"    ? BoundaryKind::inflow
                               : kind == "outflow" ? BoundaryKind::outflow
                                                   : BoundaryKind::wall;
        }
        if (k >= config.wall_velocity.size()) {
            continue;
        }
        for (std::size_t side = 0; side < 2; ++side) {
            bc.wall_velocity[k][side] = vector_of<Dim>(config.wall_velocity[k][side]);
        }
    }
    bc.inflow = {config.inflow_profile == "parabolic", config.inflow_velocity};
    return bc;
}

template <int Dim>
Vec<Dim> vector_of(const std::vector<double>& values)
{
    Vec<Dim> v = Vec<Dim>::Zero();
    for (int a = 0; a < Dim && static_cast<std::size_t>(a) < values.size(); ++a) {
        v[a] = values[static_cast<std::size_t>(a)];
    }
    return v;
}

template <int Dim>
Particles<Dim> make_particles(const CaseConfig& config, const MacGrid<Dim>& grid)
{
    Particles<Dim> bodies;
    for (std::size_t k = 0; k < config.bodies.size(); ++k) {
        const BodyConfig& b = config.bodies[k];
        Particle<Dim> body;
        body.id = static_cast<int>(k);
        body.shape = Ball<Dim>{b.diameter};
        body.density = b.density;
        body.material = b.material;
        body.motion = b.motion == "fixed"        ? Motion::fixed
                      : b.motion == "prescribed" ? Motion::prescribed
                                                 : Motion::free;
        body.centre = grid.domain().wrap(vector_of<Dim>(b.position)); // in the box
        if (body.motion != Motion::fixed) {
            body.velocity = vector_of<Dim>(b.velocity);
        }
        if constexpr (Dim == 2) {
            body.omega = body.motion == Motion::fixed ? 0.0 : b.omega;
        }
        const int n_rings = b.n_rings > 0
                                ? b.n_rings
                                : rings_for_spacing(body.radius(), grid.spacing().maxCoeff(),
                                                    config.marker_spacing_ratio);
        body.coupling = MarkerCoupling<Dim>(make_ball_markers(body.shape, n_rings));
        bodies.add(std::move(body));
    }
    return bodies;
}

template <int Dim>
std::optional<ContactSetup<Dim>>
make_contact_setup(const CaseConfig& config, const MacGrid<Dim>& grid,
                   const BoundaryConditions<Dim>& bc, const Particles<Dim>& bodies)
{
    if (!bodies.has_free_body()) {
        return std::nullopt;
    }
    const ContactModelInput input{
        {config.contact_stiffness, config.contact_damping, config.contact_tangential_ratio},
        config.contact_reference_mass};
    std::optional<AnyContactModel> model = make_contact_model(config.contact_model, input);
    if (!model) {
        return std::nullopt; // contact.model = "none": no collisions
    }
    double largest = 0.0;
    for (const Particle<Dim>& body : bodies) {
        largest = std::max(largest, body.shape.diameter);
    }
    // The range reaches one smallest radius beyond contact + margin: the skin of the DEM's
    // neighbour list (contact/neighbour_list.hpp), rebuilt when a body has moved half of it.
    double smallest = largest;
    for (const Particle<Dim>& body : bodies) {
        smallest = std::min(smallest, body.shape.diameter);
    }
    DemWalls<Dim> walls{grid.origin(), grid.length(), {}};
    walls.material = config.wall_material;
    for (int d = 0; d < Dim; ++d) {
        const auto axis = static_cast<std::size_t>(d);
        walls.has_walls[axis] = !bc.is_periodic[axis];
        for (int side = 0; side < 2; ++side) {
            walls.velocity[axis][static_cast<std::size_t>(side)] = bc.wall(d, side);
        }
    }
    return ContactSetup<Dim>{
        DemSettings{std::move(*model), config.contact_beta, std::max(1, config.contact_substeps),
                    config.contact_margin},
        config.contact_coupling == "paper",
        CellList<Dim>(grid.domain(), largest + config.contact_margin + 0.5 * smallest), walls};
}

#define FDDEM_INSTANTIATE_SETUP(DIM)                                                               \
    template MacGrid<DIM> make_grid<DIM>(const CaseConfig&);                                       \
    template BoundaryConditions<DIM> make_boundary_conditions<DIM>(const CaseConfig&);             \
    template Vec<DIM> vector_of<DIM>(const std::vector<double>&);                                  \
    template Particles<DIM> make_particles<DIM>(const CaseConfig&, const MacGrid<DIM>&);           \
    template std::optional<ContactSetup<DIM>> make_contact_setup<DIM>(                             \
        const CaseConfig&, const MacGrid<DIM>&, const BoundaryConditions<DIM>&,                    \
        const Particles<DIM>&);
FDDEM_INSTANTIATE_SETUP(2)
FDDEM_INSTANTIATE_SETUP(3)
#undef FDDEM_INSTANTIATE_SETUP

} // namespace fddem
