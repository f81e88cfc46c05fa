// SPDX-License-Identifier: MIT
#include "fddem/io/case_schema.hpp"

#include "fddem/io/body_entries.hpp"
#include "fddem/io/contact_derivation.hpp"
#include "fddem/io/key_binding.hpp"

#include <fmt/format.h>

namespace fddem {
namespace {

using detail::body_key;
using detail::bound;
using detail::bound_in;
using detail::entry_of;
using detail::line_key;

constexpr double inf = std::numeric_limits<double>::infinity();

KeySpec key(std::string section, std::string name, KeyType type, std::string unit,
            std::optional<std::string> value, std::string doc)
{
    KeySpec spec;
    spec.section = std::move(section);
    spec.name = std::move(name);
    spec.type = type;
    spec.unit = std::move(unit);
    spec.value = std::move(value);
    spec.doc = std::move(doc);
    return spec;
}

KeySpec ranged(KeySpec spec, double min, double max, bool is_min_open, bool is_max_open)
{
    spec.min = min;
    spec.max = max;
    spec.is_min_open = is_min_open;
    spec.is_max_open = is_max_open;
    return spec;
}

KeySpec positive(KeySpec spec)
{
    return ranged(std::move(spec), 0.0, inf, true, false);
}

/// The velocity of one wall, [walls] x_low…z_high.
auto wall_velocity(std::size_t axis, std::size_t side)
{
    return [axis, side](CaseConfig& config, std::size_t /*entry*/) -> std::vector<double>& {
        return entry_of(config.walls.velocity, axis).at(side);
    };
}

/// What one side is, [boundaries] x_low…z_high.
auto boundary_kind(std::size_t axis, std::size_t side)
{
    return [axis, side](CaseConfig& config, std::size_t /*entry*/) -> BoundaryKind& {
        return entry_of(config.boundaries, axis).at(side);
    };
}

/// The surface keys of [[bodies]] and [walls]: each falls back to the [contact] key of the
/// same name (`whose`: "body" or "walls"). `surface(config, entry)` is where they go.
template <class Surface>
void add_material_keys(std::vector<KeySpec>& s, const std::string& section,
                       const std::string& whose, Surface surface)
{
    const std::string fallback = "none";
    s.push_back(bound_in(surface,
                         positive(key(section, "young_modulus", KeyType::real, "Pa", fallback,
                                      "Hertz–Mindlin: Young's modulus E of the " + whose +
                                          "; default contact.young_modulus.")),
                         &SurfaceKeys::young_modulus));
    s.push_back(bound_in(surface,
                         ranged(key(section, "poisson_ratio", KeyType::real, "", fallback,
                                    "Hertz–Mindlin: Poisson ratio ν of the " + whose +
                                        "; default contact.poisson_ratio."),
                                0.0, 0.5, false, true),
                         &SurfaceKeys::poisson_ratio));
    s.push_back(bound_in(surface,
                         ranged(key(section, "friction", KeyType::real, "", fallback,
                                    "Sliding friction coefficient μ_s of the " + whose +
                                        "; default contact.friction."),
                                0.0, inf, false, false),
                         &SurfaceKeys::friction));
    s.push_back(bound_in(surface,
                         ranged(key(section, "rolling_friction", KeyType::real, "", fallback,
                                    "Rolling friction coefficient μ_r of the " + whose +
                                        "; default contact.rolling_friction."),
                                0.0, inf, false, false),
                         &SurfaceKeys::rolling_friction));
    s.push_back(bound_in(surface,
                         ranged(key(section, "restitution", KeyType::real, "", fallback,
                                    "Hertz–Mindlin: restitution coefficient e of the " + whose +
                                        "; default contact.restitution."),
                                0.0, 1.0, true, false),
                         &SurfaceKeys::restitution));
}

/// The keys of a [[bodies]] entry that gives many bodies (io/body_entries.hpp): from a file,
/// or inserted at random. Its other keys (shape, motion, n_rings, surface) are every body's.
void add_body_group_keys(std::vector<KeySpec>& s)
{
    using T = KeyType;
    const auto group = [](KeySpec spec, auto member) {
        return bound_in(
            [](CaseConfig& config, std::size_t entry) -> BodyGroupConfig& {
                return entry_of(config.body_groups, entry);
            },
            std::move(spec), member);
    };
    s.push_back(group(
        key("bodies", "file", T::string, "", "none",
            "A CSV file of bodies, relative to the case file: a header naming the columns id, x, "
            "y, (z,) diameter, density and optionally u, v, (w), then one body per row (ids: "
            "whole numbers ≥ 0, unique in the case). The entry's other keys apply to every row; "
            "velocity, unless the file has u, v, (w). Entries without a file number their "
            "bodies on from the largest id before them."),
        &BodyGroupConfig::file));
    s.push_back(group(ranged(key("bodies", "count", T::integer, "", "none",
                                 "Random insertion: this many bodies of the entry's diameter at "
                                 "random places in the region, none closer than bodies.gap to "
                                 "another body or to the region's faces."),
                             1, static_cast<double>(max_inserted_bodies), false, false),
                      &BodyGroupConfig::count));
    s.push_back(group(ranged(key("bodies", "volume_fraction", T::real, "", "none",
                                 "Random insertion: as many bodies as fill this fraction of the "
                                 "region (within half a body); random sequential addition jams "
                                 "near 0.547 (2D) and 0.384 (3D)."),
                             0.0, 1.0, true, true),
                      &BodyGroupConfig::volume_fraction));
    s.push_back(group(key("bodies", "region_low", T::real_vector, "m", "none",
                          "Random insertion: the region's lower corner; default the box's."),
                      &BodyGroupConfig::region_low));
    s.push_back(group(key("bodies", "region_high", T::real_vector, "m", "none",
                          "Random insertion: the region's upper corner; default the box's."),
                      &BodyGroupConfig::region_high));
    s.push_back(group(ranged(key("bodies", "seed", T::integer, "", "none",
                                 "Random insertion: seed of the random numbers (std::mt19937_64; "
                                 "the same seed places the same bodies on every machine); "
                                 "default 0."),
                             0, inf, false, false),
                      &BodyGroupConfig::seed));
    s.push_back(group(ranged(key("bodies", "gap", T::real, "m", "none",
                                 "Random insertion: the least clearance between inserted bodies, "
                                 "and from the region's faces; default 0."),
                             0.0, inf, false, false),
                      &BodyGroupConfig::gap));
}

} // namespace

std::vector<KeySpec> case_schema()
{
    using T = KeyType;
    const std::string none;
    std::vector<KeySpec> s;
    s.push_back(
        bound(key("case", "title", T::string, none, "\"\"", "A one-line description of the case."),
              &CaseConfig::title));

    s.push_back(
        bound(key("domain", "origin", T::real_vector, "m", "zeros", "Lower corner of the box."),
              &CaseConfig::domain, &DomainConfig::origin));
    s.push_back(
        bound(positive(key("domain", "size", T::real_vector, "m", std::nullopt,
                           "Side lengths of the box; 2 entries make a 2D case, 3 a 3D one.")),
              &CaseConfig::domain, &DomainConfig::size));
    s.push_back(
        bound(ranged(key("domain", "cells", T::integer_vector, none, std::nullopt,
                         "Cells along each axis (the grid is uniform; equal spacing per axis "
                         "is recommended)."),
                     4, 1000000, false, false),
              &CaseConfig::domain, &DomainConfig::cells));
    s.push_back(bound(key("domain", "periodic", T::boolean_vector, none, "false",
                          "Whether each axis is periodic (else walled on both sides)."),
                      &CaseConfig::domain, &DomainConfig::periodic));

    for (std::size_t axis = 0; axis < side_names.size(); ++axis) {
        for (std::size_t side = 0; side < 2; ++side) {
            const std::string wall = side_names.at(axis).at(side);
            s.push_back(bound_in(
                wall_velocity(axis, side),
                key("walls", wall, T::real_vector, "m/s", "zeros",
                    fmt::format("Velocity of the {} wall; only tangential components may be "
                                "non-zero (a sliding wall, e.g. a lid).",
                                wall))));
        }
    }
    add_material_keys(s, "walls", "walls (all share one set)",
                      [](CaseConfig& config, std::size_t /*entry*/) -> SurfaceKeys& {
                          return config.walls.surface;
                      });

    for (std::size_t axis = 0; axis < side_names.size(); ++axis) {
        for (std::size_t side = 0; side < 2; ++side) {
            const std::string name = side_names.at(axis).at(side);
            s.push_back(
                bound_in(boundary_kind(axis, side),
                         key("boundaries", name, T::string, none, "\"wall\"",
                             fmt::format("What the {} side of a non-periodic axis is: a wall "
                                         "(no slip; [walls] sets its velocity), an inflow "
                                         "([inflow] sets its velocity) or an outflow (zero "
                                         "normal gradient, carrying the inflow's volume flux).",
                                         name))));
        }
    }
    s.push_back(bound(key("inflow", "profile", T::string, none, "\"uniform\"",
                          "Normal velocity over every inflow side: uniform, or parabolic (Π 4s(1 "
                          "− s) over the walled transverse axes, s the fraction across the box: "
                          "a channel's Poiseuille profile, mean 2/3 of the maximum in 2D)."),
                      &CaseConfig::inflow, &InflowConfig::profile));
    s.push_back(
        bound(positive(key("inflow", "velocity", T::real, "m/s", "none",
                           "Inflow speed into the box: the uniform speed, or the parabola's "
                           "maximum (centre line). Required when a side is an inflow.")),
              &CaseConfig::inflow, &InflowConfig::velocity));

    s.push_back(bound(
        positive(key("fluid", "density", T::real, "kg/m³", std::nullopt, "Fluid density ρf.")),
        &CaseConfig::fluid, &FluidConfig::density));
    s.push_back(
        bound(positive(key("fluid", "viscosity", T::real, "Pa·s", "none",
                           "Dynamic viscosity μ; required unless [nondimensional] gives reynolds, "
                           "from which it is derived.")),
              &CaseConfig::fluid, &FluidConfig::viscosity));
    s.push_back(bound(key("fluid", "gravity", T::real_vector, "m/s²", "zeros",
                          "Gravitational acceleration; it acts on particles only (buoyancy-reduced "
                          "weight), the fluid's hydrostatic pressure is not computed."),
                      &CaseConfig::fluid, &FluidConfig::gravity));
    s.push_back(bound(key("fluid", "body_force", T::real_vector, "N/m³", "zeros",
                          "A uniform force per unit volume on the fluid, e.g. to drive a periodic "
                          "channel."),
                      &CaseConfig::fluid, &FluidConfig::body_force));

    s.push_back(bound(positive(key("time", "dt", T::real, "s", std::nullopt, "Time step Δt.")),
                      &CaseConfig::time, &TimeConfig::dt));
    s.push_back(bound(positive(key("time", "end", T::real, "s", "none",
                                   "End time; at least one of time.end, time.steady_tolerance and "
                                   "time.rest_speed is required. With the fixed time.dt it must be "
                                   "a whole number of steps, at most time.max_steps of them.")),
                      &CaseConfig::time, &TimeConfig::end));
    s.push_back(bound(positive(key("time", "steady_tolerance", T::real, none, "none",
                                   "Stop when the flow is steady: max|u^{n+1} − u^n|/Δt · L/U² "
                                   "below this (L the smallest box side, U the largest speed).")),
                      &CaseConfig::time, &TimeConfig::steady_tolerance));
    s.push_back(
        bound(positive(key("time", "rest_speed", T::real, "m/s", "none",
                           "Stop when the particles have settled: every free body's speed "
                           "|U| + |ω|R below this for time.rest_duration (bodies at rest from "
                           "the start count as settled: see time.min_end).")),
              &CaseConfig::time, &TimeConfig::rest_speed));
    s.push_back(bound(positive(key("time", "rest_duration", T::real, "s", "0.1",
                                   "How long every free body must stay below time.rest_speed.")),
                      &CaseConfig::time, &TimeConfig::rest_duration));
    s.push_back(bound(ranged(key("time", "min_end", T::real, "s", "0",
                                 "The earliest time at which time.rest_speed or "
                                 "time.steady_tolerance may end the run."),
                             0.0, inf, false, false),
                      &CaseConfig::time, &TimeConfig::min_end));
    s.push_back(bound(ranged(key("time", "max_steps", T::integer, none, "100000000",
                                 "Stop after this many steps."),
                             1, inf, false, false),
                      &CaseConfig::time, &TimeConfig::max_steps));
    s.push_back(
        bound(positive(key("time", "max_courant", T::real, none, "none",
                           "Adaptive time step: Δt limited so that the fluid and the bodies "
                           "move at most this many cells per step (max |u_d| Δt / h_d and "
                           "(|U| + |ω|R) Δt / h); time.dt is then the first and the largest "
                           "step, and Δt grows by at most 1.2× per step. None: the fixed "
                           "time.dt.")),
              &CaseConfig::time, &TimeConfig::max_courant));
    s.push_back(bound(
        positive(
            key("time", "min_dt", T::real, "s", "none",
                "With time.max_courant: the shortest step the Courant limit "
                "may ask for (none: 1e-6 × time.dt). Below it the run stops as a numerical failure "
                "(exit status 3, the outputs and a checkpoint of the last "
                "good step written): a flow whose speed grows as Δt "
                "shrinks has diverged, and would otherwise march on at ever "
                "smaller steps without end.")),
        &CaseConfig::time, &TimeConfig::min_dt));
    s.push_back(bound(
        ranged(key("time", "max_retries", T::integer, none, "3",
                   "With time.max_courant: how often a failed step is taken again from its "
                   "start at half its Δt (the controller then grows Δt back by at most 1.2× a "
                   "step). A step fails if its flow blows up, or if it ends above "
                   "time.retry_mass_residual or time.retry_courant. A step that still fails "
                   "after the last retry is kept as it is (solver.csv's retries column shows "
                   "it; a blow-up stops the run, exit status 3); no retry goes below "
                   "time.min_dt. 0: never retry."),
               0, 60, false, false),
        &CaseConfig::time, &TimeConfig::max_retries));
    s.push_back(bound(positive(key("time", "retry_mass_residual", T::real, none, "none",
                                   "With time.max_courant: a step whose outer iterations end "
                                   "with a mass residual (solver.csv) above this is retried at "
                                   "half its Δt (time.max_retries). None: not a reason to "
                                   "retry.")),
                      &CaseConfig::time, &TimeConfig::retry_mass_residual));
    s.push_back(bound(positive(key("time", "retry_courant", T::real, none, "none",
                                   "With time.max_courant: a step whose Courant number after "
                                   "it (solver.csv) is above this is retried at half its Δt "
                                   "(time.max_retries): the flow sped up within the step "
                                   "beyond what the limit allowed for (none: 4 × "
                                   "time.max_courant, beyond what the runs measured reached "
                                   "without failing; docs/method.md §1, Retries). A very large "
                                   "value turns this reason alone off; time.max_retries = 0 "
                                   "turns every retry off.")),
                      &CaseConfig::time, &TimeConfig::retry_courant));
    s.push_back(bound(key("time", "steady", T::boolean, none, "false",
                          "Pseudo-time march to a steady state (needs time.steady_tolerance, no "
                          "free bodies): Δt starts at time.dt and follows the residual, Δt ← Δt · "
                          "r_old/r_new (switched evolution relaxation, Mulder & van Leer 1985), at "
                          "most 2× per step and within time.max_courant if given. Intermediate "
                          "states are not time-accurate."),
                      &CaseConfig::time, &TimeConfig::is_steady));
    s.push_back(bound(key("time", "scheme", T::string, none, "\"euler\"",
                          "Time derivative of the momentum equations and of the bodies' "
                          "eqs. (13)–(14): euler (implicit Euler, first order, the paper's) or "
                          "bdf2 (second-order backward differences, with the variable-step "
                          "coefficients when Δt changes; the first step is Euler; "
                          "docs/method.md §4)."),
                      &CaseConfig::time, &TimeConfig::scheme));

    s.push_back(bound(key("simple", "algorithm", T::string, none, "\"simple\"",
                          "What a time step of the fluid is: simple (outer iterations of the "
                          "momentum solve, the projection and, with bodies, eqs. (13)–(16), until "
                          "the residuals are below simple.tolerance: the paper's) or projection "
                          "(one momentum predictor, solved until its residual is below "
                          "simple.tolerance, one projection and, with bodies, one pass of eqs. "
                          "(13)–(16): the incremental pressure-correction scheme, 1.7–4.4 "
                          "times faster in the cases measured; with bodies: time.scheme "
                          "\"euler\" and coupling.normalised_forcing only, no free body lighter "
                          "than the fluid, and a step with "
                          "a body in contact or within two kernel widths of a wall or another "
                          "body takes simple's iterations; docs/method.md §1)."),
                      &CaseConfig::simple, &SimpleConfig::algorithm));
    s.push_back(bound(ranged(key("simple", "tolerance", T::real, none, "1e-5",
                                 "SIMPLE convergence: normalised mass and momentum residuals below "
                                 "this end a step's outer iterations (simple.algorithm = "
                                 "\"projection\": the predictor's momentum residual)."),
                             0.0, 1.0, true, true),
                      &CaseConfig::simple, &SimpleConfig::tolerance));
    s.push_back(bound(key("simple", "converge_fluid_with_bodies", T::boolean, none, "false",
                          "With bodies, end a step only when the fluid's mass and momentum "
                          "residuals are below simple.tolerance as well as the bodies' change "
                          "(false: the bodies' change alone, as the paper's cases run; "
                          "docs/method.md §4)."),
                      &CaseConfig::simple, &SimpleConfig::is_fluid_converged_with_bodies));
    s.push_back(bound(ranged(key("simple", "max_outer_iterations", T::integer, none, "50",
                                 "Outer iterations per step at most (a step that reaches it is "
                                 "reported as not converged; simple.algorithm = \"projection\": "
                                 "rounds of the predictor's solve at most)."),
                             1, 10000, false, false),
                      &CaseConfig::simple, &SimpleConfig::max_outer_iterations));
    s.push_back(bound(ranged(key("simple", "min_outer_iterations_dem", T::integer, none, "2",
                                 "Outer iterations a step takes at least when a free body the "
                                 "DEM moves (paper coupling, in contact or within the "
                                 "lubrication range) is in it. Its velocity is given for the "
                                 "step, so the test on the bodies' change says nothing about "
                                 "it after one iteration: with 1 a pile at rest takes one "
                                 "iteration a step, which grows the mass residual until the "
                                 "run fails; 2 holds it (docs/method.md §5, \"A pile at "
                                 "rest\")."),
                             1, 10, false, false),
                      &CaseConfig::simple, &SimpleConfig::min_outer_iterations_dem));
    s.push_back(bound(key("simple", "hold_mass_residual", T::boolean, none, "false",
                          "With bodies, end a step only once the mass residual is no larger "
                          "than at the step's start (or has stopped falling, from the third "
                          "outer iteration), as well as the bodies' change below "
                          "simple.tolerance: for a free body that barely answers its fluid, "
                          "whose steps otherwise end while the fluid diverges (docs/method.md "
                          "§5, \"The fluid's residual held\")."),
                      &CaseConfig::simple, &SimpleConfig::is_mass_residual_held));
    s.push_back(bound(ranged(key("simple", "velocity_relaxation", T::real, none, "1.0",
                                 "Under-relaxation α_u of the momentum equations."),
                             0.0, 1.0, true, false),
                      &CaseConfig::simple, &SimpleConfig::velocity_relaxation));
    s.push_back(bound(ranged(key("simple", "pressure_relaxation", T::real, none, "1.0",
                                 "Under-relaxation α_p of the pressure correction, eq. (10)."),
                             0.0, 1.0, true, false),
                      &CaseConfig::simple, &SimpleConfig::pressure_relaxation));
    s.push_back(bound(key("simple", "pressure_update", T::string, none, "\"rotational\"",
                          "How eq. (10) updates p from p′: standard (p* + α_p p′, the paper's) "
                          "or rotational (p* + α_p (p′ − μ∇·u*): the same converged answer in "
                          "fewer outer iterations where viscosity acts within a cell in Δt; "
                          "docs/method.md §1)."),
                      &CaseConfig::simple, &SimpleConfig::pressure_update));
    s.push_back(bound(ranged(key("simple", "acceleration_depth", T::integer, none, "2",
                                 "Anderson acceleration of the outer iterations of a step with "
                                 "bodies: how many earlier iterates it combines (0: off; "
                                 "docs/method.md §4)."),
                             0, 10, false, false),
                      &CaseConfig::simple, &SimpleConfig::acceleration_depth));
    s.push_back(bound(ranged(key("simple", "acceleration_weight_bits", T::integer, none, "12",
                                 "Significant bits the Anderson acceleration's weights are "
                                 "rounded to, so that round-off (another number of MPI ranks) "
                                 "does not move them (0: not rounded; docs/parallel.md, "
                                 "\"Anderson mixing and the same answer\")."),
                             0, 52, false, false),
                      &CaseConfig::simple, &SimpleConfig::acceleration_weight_bits));
    s.push_back(bound(
        ranged(key("simple", "acceleration_max_step", T::real, "", "0",
                   "The largest step the Anderson acceleration may take beyond an outer "
                   "iteration's output, as a multiple of that iteration's residual (the 2-norm "
                   "over all bodies of the change of U and ωR); a larger one is refused and the "
                   "mixing restarts (0: not "
                   "bounded; 100 still accelerates modes that contract by up to 0.99 an "
                   "iteration; docs/method.md §4, \"The mixing's step bounded\")."),
               0.0, 1e6, false, false),
        &CaseConfig::simple, &SimpleConfig::acceleration_max_step));
    s.push_back(
        bound(ranged(key("simple", "momentum_sweeps", T::integer, none, "4",
                         "Red-black Gauss–Seidel sweeps of the momentum equations per V-cycle "
                         "(half before the coarse correction, half after), or per outer "
                         "iteration without cycles."),
                     1, 100, false, false),
              &CaseConfig::simple, &SimpleConfig::momentum_sweeps));
    s.push_back(
        bound(ranged(key("simple", "momentum_cycles", T::integer, none, "1",
                         "Multigrid V-cycles (additive correction) of the momentum equations "
                         "per outer iteration, when the multigrid is used; 0: sweeps alone."),
                     0, 20, false, false),
              &CaseConfig::simple, &SimpleConfig::momentum_cycles));
    s.push_back(bound(key("simple", "momentum_solver", T::string, none, "\"auto\"",
                          "Momentum solve: multigrid (V-cycles smoothed by Gauss–Seidel), "
                          "gauss_seidel (sweeps alone) or auto (multigrid where viscosity "
                          "dominates the time term, ρΔV/Δt < 20 % of a_P; docs/method.md §1)."),
                      &CaseConfig::simple, &SimpleConfig::momentum_solver));
    s.push_back(bound(key("simple", "convection", T::string, none, "\"central\"",
                          "Convection: central (second order, by deferred correction) or "
                          "upwind (first order)."),
                      &CaseConfig::simple, &SimpleConfig::convection));
    s.push_back(bound(key("simple", "pressure_solver", T::string, none, "\"auto\"",
                          "Pressure-correction solver: fft (direct, FFTW; on several ranks "
                          "FFTW-MPI's slabs), hypre (PFMG-preconditioned CG) or auto (fft "
                          "wherever the boundaries allow, hypre on more ranks than FFT planes)."),
                      &CaseConfig::simple, &SimpleConfig::pressure_solver));
    s.push_back(bound(key("simple", "fft_planning", T::string, none, "\"estimate\"",
                          "FFTW planning: estimate (the same plan every run: bit-identical "
                          "reruns) or measure (≈ 1.7× faster transforms at 256², but the plan "
                          "and the last bits may differ between runs)."),
                      &CaseConfig::simple, &SimpleConfig::fft_planning));
    s.push_back(bound(ranged(key("simple", "linear_tolerance", T::real, none, "1e-10",
                                 "Relative residual tolerance of the hypre pressure solver."),
                             0.0, 1.0, true, true),
                      &CaseConfig::simple, &SimpleConfig::linear_tolerance));
    s.push_back(bound(ranged(key("simple", "linear_max_iterations", T::integer, none, "200",
                                 "Iterations of the hypre pressure solver at most."),
                             1, 100000, false, false),
                      &CaseConfig::simple, &SimpleConfig::linear_max_iterations));

    s.push_back(body_key(key("bodies", "shape", T::string, none, "\"disk\"",
                             "Body shape: disk (2D) or sphere (3D)."),
                         &BodyConfig::shape));
    s.push_back(body_key(positive(key("bodies", "diameter", T::real, "m", "none",
                                      "Diameter D; required, except with bodies.file (whose "
                                      "diameter column gives it).")),
                         &BodyConfig::diameter));
    s.push_back(
        body_key(positive(key("bodies", "density", T::real, "kg/m³", "none",
                              "Body density ρs; required unless nondimensional.density_ratio "
                              "gives it.")),
                 &BodyConfig::density));
    s.push_back(body_key(key("bodies", "position", T::real_vector, "m", "none",
                             "Initial centre (inside the box, clear of walls and other bodies); "
                             "required, except with bodies.file or random insertion."),
                         &BodyConfig::position));
    s.push_back(body_key(key("bodies", "velocity", T::real_vector, "m/s", "zeros",
                             "Initial velocity; for motion = \"prescribed\" the velocity kept."),
                         &BodyConfig::velocity));
    s.push_back(body_key(key("bodies", "omega", T::angular, "rad/s", "zeros",
                             "Initial angular velocity: a number (about z) in 2D, [ωx, ωy, ωz] "
                             "in 3D; kept for prescribed motion."),
                         &BodyConfig::omega));
    s.push_back(body_key(key("bodies", "motion", T::string, none, "\"free\"",
                             "free (moved by fluid and gravity), prescribed (keeps its velocity), "
                             "fixed (at rest)."),
                         &BodyConfig::motion));
    s.push_back(body_key(
        ranged(key("bodies", "release_time", T::real, "s", "none",
                   "A prescribed body moves freely (as motion = \"free\") from this time on, "
                   "from the velocity it was given: a body brought to a speed and then let go, "
                   "in one run (e.g. a sphere's approach to a wall at a measured impact speed). "
                   "With time.max_courant a step ends on it; with the fixed time.dt it must be "
                   "a whole number of steps. Prescribed bodies only."),
               0.0, inf, false, false),
        &BodyConfig::release_time));
    s.push_back(
        body_key(ranged(key("bodies", "n_rings", T::integer, none, "0",
                            "Marker rings N_a (paper Fig. 1: 1 + 3 N_a (N_a + 1) markers); 0: "
                            "from coupling.marker_spacing_ratio."),
                        0, 1000, false, false),
                 &BodyConfig::n_rings));
    add_material_keys(s, "bodies", "body",
                      [](CaseConfig& config, std::size_t entry) -> SurfaceKeys& {
                          return entry_of(config.bodies, entry).surface;
                      });
    add_body_group_keys(s);

    s.push_back(
        bound(key("coupling", "kernel", T::string, none, "\"hat\"",
                  "Discrete delta function: hat (the paper's linear d_h), roma3 (Roma, "
                  "Peskin & Berger 1999), peskin4 (Peskin 2002), roma3_smoothed (roma3 averaged "
                  "over a cell, Yang et al. 2009: smaller force oscillations of a body "
                  "moving across the grid, a larger effective diameter; docs/method.md §4, "
                  "\"The spurious lateral force, isolated\")."),
              &CaseConfig::coupling, &CouplingConfig::kernel));
    s.push_back(
        bound(ranged(key("coupling", "marker_spacing_ratio", T::real, none, "1.4",
                         "Target marker spacing h_L / h when bodies.n_rings is 0 (paper §3.1 "
                         "recommends about 1.45)."),
                     0.5, 10.0, false, false),
              &CaseConfig::coupling, &CouplingConfig::marker_spacing_ratio));
    s.push_back(bound(key("coupling", "markers", T::string, none, "\"paper\"",
                          "Marker layout: paper (the last ring half a ring spacing inside the "
                          "surface: the body smaller by about 0.4 h in drag, its inertia within "
                          "2.3 % from D/16) or retracted (the outermost ring "
                          "coupling.marker_retraction h inside the surface, the rings evenly "
                          "spaced inside it: drag and settling within about 1 % at D/16–D/20, but "
                          "the body carries too much fluid, +12 % inertia at D/16, so light bodies "
                          "accelerate too slowly; docs/method.md §4) or surface (only that "
                          "outermost ring, markers "
                          "about coupling.marker_spacing_ratio h apart, each owning a shell of "
                          "thickness h; free bodies need coupling.inner_fluid = \"volume\")."),
                      &CaseConfig::coupling, &CouplingConfig::markers));
    s.push_back(bound(
        ranged(key("coupling", "marker_retraction", T::real, none, "0.3",
                   "With markers = \"retracted\" or \"surface\": how far inside the surface the "
                   "outermost ring lies, in grid spacings h (0.3: Breugem 2012). The value "
                   "that gives the exact Stokes drag grows with the kernel's width (3D sphere, "
                   "d/h 8: hat 0.24, roma3 0.43, roma3_smoothed 0.52, peskin4 0.62); "
                   "tools/stokes_retraction.py measures it for a kernel and resolution "
                   "(docs/method.md §4)."),
               0.0, 2.0, false, false),
        &CaseConfig::coupling, &CouplingConfig::marker_retraction));
    s.push_back(bound(key("coupling", "force_before_projection", T::boolean, none, "false",
                          "Apply the marker force of eqs. (15)–(16) to the momentum solve's u* "
                          "and then correct the pressure, so that every outer iteration ends "
                          "divergence-free (Uhlmann 2005); false: after the pressure correction, "
                          "as the paper (docs/method.md §4)."),
                      &CaseConfig::coupling, &CouplingConfig::is_forcing_before_projection));
    s.push_back(bound(key("coupling", "markers_off_at_walls", T::boolean, none, "false",
                          "Switch off, for the outer iteration, every marker closer to a wall "
                          "than coupling.markers_off_reach: no force, and its fluid velocity "
                          "taken as the body's in (13)–(14). Such a marker's kernel reads the "
                          "wall's odd ghost images, which turn the forcing's feedback around "
                          "(docs/method.md §5, the stall in contact), or the row of cells beside "
                          "the wall, which drains the fluid squeezed out under a body (§5, the "
                          "retracted ring beside a wall). false: every marker acts, as the paper."),
                      &CaseConfig::coupling, &CouplingConfig::is_wall_marker_off));
    s.push_back(bound(key("coupling", "markers_off_between_bodies", T::boolean, none, "false",
                          "Switch off, for the outer iteration, every marker closer than "
                          "coupling.markers_off_reach to the plane midway between its body's "
                          "surface and a neighbour's: the wall rule of markers_off_at_walls with "
                          "the midplane as the wall (a symmetry plane when two equal bodies close "
                          "at equal speeds). Without it the two bodies' markers both hold the "
                          "cells of the film between them, and the retracted layout's resolved "
                          "force below a cell grows as Δt shrinks (docs/method.md §5, \"The row "
                          "of cells between two bodies left free\"). false: every marker acts, as "
                          "the paper."),
                      &CaseConfig::coupling, &CouplingConfig::is_body_marker_off));
    s.push_back(
        bound(ranged(key("coupling", "markers_off_reach", T::real, none, "none",
                         "With markers_off_at_walls (or markers_off_between_bodies): how close "
                         "to a wall (or a midplane: r Σ|n_d| h_d along its normal n, the kernel "
                         "box's reach) a marker is switched off, in grid spacings. Default: the "
                         "kernel's support radius + "
                         "0.5 (hat 1.5, roma3 2, peskin4 and roma3_smoothed 2.5), so that no "
                         "marker reads the row of cells beside the wall; with less (measured with "
                         "the hat and roma3 kernels) the resolved force of a body below half a "
                         "cell from the wall grows as Δt shrinks (docs/method.md §5, \"The wall's "
                         "row of cells left free\"). Before 2026-12-01 "
                         "it was the kernel's stencil half width (hat 1, the others 2)."),
                     0.0, 5.0, true, false),
              &CaseConfig::coupling, &CouplingConfig::wall_marker_reach));
    s.push_back(
        bound(key("coupling", "normalised_forcing", T::boolean, none, "false",
                  "Divide eq. (15)'s correction at each marker by max(1, r), r the row "
                  "sum of the forcing operator I·D at that marker: the paper's eq. (15) "
                  "overshoots every slip mode whose eigenvalue exceeds 2, which a "
                  "sphere's retracted markers have at d/h = 12 and 16 (up to 3.2; fddem "
                  "warns above 10; the paper's layout already at d/h = 8), and a moving "
                  "sphere at d/h = 16 then diverges when Δt is small. The converged λ is the "
                  "same "
                  "(docs/method.md §4, \"Finer than d = 8 h the sphere's forcing overshoots\"). "
                  "false: the paper's."),
              &CaseConfig::coupling, &CouplingConfig::is_forcing_normalised));
    s.push_back(bound(key("coupling", "adjoint_at_walls", T::boolean, none, "true",
                          "Fold what the markers spread into a wall's ghost images back onto "
                          "the fluid those images are made of, with the ghost fill's own "
                          "coefficients, so that spreading is the exact adjoint of the "
                          "interpolation beside a wall and the forcing cannot feed the slip it "
                          "corrects (docs/method.md §5, the stall in contact). false: what is "
                          "spread into a wall's ghosts is dropped (fddem before 2026-11-27)."),
                      &CaseConfig::coupling, &CouplingConfig::is_adjoint_at_walls));
    s.push_back(
        bound(key("coupling", "body_sweep", T::string, none, "\"sequential\"",
                  "How eqs. (13)–(16) go over the bodies in each outer iteration: "
                  "sequential (body after body, each reading the fluid as the bodies "
                  "before it left it; on several MPI ranks one gather over the ranks and one "
                  "halo exchange per body) or simultaneous (every body from the same "
                  "fluid, the corrections added together, as eq. (16) spreads all the "
                  "markers at once: one gather and one halo exchange per outer iteration, "
                  "whatever the number of bodies). Bodies whose kernel supports do not "
                  "meet get the same answer either way; touching ones converge to the "
                  "same λ by different paths (docs/method.md §4)."),
              &CaseConfig::coupling, &CouplingConfig::body_sweep));
    s.push_back(
        bound(key("coupling", "inner_fluid", T::string, none, "\"markers\"",
                  "Where eqs. (13)–(14) take the fluid inside a free body from: markers (the "
                  "paper: its markers' interpolated velocities now, and the fluid moving "
                  "rigidly with the body at the step's start) or volume (the velocity "
                  "integrated over the cells the body covers, weighted by their volume "
                  "fractions, now and at the step's start: Kempe & Fröhlich 2012). volume "
                  "lets the surface marker layout move free bodies; not with time.scheme = "
                  "\"bdf2\" nor coupling.markers_off_at_walls or markers_off_between_bodies "
                  "(docs/method.md §4, \"The fluid "
                  "inside a body\")."),
              &CaseConfig::coupling, &CouplingConfig::inner_fluid));

    s.push_back(bound(key("contact", "model", T::string, none, "\"linear\"",
                          "Collision model: linear (spring–dashpot F = kα + cα̇, the paper's "
                          "eq. (18)), hertz_mindlin (Hertz normal force with a restitution "
                          "dashpot, Mindlin tangential stiffness; docs/method.md), adaptive "
                          "(Kempe & Fröhlich 2012: a Hertz spring and linear damper fitted per "
                          "contact so that each collision lasts contact.collision_steps time "
                          "steps and rebounds with contact.restitution) or none (bodies pass "
                          "through each other and the walls)."),
                      &CaseConfig::contact, &ContactConfig::model));
    s.push_back(bound(key("contact", "coupling", T::string, none, "\"paper\"",
                          "paper: while in contact, DEM replaces (13)–(14) and (17) (stable in "
                          "piles); additive: the mean contact force of the sub-steps is added "
                          "to (13)–(14) (unstable when collisions are much shorter than Δt)."),
                      &CaseConfig::contact, &ContactConfig::coupling));
    s.push_back(bound(key("contact", "fluid_force", T::string, none, "\"auto\"",
                          "The fluid's force on a body during the DEM sub-steps: none (the "
                          "paper: its buoyant weight only; with the paper coupling a body the DEM "
                          "moves, in contact or within the margin or the lubrication range, then "
                          "feels no resolved fluid force), held (the resolved hydrodynamic "
                          "force and torque of the step before, held constant over the sub-steps "
                          "in which it touches nothing), always (held, also over the sub-steps "
                          "in which the body touches: an enduring contact, two spheres touching "
                          "as they settle, keeps its drag; §5, \"A fluid force in an enduring "
                          "contact\") or auto: held when lubrication.enabled with "
                          "lubrication.coupling = \"dem\" (a body within the lubrication "
                          "range of a wall would otherwise fall beside it at its buoyant weight "
                          "alone), none otherwise, as the paper (docs/method.md §5, Coupling)."),
                      &CaseConfig::contact, &ContactConfig::fluid_force));
    s.push_back(bound(positive(key("contact", "stiffness", T::real, "N/m", "none",
                                   "Linear: spring stiffness k (2D: per unit depth); or give "
                                   "restitution and duration instead.")),
                      &CaseConfig::contact, &ContactConfig::stiffness));
    s.push_back(bound(ranged(key("contact", "damping", T::real, "N·s/m", "none",
                                 "Linear: dashpot coefficient c (with stiffness; default 0)."),
                             0.0, inf, false, false),
                      &CaseConfig::contact, &ContactConfig::damping));
    s.push_back(bound(ranged(key("contact", "restitution", T::real, none, "none",
                                 "Restitution coefficient e. Linear: of a wall collision of the "
                                 "lightest body (with duration), fddem derives k and c; "
                                 "hertz_mindlin: of every body and wall without its own, fddem "
                                 "derives the dashpot; adaptive: the dry restitution e_dry of "
                                 "every collision. Default 1."),
                             0.0, 1.0, true, false),
                      &CaseConfig::contact, &ContactConfig::surface, &SurfaceKeys::restitution));
    s.push_back(
        bound(positive(key("contact", "duration", T::real, "s", "none",
                           "Linear: duration t_c of a wall collision of the lightest body; fddem "
                           "derives k and c. Default (neither stiffness nor duration): time.dt.")),
              &CaseConfig::contact, &ContactConfig::duration));
    s.push_back(bound(ranged(key("contact", "tangential_stiffness_ratio", T::real, none, "none",
                                 "Linear: tangential spring k_t = κ k (dashpot c √κ) used when "
                                 "friction > 0; adaptive: k_t = κ dF_n/dα (dashpot d_n √κ). "
                                 "Default 2/7, which gives a sphere equal normal and tangential "
                                 "periods."),
                             0.0, 10.0, true, false),
                      &CaseConfig::contact, &ContactConfig::tangential_stiffness_ratio));
    s.push_back(
        bound(positive(key("contact", "young_modulus", T::real, "Pa", "none",
                           "Hertz–Mindlin: Young's modulus E of every body and wall without "
                           "its own (2D: a modulus per unit depth, docs/method.md).")),
              &CaseConfig::contact, &ContactConfig::surface, &SurfaceKeys::young_modulus));
    s.push_back(
        bound(ranged(key("contact", "poisson_ratio", T::real, none, "none",
                         "Hertz–Mindlin: Poisson ratio ν of every body and wall without its "
                         "own. Default 0.3."),
                     0.0, 0.5, false, true),
              &CaseConfig::contact, &ContactConfig::surface, &SurfaceKeys::poisson_ratio));
    s.push_back(
        bound(ranged(key("contact", "friction", T::real, none, "0.0",
                         "Sliding (Coulomb) friction coefficient μ_s of every body and wall "
                         "without its own; a pair takes the geometric mean. 0: frictionless, "
                         "as in the paper."),
                     0.0, inf, false, false),
              &CaseConfig::contact, &ContactConfig::surface, &SurfaceKeys::friction));
    s.push_back(
        bound(ranged(key("contact", "rolling_friction", T::real, none, "0.0",
                         "Rolling friction coefficient μ_r of every body and wall without its "
                         "own: a torque μ_r R* F_n against the relative rolling (constant "
                         "directional torque model). 0: none."),
                     0.0, inf, false, false),
              &CaseConfig::contact, &ContactConfig::surface, &SurfaceKeys::rolling_friction));
    s.push_back(
        bound(positive(key("contact", "impact_velocity", T::real, "m/s", "none",
                           "Hertz–Mindlin: the fastest impact expected, which sets the "
                           "sub-steps (t_c ∝ v^(−1/5)). Default: √(2|g|L) (L the largest box "
                           "side) + twice the fastest initial body + the fastest wall.")),
              &CaseConfig::contact, &ContactConfig::impact_velocity));
    s.push_back(bound(ranged(key("contact", "collision_steps", T::integer, none, "none",
                                 "Adaptive: the number N_c of time steps every collision lasts, "
                                 "T_c = N_c Δt (Kempe & Fröhlich 2012 use 10). Default 10."),
                             1, 1000000, false, false),
                      &CaseConfig::contact, &ContactConfig::collision_steps));
    s.push_back(
        bound(positive(key("contact", "minimum_impact_velocity", T::real, "m/s", "none",
                           "Adaptive: an impact slower than this (a resting contact) gets the "
                           "stiffness and damping of an impact at this speed, whose stiffness "
                           "would otherwise grow without bound (fddem's choice; docs/method.md "
                           "§6). Default g N_c time.dt / 1000 (g the magnitude of "
                           "fluid.gravity): a body resting under its weight then oscillates "
                           "with a period of about 0.6 N_c Δt.")),
              &CaseConfig::contact, &ContactConfig::minimum_impact_velocity));
    s.push_back(bound(ranged(key("contact", "velocity_damping", T::real, "kg/s", "0.0",
                                 "Velocity damping β of eq. (18) (0: none, as in the paper)."),
                             0.0, inf, false, false),
                      &CaseConfig::contact, &ContactConfig::velocity_damping));
    s.push_back(
        bound(ranged(key("contact", "margin", T::real, "m", "0.0",
                         "Paper coupling: a body closer than this to another body or a wall "
                         "during the DEM sub-steps is moved by DEM for the step, as one in "
                         "contact (0: touching bodies only, as the paper). About h keeps "
                         "crowded bodies from being pushed into each other by the fluid "
                         "update within a step (docs/method.md §5)."),
                     0.0, inf, false, false),
              &CaseConfig::contact, &ContactConfig::margin));
    s.push_back(
        bound(ranged(key("contact", "substeps", T::integer, none, "0",
                         "DEM sub-steps N_i per time step (Δt_i = Δt/N_i); 0: enough for 80 "
                         "per pair collision. At least 10 per collision are required."),
                     0, max_dem_substeps, false, false),
              &CaseConfig::contact, &ContactConfig::substeps));

    s.push_back(bound(key("lubrication", "enabled", T::boolean, none, "false",
                          "Add the lubrication correction of the film the grid does not resolve "
                          "between close bodies and walls (Breugem 2012: the analytic resistance "
                          "at the gap minus that at lubrication.range; normal and tangential, "
                          "spheres and disks; applied implicitly, in eqs. (13)–(14) to a body "
                          "not in contact and in the DEM sub-steps to one in contact: "
                          "lubrication.coupling; docs/method.md §5, Lubrication). false: none, "
                          "as the paper."),
                      &CaseConfig::lubrication, &LubricationConfig::is_enabled));
    s.push_back(bound(positive(key("lubrication", "range", T::real, none, "2.0",
                                   "Activation gap h_Δ in grid spacings h (the largest): the "
                                   "correction acts below it and vanishes continuously at it. "
                                   "About 2 h, where the grid stops resolving the film (to be "
                                   "calibrated against the resolved force, as Breugem 2012 did).")),
                      &CaseConfig::lubrication, &LubricationConfig::range));
    s.push_back(
        bound(ranged(key("lubrication", "roughness", T::real, none, "0.001",
                         "Saturation gap h_σ as a fraction of the smaller radius: below it "
                         "the correction is held at its value at h_σ, where surface asperities "
                         "touch (fddem's choice, of the order invoked for precision spheres; to "
                         "be calibrated against restitution data)."),
                     0.0, 1.0, true, false),
              &CaseConfig::lubrication, &LubricationConfig::roughness));
    s.push_back(bound(key("lubrication", "in_contact", T::string, none, "\"off\"",
                          "The correction while the surfaces overlap: off (none; the contact "
                          "model's damping stands for the solid contact's dissipation, the film "
                          "being squeezed out: Costa et al. 2015, Kempe & Fröhlich 2012) or "
                          "saturated (held at its value at the roughness, fddem's former "
                          "behaviour; with the adaptive model's stretched collision it takes most "
                          "of the impact energy: docs/method.md §5)."),
                      &CaseConfig::lubrication, &LubricationConfig::in_contact));
    s.push_back(bound(key("lubrication", "resolved", T::string, none, "\"range\"",
                          "What the grid is taken to resolve of the film, subtracted from the "
                          "analytic resistance c: range (c at lubrication.range and no more, "
                          "Breugem 2012) or shells (c of the gap between the bodies' outermost "
                          "marker shells, the gap plus their depths below the surfaces: the "
                          "retraction for the retracted layout; with it a range of several h, "
                          "e.g. 8; docs/method.md §5, \"What the grid resolves\")."),
                      &CaseConfig::lubrication, &LubricationConfig::resolved));
    s.push_back(
        bound(key("lubrication", "coupling", T::string, none, "\"implicit\"",
                  "How the correction reaches a body within lubrication.range that is "
                  "not in contact: implicit (it stays on eqs. (13)–(14), the correction's "
                  "damping on their left-hand side, the bodies the film joins solved "
                  "together; the DEM takes over within contact.margin, and while a body "
                  "leaves a collision within the range; docs/method.md §5, \"Implicit "
                  "coupling of the film\") or dem (it counts as in contact, so with the "
                  "paper's coupling the DEM sub-steps move it, with the resolved force "
                  "of the step before held; a light body beside another then goes "
                  "unstable: the paper's eighteen disks blow up in the step to t = 0.135 s; the "
                  "default until 2026-12-02, kept by the cases measured with it; §5, "
                  "\"The default coupling of the film\")."),
              &CaseConfig::lubrication, &LubricationConfig::coupling));
    s.push_back(bound(
        key("lubrication", "film_solve", T::string, none, "\"sweep\"",
            "How the DEM sub-steps apply the films of several gaps: sweep (pair by pair, each "
            "on the velocities the pairs before it left; the result depends on their order) "
            "or joint (all of a sub-step's films solved together: order-free, a body between "
            "two stiff films stopped, not reversed; the same as sweep, bit for bit, for a film "
            "whose bodies have no other; docs/method.md §5, \"The films solved together\")."),
        &CaseConfig::lubrication, &LubricationConfig::film_solve));

    s.push_back(
        bound(positive(key("nondimensional", "reynolds", T::real, none, "none",
                           "Re = ρf U_c D / μ (D: the first body's diameter); fddem derives "
                           "fluid.viscosity.")),
              &CaseConfig::nondimensional, &NondimensionalConfig::reynolds));
    s.push_back(bound(
        ranged(key("nondimensional", "density_ratio", T::real, none, "none",
                   "ρr = ρs / ρf; with reynolds, fddem derives every body's density and "
                   "the gravity of eqs. (21)–(22) (Happel & Brenner wall factor K; 2D only: a 3D "
                   "case gives fluid.gravity and bodies.density)."),
               0.0, inf, true, false),
        &CaseConfig::nondimensional, &NondimensionalConfig::density_ratio));
    s.push_back(bound(positive(key("nondimensional", "velocity", T::real, "m/s", "1.0",
                                   "Characteristic velocity U_c of eq. (21).")),
                      &CaseConfig::nondimensional, &NondimensionalConfig::velocity));

    s.push_back(key("derived", "viscosity", T::real, "Pa·s", "none",
                    "Written by fddem into case.toml when derived from [nondimensional]; "
                    "ignored on input."));
    s.push_back(key("derived", "gravity", T::real_vector, "m/s²", "none",
                    "Written by fddem when derived (eq. 21–22); ignored on input."));
    s.push_back(key("derived", "body_density", T::real, "kg/m³", "none",
                    "Written by fddem when derived from the density ratio; ignored on input."));
    s.push_back(key("derived", "wall_factor", T::real, none, "none",
                    "Happel & Brenner wall factor K of eq. (20), written by fddem; ignored on "
                    "input."));

    s.push_back(key("derived", "contact_stiffness", T::real, "N/m", "none",
                    "Linear: contact stiffness k used, written by fddem; ignored on input."));
    s.push_back(key("derived", "contact_damping", T::real, "N·s/m", "none",
                    "Linear: contact damping c used, written by fddem; ignored on input."));
    s.push_back(key("derived", "contact_damping_constant", T::real, none, "none",
                    "Hertz–Mindlin: A of the dashpot c_n = A √(m* k_H) α^(1/4) of a wall "
                    "collision of the lightest body, written by fddem."));
    s.push_back(key("derived", "contact_impact_velocity", T::real, "m/s", "none",
                    "Hertz–Mindlin: the impact speed that set the sub-steps, written by fddem."));
    s.push_back(key("derived", "contact_minimum_impact_velocity", T::real, "m/s", "none",
                    "Adaptive: the floor of the impact speed used, written by fddem."));
    s.push_back(key("derived", "contact_duration", T::real, "s", "none",
                    "Duration of a wall collision of the lightest body (hertz_mindlin: "
                    "undamped, at the impact velocity; adaptive: N_c time.dt), written by "
                    "fddem."));
    s.push_back(key("derived", "contact_restitution", T::real, none, "none",
                    "Restitution of a wall collision of the lightest body, written by fddem."));
    s.push_back(key("derived", "contact_substeps", T::integer, none, "none",
                    "DEM sub-steps N_i used, written by fddem; ignored on input."));

    s.push_back(
        bound(key("output", "directory", T::string, none, "\"\"",
                  "Run directory; empty: runs/<case file name>. `fddem run -o` overrides it."),
              &CaseConfig::output, &OutputConfig::directory));
    s.push_back(bound(ranged(key("output", "field_interval", T::real, "s", "0",
                                 "Simulated time between field files (VTK); 0: the initial and "
                                 "final fields only."),
                             0.0, inf, false, false),
                      &CaseConfig::output, &OutputConfig::field_interval));
    s.push_back(bound(ranged(key("output", "particle_interval", T::real, "s", "0",
                                 "Simulated time between rows of particles.csv; 0: every step."),
                             0.0, inf, false, false),
                      &CaseConfig::output, &OutputConfig::particle_interval));
    s.push_back(bound(ranged(key("output", "log_interval", T::integer, none, "100",
                                 "Steps between log lines when not on a terminal."),
                             1, inf, false, false),
                      &CaseConfig::output, &OutputConfig::log_interval));

    s.push_back(
        line_key(key("output.lines", "name", T::string, none, std::nullopt,
                     "Name of a line sample, written to samples/<name>.csv (letters, digits, _ "
                     "and -)."),
                 &LineSample::name));
    s.push_back(line_key(key("output.lines", "from", T::real_vector, "m", std::nullopt,
                             "Start point of the line (inside the box)."),
                         &LineSample::from));
    s.push_back(line_key(key("output.lines", "to", T::real_vector, "m", std::nullopt,
                             "End point of the line (inside the box)."),
                         &LineSample::to));
    s.push_back(line_key(ranged(key("output.lines", "points", T::integer, none, "101",
                                    "Number of equally spaced sample points, ends included."),
                                2, 1000000, false, false),
                         &LineSample::n_points));

    s.push_back(
        bound(ranged(key("checkpoint", "step_interval", T::integer, none, "1000",
                         "Steps between checkpoints (RUN_DIR/checkpoints/, for `fddem run "
                         "--restart`); 0: none by step count. A checkpoint is also written at "
                         "the end and on SIGINT/SIGTERM."),
                     0, inf, false, false),
              &CaseConfig::checkpoint, &CheckpointConfig::step_interval));
    s.push_back(bound(ranged(key("checkpoint", "time_interval", T::real, "s", "0",
                                 "Simulated time between checkpoints; 0: none by time."),
                             0.0, inf, false, false),
                      &CaseConfig::checkpoint, &CheckpointConfig::time_interval));
    s.push_back(
        bound(ranged(key("checkpoint", "keep", T::integer, none, "2",
                         "Checkpoints kept: after writing one, all but the newest this many "
                         "are removed."),
                     1, 1000000, false, false),
              &CaseConfig::checkpoint, &CheckpointConfig::keep));

    s.push_back(
        bound(positive(key("run", "max_memory", T::real, "B", "none",
                           "The most memory the run may take on one machine: a run whose "
                           "estimate (printed at its start; on several MPI ranks, that of the "
                           "ranks on the machine) is larger stops before any work (exit status "
                           "2). None: the machine's memory (its cgroup limit, if lower).")),
              &CaseConfig::run, &RunConfig::max_memory));
    s.push_back(
        bound(ranged(key("parallel", "ranks", T::integer_vector, none, "none",
                         "MPI ranks along each axis on a run of several processes (mpirun -n N): "
                         "their product must be N, and every block at least 3 cells thick. Ignored "
                         "on one process. None: the layout with the least block-interface area "
                         "(docs/parallel.md)."),
                     1, 1000000, false, false),
              &CaseConfig::parallel, &ParallelConfig::ranks));
    return s;
}

std::vector<TableArraySpec> case_table_arrays()
{
    return {{"output.lines", "Line samples of u, v (w) and p at the end of the run."},
            {"bodies",
             "Rigid particles. An entry gives one body (at `position`), one per row of a CSV "
             "file (`file`), or many inserted at random (`count` or `volume_fraction`, in "
             "`region_low`–`region_high`, with `seed` and `gap`). The entry's other keys "
             "(shape, motion, n_rings, the surface keys, and velocity unless the file has u, "
             "v, w columns) apply to every body it gives: one entry per kind of body, so that "
             "each key is declared once and a case can mix a bed from a file with bodies given "
             "one by one. Ids: a file gives its own (whole numbers ≥ 0, unique in the case); "
             "every other entry numbers its bodies on from the largest id of the entries "
             "before it, from 0. Random bodies keep clear of the bodies of every other entry; "
             "the same seed gives the same bodies on every machine. The case as run records a "
             "file by its absolute path, so that `fddem run --restart` finds it."}};
}

std::string type_name(KeyType type)
{
    switch (type) {
    case KeyType::real:
        return "number";
    case KeyType::integer:
        return "integer";
    case KeyType::string:
        return "string";
    case KeyType::boolean:
        return "boolean";
    case KeyType::real_vector:
        return "[number; dim]";
    case KeyType::integer_vector:
        return "[integer; dim]";
    case KeyType::boolean_vector:
        return "[boolean; dim] or boolean";
    case KeyType::angular:
        return "number (2D) or [number; 3] (3D)";
    }
    return "?";
}

std::string range_text(const KeySpec& spec)
{
    if (!spec.choices.empty()) {
        std::string text = "one of:";
        for (const auto& c : spec.choices) {
            text += (text.back() == ':' ? " " : ", ") + c;
        }
        return text;
    }
    const bool has_min = spec.min > -inf;
    const bool has_max = spec.max < inf;
    if (has_min && has_max) {
        return fmt::format("{}{:g}, {:g}{}", spec.is_min_open ? "(" : "[", spec.min, spec.max,
                           spec.is_max_open ? ")" : "]");
    }
    if (has_min) {
        return fmt::format("{} {:g}", spec.is_min_open ? ">" : ">=", spec.min);
    }
    if (has_max) {
        return fmt::format("{} {:g}", spec.is_max_open ? "<" : "<=", spec.max);
    }
    return "";
}

std::string describe_keys(bool markdown)
{
    std::string out;
    if (markdown) {
        out += "# Case-file reference\n\n"
               "Generated by `fddem info --keys --markdown` from `src/fddem/io/case_schema.cpp`; "
               "do not edit by hand.\n\n"
               "A case is a TOML file. Vectors have one entry per axis (2 or 3, set by "
               "`domain.size`). Values are dimensional, in any consistent unit system (SI "
               "units are shown). `fddem run CASE --set section.key=value` overrides any key "
               "(`bodies.N.key=value`: "
               "body N, from 1; `bodies.key=value`: every body).\n";
    }
    std::string section;
    for (const KeySpec& spec : case_schema()) {
        if (spec.section != section) {
            section = spec.section;
            bool is_array = false;
            std::string array_doc;
            for (const auto& t : case_table_arrays()) {
                if (t.name == section) {
                    is_array = true;
                    array_doc = t.doc;
                }
            }
            const std::string header = is_array ? "[[" + section + "]]" : "[" + section + "]";
            if (markdown) {
                out += "\n## `" + header + "`\n\n" + (is_array ? array_doc + "\n\n" : "") +
                       "| key | type | unit | default | range | "
                       "meaning |\n| --- | --- | --- | --- | --- | --- |\n";
            } else {
                out += "\n" + header + "\n" + (is_array ? "  " + array_doc + "\n" : "");
            }
        }
        const std::string value = spec.value ? *spec.value : "required";
        if (markdown) {
            out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", spec.name,
                               type_name(spec.type), spec.unit.empty() ? "–" : spec.unit, value,
                               range_text(spec).empty() ? "–" : range_text(spec), spec.doc);
        } else {
            out += fmt::format("  {:<22} {:<16} {:<7} default {:<12} {}\n      {}\n", spec.name,
                               type_name(spec.type), spec.unit, value, range_text(spec), spec.doc);
        }
    }
    return out;
}

} // namespace fddem
