// SPDX-License-Identifier: MIT
#pragma once
/// A case as read and checked by io/case_reader: plain, typed data, dimension-agnostic (the
/// number of entries of `domain.size` is the dimension). One struct per section of the case
/// file, one field per key: io/case_schema.cpp binds each key to its field and holds its unit,
/// default, range and doc. Closed sets of words are enums; io/case_names.hpp holds their names.
/// Values the reader derives (docs/case-file.md, [derived]) sit beside the keys they come from.

#include "fddem/bodies/material.hpp"
#include "fddem/bodies/particle.hpp"
#include "fddem/contact/contact_models.hpp"
#include "fddem/contact/lubrication.hpp"
#include "fddem/coupling/delta_kernel.hpp"
#include "fddem/fluid/boundary_conditions.hpp"
#include "fddem/fluid/fluid_state.hpp"
#include "fddem/fluid/momentum.hpp"
#include "fddem/fluid/pressure_correction.hpp"
#include "fddem/linsolve/anderson_mixing.hpp"
#include "fddem/linsolve/poisson_solver.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fddem {

/// The shape of a body: a disk (2D) or a sphere (3D).
enum class BodyShape { disk, sphere };

/// [domain]
struct DomainConfig {
    int dimension = 2;          ///< the number of entries of `size`
    std::vector<double> origin; ///< [m]
    std::vector<double> size;   ///< [m]
    std::vector<int> cells;
    std::vector<bool> periodic;
};

/// The surface keys of a [[bodies]] entry, of [walls] or of [contact] (whose values every body
/// and wall without its own take), as given: each is unset when the case does not give it.
struct SurfaceKeys {
    std::optional<double> young_modulus;    ///< E [Pa]
    std::optional<double> poisson_ratio;    ///< ν
    std::optional<double> friction;         ///< μ_s
    std::optional<double> rolling_friction; ///< μ_r
    std::optional<double> restitution;      ///< e
};

/// [walls]
struct WallsConfig {
    /// Velocity of each wall [m/s], indexed [axis][side]; zero when not given.
    std::vector<std::array<std::vector<double>, 2>> velocity;
    SurfaceKeys surface;
    Material material; ///< the walls' surface: `surface`, else [contact]'s (derived)
};

/// [inflow]
struct InflowConfig {
    InflowShape profile = InflowShape::uniform;
    double velocity = 0.0; ///< [m/s]: the speed, or the parabola's maximum
};

/// [fluid]
struct FluidConfig {
    double density = 1.0;           ///< ρf [kg/m³]
    double viscosity = 1.0;         ///< μ [Pa·s] (given, or derived from [nondimensional])
    std::vector<double> gravity;    ///< g [m/s²]; acts on particles only (DESIGN.md §1)
    std::vector<double> body_force; ///< uniform force on the fluid [N/m³] (e.g. a channel's drive)
};

/// [time]
struct TimeConfig {
    double dt = 1e-3;                       ///< Δt [s]
    std::optional<double> end;              ///< [s]
    std::optional<double> steady_tolerance; ///< stop when max|u^{n+1}−u^n|/(Δt) · L/U² drops below
    std::optional<double> rest_speed;       ///< stop when every free body is slower than this [m/s]
    double rest_duration = 0.1;             ///< ... for this long [s]
    double min_end = 0.0; ///< rest_speed and steady_tolerance end no run before this [s]
    long max_steps = 100000000;
    std::optional<double> max_courant; ///< adaptive Δt: at most this many cells per step
    std::optional<double> min_dt; ///< below it the adaptive Δt stops the run [s] (none: 1e-6 dt)
    int max_retries = 3; ///< with max_courant: a failed step is taken again at Δt/2 this often
    std::optional<double> retry_mass_residual; ///< a step ending above it is retried
    std::optional<double> retry_courant;       ///< a step ending above it is retried
    bool is_steady = false;                    ///< pseudo-time march to a steady state (SER)
    TimeScheme scheme = TimeScheme::euler;     ///< the time derivative (core/time_scheme.hpp)
};

/// What a time step of the fluid is (simple.algorithm).
enum class StepAlgorithm {
    simple, ///< outer iterations of eqs. (7)–(16) to simple.tolerance (the paper's)
    /// one predictor, solved to simple.tolerance, one projection and one pass of eqs. (13)–(16)
    /// (a step with a body near contact takes simple's iterations)
    projection
};

/// [simple]
struct SimpleConfig {
    StepAlgorithm algorithm = StepAlgorithm::simple;
    double tolerance = 1e-5; ///< normalised mass and momentum residuals
    /// With bodies, also require the fluid's residuals (not only the bodies' change) below
    /// `tolerance` to end a step (issue 13; docs/method.md §4)
    bool is_fluid_converged_with_bodies = false;
    int max_outer_iterations = 50;
    /// Outer iterations a step takes at least when a free body the DEM moves is in it (2 holds
    /// a pile at rest; 1: the step's test may end it after one, as fddem ran before 2026-11-27)
    int min_outer_iterations_dem = 2;
    /// With bodies, end a step only once its mass residual is no larger than at its start, or
    /// has stopped falling (docs/method.md §5, "The fluid's residual held")
    bool is_mass_residual_held = false;
    double velocity_relaxation = 1.0;
    double pressure_relaxation = 1.0;
    PressureUpdate pressure_update = PressureUpdate::rotational; ///< eq. (10)
    int acceleration_depth = 2; ///< Anderson mixing depth of a step's outer iterations (0: off)
    /// the mixing's weights rounded to this many significant bits (0: not rounded)
    int acceleration_weight_bits = AndersonMixing::default_weight_bits;
    /// the mixing's step at most this many times the iteration's residual (0: not bounded)
    double acceleration_max_step = AndersonMixing::default_max_step_ratio;
    int momentum_sweeps = 4; ///< Gauss–Seidel sweeps per V-cycle (or in all, without cycles)
    int momentum_cycles = 1; ///< multigrid V-cycles per outer iteration (0: sweeps alone)
    MomentumSolver momentum_solver = MomentumSolver::automatic;
    ConvectionScheme convection = ConvectionScheme::central;
    PoissonSolverKind pressure_solver = PoissonSolverKind::automatic;
    FftPlanning fft_planning = FftPlanning::estimate;
    double linear_tolerance = 1e-10; ///< hypre relative residual tolerance
    int linear_max_iterations = 200;
};

/// One body, as a [[bodies]] entry gives it (io/body_entries.hpp: one entry may give many).
struct BodyConfig {
    int id = 0; ///< stable for the run (io/body_entries.hpp says how ids are given)
    BodyShape shape = BodyShape::disk;
    double diameter = 1.0;        ///< [m]
    double density = 1.0;         ///< ρs [kg/m³] (given, or derived from [nondimensional])
    std::vector<double> position; ///< centre [m]
    std::vector<double> velocity; ///< initial (or prescribed) U [m/s]
    std::vector<double> omega;    ///< initial (or prescribed) ω [rad/s]: ω_z (2D), ω (3D)
    Motion motion = Motion::free;
    /// A prescribed body moves freely from this time on [s] (bodies.release_time): a run that
    /// brings a body to a given speed, then lets it go, in one command.
    std::optional<double> release_time;
    int n_rings = 0; ///< N_a; 0: from coupling.marker_spacing_ratio
    SurfaceKeys surface;
    Material material; ///< its surface: `surface`, else [contact]'s (derived)
    /// Where it is given, for messages: its [[bodies]] entry (from 0) and, for a body of a
    /// file, the file and the line of its row (0: not from a file).
    std::size_t entry = 0;
    std::string file;
    int file_line = 0;
};

/// Moved by the fluid and by contacts at some time of the run: free, or prescribed until its
/// release. What a case derives for collisions (stiffness, sub-steps) counts such a body.
[[nodiscard]] inline bool moves_freely(const BodyConfig& b) noexcept
{
    return b.motion == Motion::free || (b.motion == Motion::prescribed && b.release_time);
}

/// How a [[bodies]] entry gives its bodies (io/body_entries.hpp): one at its `position`; one
/// per row of `file`; or `count` (or `volume_fraction`'s worth) inserted at random.
struct BodyGroupConfig {
    std::string file;                      ///< CSV of bodies, relative to the case file
    long count = 0;                        ///< random insertion: this many bodies (0: not given)
    std::optional<double> volume_fraction; ///< random insertion: this fraction of the region
    std::vector<double> region_low;        ///< [m]; empty: the box's lower corner
    std::vector<double> region_high;       ///< [m]; empty: the box's upper corner
    long seed = 0;                         ///< of the random numbers
    double gap = 0.0;                      ///< least clearance between bodies and walls [m]
};

/// How the marker rings fill a body (coupling.markers).
enum class MarkerLayout { paper, retracted, surface };

/// Where eqs. (13)–(14) take the fluid inside a free body from (coupling.inner_fluid): the
/// markers that fill it, with the fluid moving rigidly at level n (the paper), or the cells it
/// covers, at both levels (Kempe & Fröhlich 2012; coupling/inner_fluid.hpp).
enum class InnerFluidSource { markers, volume };

/// How eqs. (13)–(16) go over the bodies in an outer iteration (coupling.body_sweep).
enum class BodySweep {
    sequential,  ///< body after body, each reading the fluid the ones before left (Gauss–Seidel)
    simultaneous ///< all from the same u, corrections added together (Jacobi; one exchange)
};

/// [coupling]
struct CouplingConfig {
    KernelKind kernel = KernelKind::hat; ///< the discrete delta function
    double marker_spacing_ratio = 1.4;   ///< h_L / h when n_rings is not given
    /// Where the marker rings go: the paper's layout (the last ring h_L/2 inside the surface) or
    /// the outermost ring `marker_retraction` h inside it (issue 13; docs/method.md §4), or that
    /// ring alone (free bodies then need inner_fluid = volume)
    MarkerLayout markers = MarkerLayout::paper;
    double marker_retraction = 0.3; ///< in grid spacings h (Breugem 2012)
    /// Eqs. (15)–(16) between the momentum solve and the pressure correction, so that each
    /// outer iteration ends divergence-free (Uhlmann 2005), not after the correction (the paper)
    bool is_forcing_before_projection = false;
    /// Markers closer to a wall than wall_marker_reach take no part in eqs. (13)–(16) (Kempe &
    /// Fröhlich 2012b, as Biegert et al. 2017 report)
    bool is_wall_marker_off = false;
    /// coupling.markers_off_reach [cells]; none: default_wall_marker_reach of the kernel
    std::optional<double> wall_marker_reach;
    /// coupling.markers_off_between_bodies: markers closer than the same reach to the plane
    /// midway between their body's surface and a neighbour's take no part (fddem's)
    bool is_body_marker_off = false;
    /// What markers spread into a wall's ghost images goes back, through the ghost fill's
    /// transpose, onto the fluid those images are made of: D the adjoint of I beside a wall
    bool is_adjoint_at_walls = true;
    /// Eq. (15)'s correction divided at each marker by max(1, the forcing operator's row sum)
    /// (coupling/forcing_gain.hpp), so that no slip mode overshoots
    bool is_forcing_normalised = false;
    BodySweep body_sweep = BodySweep::sequential;             ///< coupling.body_sweep
    InnerFluidSource inner_fluid = InnerFluidSource::markers; ///< coupling.inner_fluid
};

/// What the reader derives for the DEM collision model (eq. (18)) from [contact] and the bodies.
struct ContactDerived {
    double stiffness = 0.0;       ///< k [N/m] (2D: per unit depth) of the linear model
    double damping = 0.0;         ///< c [N·s/m] of the linear model
    double duration = 0.0;        ///< of a wall collision of the lightest free body [s]
    double restitution = 1.0;     ///< of that collision
    double impact_velocity = 0.0; ///< hertz_mindlin: the impact speed that set the sub-steps [m/s]
    double minimum_impact_velocity = 0.0; ///< adaptive: v_min used [m/s]
    double reference_mass = 0.0;          ///< the lightest free body's mass [kg]
    int substeps = 1;                     ///< N_i
};

/// [contact]: the DEM collision model (eq. (18)).
struct ContactConfig {
    ContactModelKind model = ContactModelKind::linear;
    ContactCoupling coupling = ContactCoupling::paper;
    ContactFluidForce fluid_force = ContactFluidForce::automatic; ///< on a body in the sub-steps
    std::optional<double> stiffness;                              ///< linear: k [N/m]
    std::optional<double> damping;                                ///< linear: c [N·s/m]
    std::optional<double> duration;                ///< linear: t_c of a wall collision [s]
    double tangential_stiffness_ratio = 2.0 / 7.0; ///< linear, adaptive: κ = k_t / k
    std::optional<double> impact_velocity;         ///< hertz_mindlin: the fastest impact [m/s]
    int collision_steps = 10;                      ///< adaptive: N_c, T_c = N_c Δt
    std::optional<double> minimum_impact_velocity; ///< adaptive: v_min [m/s]
    SurfaceKeys surface;           ///< of every body and wall without its own (e: also linear's)
    double velocity_damping = 0.0; ///< β [kg/s]
    double margin = 0.0;           ///< DemSettings::margin [m]
    int substeps = 0;              ///< N_i as given; 0: automatic
    ContactDerived derived;
};

/// [lubrication]: the correction for the film between close bodies that the grid does not
/// resolve (contact/lubrication.hpp, docs/method.md §5, Lubrication). Off by default.
struct LubricationConfig {
    bool is_enabled = false;
    double range = 2.0;      ///< activation gap h_Δ in grid spacings h (the largest spacing)
    double roughness = 1e-3; ///< saturation gap h_σ as a fraction of the smaller radius
    LubricationInContact in_contact = LubricationInContact::off;   ///< while the surfaces overlap
    LubricationResolved resolved = LubricationResolved::range;     ///< what the grid resolves
    LubricationCoupling coupling = LubricationCoupling::implicit;  ///< bodies not in contact
    LubricationFilmSolve film_solve = LubricationFilmSolve::sweep; ///< the DEM's films at once

    /// On, and in eqs. (13)–(14) for bodies not in contact (coupling/lubrication_coupling.hpp).
    [[nodiscard]] bool is_implicit() const noexcept
    {
        return is_enabled && coupling == LubricationCoupling::implicit;
    }
};

/// [nondimensional]: given, fddem derives viscosity, gravity and body densities.
struct NondimensionalConfig {
    std::optional<double> reynolds;      ///< Re = ρf U_c D / μ
    std::optional<double> density_ratio; ///< ρr = ρs / ρf
    double velocity = 1.0;               ///< U_c [m/s] (eq. 21 sets g so that U_c results)
    double wall_factor = 0.0;            ///< K of eq. (20) used (derived; 0 if not derived)
};

/// One [[output.lines]] entry.
struct LineSample {
    std::string name;
    std::vector<double> from; ///< [m]
    std::vector<double> to;   ///< [m]
    int n_points = 101;
};

/// [output]
struct OutputConfig {
    std::string directory;          ///< empty: runs/<case file stem>
    double field_interval = 0.0;    ///< [s]; 0: fields at the end only
    double particle_interval = 0.0; ///< [s]; 0: particles.csv every step
    long log_interval = 100;        ///< steps between plain log lines (no terminal)
    std::vector<LineSample> lines;
};

/// [checkpoint]
struct CheckpointConfig {
    long step_interval = 1000;  ///< steps between checkpoints; 0: not by steps
    double time_interval = 0.0; ///< [s]; 0: not by simulated time
    int keep = 2;               ///< newest checkpoints kept
};

/// [run]
struct RunConfig {
    std::optional<double>
        max_memory; ///< refuse a run estimated above this [B]; none: the machine's
};

/// [parallel]
struct ParallelConfig {
    std::vector<int> ranks; ///< ranks along each axis on several processes; empty: chosen
};

struct CaseConfig {
    std::string source_file; ///< the case file path, for messages
    std::string as_run;      ///< the whole case as TOML, defaults and overrides filled in
    std::string title;       ///< [case] title

    DomainConfig domain;
    WallsConfig walls;
    /// [boundaries]: what each side is, indexed [axis][side]; a wall when not given.
    std::vector<std::array<BoundaryKind, 2>> boundaries;
    InflowConfig inflow;
    FluidConfig fluid;
    TimeConfig time;
    SimpleConfig simple;
    std::vector<BodyConfig> bodies;
    std::vector<BodyGroupConfig> body_groups; ///< one per [[bodies]] entry
    CouplingConfig coupling;
    ContactConfig contact;
    LubricationConfig lubrication;
    NondimensionalConfig nondimensional;
    OutputConfig output;
    CheckpointConfig checkpoint;
    RunConfig run;
    ParallelConfig parallel;
};

} // namespace fddem
