// SPDX-License-Identifier: MIT
#include "fddem/simulation/simulation_setup.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/coupling/markers.hpp"
#include "fddem/grid/grid_partition.hpp"
#include "fddem/simulation/contact_model_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>

namespace fddem {

template <int Dim>
MacGrid<Dim> make_grid(const CaseConfig& config, const Communicator& ranks)
{
    const DomainConfig& domain = config.domain;
    if (domain.dimension != Dim || domain.size.size() != static_cast<std::size_t>(Dim) ||
        domain.cells.size() != static_cast<std::size_t>(Dim)) {
        throw InputError(config.source_file, 0, "domain.size",
                         "the case is " + std::to_string(domain.dimension) + "-dimensional, not " +
                             std::to_string(Dim) + "-dimensional");
    }
    Index<Dim> cells{};
    Vec<Dim> origin = Vec<Dim>::Zero();
    Vec<Dim> length;
    std::array<bool, Dim> is_periodic{};
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        cells[k] = domain.cells[k];
        length[d] = domain.size[k];
        if (domain.origin.size() == static_cast<std::size_t>(Dim)) {
            origin[d] = domain.origin[k];
        }
        is_periodic[k] = k < domain.periodic.size() && domain.periodic[k];
    }
    if (ranks.size() == 1) {
        return MacGrid<Dim>(cells, origin, length, is_periodic);
    }
    return MacGrid<Dim>(
        cells, origin, length, is_periodic,
        partition_grid<Dim>(ranks, cells, is_periodic, rank_layout<Dim>(config, ranks.size())));
}

template <int Dim>
Index<Dim> rank_layout(const CaseConfig& config, int n_ranks)
{
    Index<Dim> cells{};
    std::copy_n(config.domain.cells.begin(), Dim, cells.begin());
    Index<Dim> layout{};
    try {
        if (config.parallel.ranks.empty()) {
            layout = choose_rank_layout<Dim>(cells, n_ranks);
        } else {
            // parallel.ranks (its entry count is the dimension's: io/case_keys)
            std::copy_n(config.parallel.ranks.begin(), Dim, layout.begin());
            check_rank_layout<Dim>(cells, layout, n_ranks);
        }
    } catch (const InputError& e) { // the grid's checks do not know the case file
        throw InputError(config.source_file, 0, e.key(), e.what());
    }
    return layout;
}

template <int Dim>
BoundaryConditions<Dim> make_boundary_conditions(const CaseConfig& config)
{
    BoundaryConditions<Dim> bc = BoundaryConditions<Dim>::closed_box();
    for (int d = 0; d < Dim; ++d) {
        const auto k = static_cast<std::size_t>(d);
        bc.is_periodic[k] = k < config.domain.periodic.size() && config.domain.periodic[k];
        if (k < config.boundaries.size()) {
            bc.kind[k] = config.boundaries[k];
        }
        if (k >= config.walls.velocity.size()) {
            continue;
        }
        for (std::size_t side = 0; side < 2; ++side) {
            bc.wall_velocity[k][side] = vector_of<Dim>(config.walls.velocity[k][side]);
        }
    }
    bc.inflow = {config.inflow.profile, config.inflow.velocity};
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
AngularVec<Dim> angular_of(const std::vector<double>& values)
{
    if constexpr (Dim == 2) {
        return values.empty() ? 0.0 : values.front();
    } else {
        return vector_of<3>(values);
    }
}

/// The markers of a ball: the paper's layout, or the outer ring `coupling.marker_retraction` h
/// inside the surface, with the rings inside it or alone ("surface"); N_a from bodies.n_rings,
/// else from coupling.marker_spacing_ratio.
template <int Dim>
MarkerSet<Dim> body_markers(const Ball<Dim>& ball, int n_rings, const CaseConfig& config, double h)
{
    const CouplingConfig& coupling = config.coupling;
    const double ratio = coupling.marker_spacing_ratio;
    if (coupling.markers == MarkerLayout::paper) {
        return make_ball_markers(ball, n_rings > 0 ? n_rings
                                                   : rings_for_spacing(ball.radius(), h, ratio));
    }
    const double retraction = coupling.marker_retraction * h;
    if (retraction >= 0.5 * ball.radius()) {
        throw InputError(config.source_file, 0, "coupling.marker_retraction",
                         fmt::format("retracts the outer marker ring by {:g} ({:g} h), not less "
                                     "than half the radius ({:g}) of a body of diameter {:g}: "
                                     "refine the grid or lower the retraction",
                                     retraction, coupling.marker_retraction, 0.5 * ball.radius(),
                                     2.0 * ball.radius()));
    }
    if (coupling.markers == MarkerLayout::surface) {
        return make_surface_ball_markers(ball, retraction, ratio * h, h);
    }
    return make_retracted_ball_markers(
        ball,
        n_rings > 0 ? n_rings : retracted_rings_for_spacing(ball.radius(), retraction, h, ratio),
        retraction);
}

template <int Dim>
Particles<Dim> make_particles(const CaseConfig& config, const MacGrid<Dim>& grid)
{
    Particles<Dim> bodies;
    for (std::size_t k = 0; k < config.bodies.size(); ++k) {
        const BodyConfig& b = config.bodies[k];
        Particle<Dim> body;
        body.id = b.id;
        body.shape = Ball<Dim>{b.diameter};
        body.density = b.density;
        body.material = b.material;
        body.motion = b.motion;
        body.release_time = b.release_time;
        body.centre = grid.domain().wrap(vector_of<Dim>(b.position)); // in the box
        if (body.motion != Motion::fixed) {
            body.velocity = vector_of<Dim>(b.velocity);
        }
        if (body.motion != Motion::fixed) {
            body.omega = angular_of<Dim>(b.omega);
        }
        body.coupling = MarkerCoupling<Dim>(
            body_markers(body.shape, b.n_rings, config, grid.spacing().maxCoeff()));
        bodies.add(std::move(body));
    }
    return bodies;
}

template <int Dim>
std::optional<ContactSetup<Dim>>
make_contact_setup(const CaseConfig& config, const MacGrid<Dim>& grid,
                   const BoundaryConditions<Dim>& bc, const Particles<Dim>& bodies)
{
    // Without a body that is free or will be released nothing can collide; the lubrication
    // still acts on (and is reported for) prescribed bodies near walls and each other when on.
    if (bodies.empty() || (!bodies.has_moving_body() && !config.lubrication.is_enabled)) {
        return std::nullopt;
    }
    const ContactConfig& contact = config.contact;
    // Without a free body no contact force is ever evaluated (the DEM skips pairs and walls
    // that cannot move) and the case derived no model: a placeholder stands in, and the
    // sub-steps are contact.substeps as given (at least 1), over which the lubrication is
    // averaged.
    const bool can_collide = bodies.has_moving_body();
    std::optional<AnyContactModel> model =
        can_collide ? make_contact_model(contact.model, contact_model_input(config))
                    : std::optional<AnyContactModel>(LinearSpringDashpot({1.0, 0.0}, 1.0));
    const int substeps = can_collide ? contact.derived.substeps : contact.substeps;
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
    walls.material = config.walls.material;
    for (int d = 0; d < Dim; ++d) {
        const auto axis = static_cast<std::size_t>(d);
        walls.has_walls[axis] = !bc.is_periodic[axis];
        for (int side = 0; side < 2; ++side) {
            walls.velocity[axis][static_cast<std::size_t>(side)] = bc.wall(d, side);
        }
    }
    // Lubrication acts up to its range h_Δ (in the largest grid spacing): the DEM's neighbour
    // list must reach that far when it is on.
    const LubricationConfig& lub = config.lubrication;
    const LubricationSettings lubrication{
        lub.is_enabled, config.fluid.viscosity, lub.range * grid.spacing().maxCoeff(),
        lub.roughness,  lub.in_contact,         lub.resolved,
        lub.coupling,   lub.film_solve};
    const double reach = std::max(contact.margin, lubrication.is_enabled ? lubrication.range : 0.0);
    return ContactSetup<Dim>{DemSettings{std::move(*model), contact.velocity_damping,
                                         std::max(1, substeps), contact.margin, lubrication,
                                         held_fluid_force_acts_in_contact(contact.fluid_force)},
                             contact.coupling == ContactCoupling::paper,
                             CellList<Dim>(grid.domain(), largest + reach + 0.5 * smallest), walls};
}

#define FDDEM_INSTANTIATE_SETUP(DIM)                                                               \
    template MacGrid<DIM> make_grid<DIM>(const CaseConfig&, const Communicator&);                  \
    template Index<DIM> rank_layout<DIM>(const CaseConfig&, int);                                  \
    template BoundaryConditions<DIM> make_boundary_conditions<DIM>(const CaseConfig&);             \
    template Vec<DIM> vector_of<DIM>(const std::vector<double>&);                                  \
    template AngularVec<DIM> angular_of<DIM>(const std::vector<double>&);                          \
    template Particles<DIM> make_particles<DIM>(const CaseConfig&, const MacGrid<DIM>&);           \
    template std::optional<ContactSetup<DIM>> make_contact_setup<DIM>(                             \
        const CaseConfig&, const MacGrid<DIM>&, const BoundaryConditions<DIM>&,                    \
        const Particles<DIM>&);
FDDEM_INSTANTIATE_SETUP(2)
FDDEM_INSTANTIATE_SETUP(3)
#undef FDDEM_INSTANTIATE_SETUP

} // namespace fddem
