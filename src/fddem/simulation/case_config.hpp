// SPDX-License-Identifier: MIT
#pragma once
/// A case as read and checked by io/case_reader: plain data, dimension-agnostic (the number
/// of entries of `domain.size` is the dimension). Every field mirrors one case key declared in
/// io/case_schema.cpp, which holds its unit, default, range and doc.

#include "fddem/contact/material.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fddem {

struct LineSample {
    std::string name;
    std::vector<double> from; ///< [m]
    std::vector<double> to;   ///< [m]
    int n_points = 101;
};

/// One [[bodies]] entry.
struct BodyConfig {
    std::string shape = "disk";   ///< "disk" (2D) or "sphere" (3D)
    double diameter = 1.0;        ///< [m]
    double density = 1.0;         ///< ρs [kg/m³]
    std::vector<double> position; ///< centre [m]
    std::vector<double> velocity; ///< initial (or prescribed) U [m/s]
    double omega = 0.0;           ///< initial (or prescribed) ω [rad/s] (2D)
    std::string motion = "free";  ///< "free", "prescribed" or "fixed"
    int n_rings = 0;              ///< N_a; 0: from coupling.marker_spacing_ratio
    Material material;            ///< its surface: its own keys, else [contact]'s
};

struct CaseConfig {
    std::string source_file; ///< the case file path, for messages
    std::string as_run;      ///< the whole case as TOML, defaults and overrides filled in
    std::string title;       ///< [case] title

    // [domain]
    int dimension = 2;
    std::vector<double> origin; ///< [m]
    std::vector<double> size;   ///< [m]
    std::vector<int> cells;
    std::vector<bool> periodic;

    // [walls]: velocity of each wall [m/s], indexed [axis][side]; zero when not given.
    std::vector<std::array<std::vector<double>, 2>> wall_velocity;

    // [boundaries]: "wall", "inflow" or "outflow", indexed [axis][side]; "wall" when not given.
    std::vector<std::array<std::string, 2>> boundary_kind;
    // [inflow]
    std::string inflow_profile = "uniform"; ///< "uniform" or "parabolic"
    double inflow_velocity = 0.0;           ///< [m/s]: the speed, or the parabola's maximum

    // [fluid]
    double density = 1.0;           ///< ρf [kg/m³]
    double viscosity = 1.0;         ///< μ [Pa·s]
    std::vector<double> gravity;    ///< g [m/s²]; acts on particles only (DESIGN.md §1)
    std::vector<double> body_force; ///< uniform force on the fluid [N/m³] (e.g. a channel's drive)

    // [time]
    double dt = 1e-3;                       ///< Δt [s]
    std::optional<double> end_time;         ///< [s]
    std::optional<double> steady_tolerance; ///< stop when max|u^{n+1}−u^n|/(Δt) · L/U² drops below
    std::optional<double> rest_speed;       ///< stop when every free body is slower than this [m/s]
    double rest_duration = 0.1;             ///< ... for this long [s]
    double min_end = 0.0; ///< rest_speed and steady_tolerance end no run before this [s]
    long max_steps = 100000000;
    std::optional<double> max_courant; ///< adaptive Δt: at most this many cells per step
    bool is_steady = false;            ///< pseudo-time march to a steady state (SER)

    // [simple]
    double tolerance = 1e-5; ///< normalised mass and momentum residuals
    int max_outer_iterations = 50;
    double velocity_relaxation = 1.0;
    double pressure_relaxation = 1.0;
    std::string pressure_update = "rotational"; ///< "standard" or "rotational" (eq. (10))
    int acceleration_depth = 2; ///< Anderson mixing depth of a step's outer iterations (0: off)
    int momentum_sweeps = 4;    ///< Gauss–Seidel sweeps per V-cycle (or in all, without cycles)
    int momentum_cycles = 1;    ///< multigrid V-cycles per outer iteration (0: sweeps alone)
    std::string momentum_solver = "auto";  ///< "auto", "multigrid" or "gauss_seidel"
    std::string convection = "central";    ///< "central" (deferred correction) or "upwind"
    std::string pressure_solver = "auto";  ///< "auto", "fft" or "hypre"
    std::string fft_planning = "estimate"; ///< "estimate" or "measure"
    double linear_tolerance = 1e-10;       ///< hypre relative residual tolerance
    int linear_max_iterations = 200;

    // [[bodies]], [coupling]
    std::vector<BodyConfig> bodies;
    std::string kernel = "hat";        ///< delta kernel: "hat", "roma3", "peskin4"
    double marker_spacing_ratio = 1.4; ///< h_L / h when n_rings is not given

    // [contact]: the DEM collision model (eq. (18)); stiffness, damping and substeps are
    // resolved by the reader (from restitution and duration when those are given).
    std::string contact_model = "linear";   ///< a name in contact/contact_models.cpp
    std::string contact_coupling = "paper"; ///< "paper" or "additive"
    double contact_stiffness = 0.0;         ///< k [N/m] (2D: per unit depth)
    double contact_damping = 0.0;           ///< c [N·s/m]
    double contact_beta = 0.0;              ///< velocity damping β [kg/s]
    double contact_margin = 0.0;            ///< DemSettings::margin [m]
    int contact_substeps = 1;               ///< N_i
    double contact_duration = 0.0;          ///< wall collision of the lightest body [s] (derived)
    double contact_restitution = 1.0;       ///< its restitution (derived)
    double contact_tangential_ratio = 2.0 / 7.0; ///< κ = k_t / k of the linear model
    double contact_impact_velocity = 0.0; ///< impact speed that sets the sub-steps [m/s] (Hertz)
    double contact_reference_mass = 0.0;  ///< mass of the lightest free body [kg] (derived)
    Material wall_material;               ///< the walls' surface: [walls] keys, else [contact]'s

    // [nondimensional]: given, fddem derives viscosity, gravity and body densities.
    std::optional<double> reynolds;       ///< Re = ρf U_c D / μ
    std::optional<double> density_ratio;  ///< ρr = ρs / ρf
    double characteristic_velocity = 1.0; ///< U_c [m/s] (eq. 21 sets g so that U_c results)
    double wall_factor = 0.0;             ///< K of eq. (20) used (derived; 0 if not derived)

    // [output]
    std::string output_directory;   ///< empty: runs/<case file stem>
    double field_interval = 0.0;    ///< [s]; 0: fields at the end only
    double particle_interval = 0.0; ///< [s]; 0: particles.csv every step
    long log_interval = 100;        ///< steps between plain log lines (no terminal)
    std::vector<LineSample> lines;

    // [checkpoint]
    long checkpoint_step_interval = 1000;  ///< steps between checkpoints; 0: not by steps
    double checkpoint_time_interval = 0.0; ///< [s]; 0: not by simulated time
    int checkpoint_keep = 2;               ///< newest checkpoints kept
};

} // namespace fddem
