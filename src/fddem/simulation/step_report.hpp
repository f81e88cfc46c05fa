// SPDX-License-Identifier: MIT
#pragma once
/// What one time step did, as solver.csv and the convergence and stopping tests read it.

namespace fddem {

struct StepReport {
    int outer_iterations = 0;
    /// A projection step (simple.algorithm): the rounds of sweeps (or V-cycles) its predictor
    /// took; 0 for a step of SIMPLE's outer iterations, which is how the messages tell the two
    /// apart (not in solver.csv)
    int momentum_rounds = 0;
    bool is_converged = false;      ///< residuals below tolerance within the iteration limit
    double mass_residual = 0.0;     ///< max |∇·u*| h / U_ref of the last outer iteration
    double momentum_residual = 0.0; ///< max |r/a_P| / U_ref of the accepted iterate
    double courant = 0.0;           ///< max_d max |u_d| Δt / h_d after the step
    double rate_of_change = 0.0;    ///< max |u^{n+1} − u^n| / Δt · L / U_ref² (steady check)
    double rigid_defect = 0.0; ///< max |U + ω×r − I(u)| / U_ref over markers, last iteration
    double body_change = 0.0;  ///< max (|ΔU| + R|Δω|) / U_ref over bodies, last iteration
    double max_overlap = 0.0;  ///< largest contact overlap α in the DEM sub-steps [m]
    double max_relative_overlap = 0.0; ///< largest α / radius (of the smaller body)
    int contacts = 0;                  ///< contacts at the end of the DEM sub-steps
    int unfinished_film_solves = 0;    ///< DemOutcome::n_unfinished_film_solves (not in solver.csv)
    int retries = 0; ///< times the step was taken again at half its Δt (time.max_retries)
};

} // namespace fddem
