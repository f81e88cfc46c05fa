// SPDX-License-Identifier: MIT
#pragma once
/// How long the next time step is. The paper's cases march at the fixed Δt of time.dt; beyond
/// the paper, two controls (off by default):
///
/// - A Courant limit (time.max_courant = C): Δt ≤ C / max(max_d |u_d|/h_d, (|U| + |ω|R)/h), the
///   fluid's and the bodies' speed per cell at the start of the step, and Δt ≤ time.dt, which is
///   then the largest and the first step. Δt grows by at most `max_growth` per step, so that a
///   flow that speeds up and slows down does not make the step oscillate.
/// - Pseudo-time to a steady state (time.steady): switched evolution relaxation (Mulder & van
///   Leer 1985, J. Comput. Phys. 59, 232: "SER"), Δt_{n+1} = Δt_n · r_{n−1}/r_n with r the
///   steady residual max|∂u/∂t| L/U² of the last two steps, the ratio held within
///   [1/max_growth, max_growth]. The implicit-Euler step becomes a Newton-like step as r → 0
///   and Δt → ∞; the Courant limit, if given, caps it. A step whose outer iterations did not
///   converge halves Δt instead: its r = |Δu|/Δt is then no residual of the steady equations
///   (it falls with 1/Δt for the same Δu, and SER would grow Δt without end; measured on the
///   Re 1000 cavity: Δt doubled to 250 s with every step unconverged).

#include "fddem/simulation/step_report.hpp"

#include <optional>
#include <string>

namespace fddem {

struct TimeStepSettings {
    double initial_dt;                 ///< time.dt [s]
    std::optional<double> max_courant; ///< time.max_courant
    bool is_steady = false;            ///< time.steady
    std::optional<double> end_time;    ///< time.end [s]: the last step ends on it
    /// Largest growth of Δt from one step to the next (the Courant limit; SER's ratio bound).
    /// 1.2 for the Courant limit (a common choice, e.g. OpenFOAM's maxDeltaT growth of 1.2);
    /// 2 for SER, which Mulder & van Leer let grow without bound and which here keeps SIMPLE's
    /// outer iterations converging from one step to the next.
    double max_growth = 1.2;
};

/// The steady residuals r = max|∂u/∂t| L/U² of the last two steps (0: no such step yet), which
/// SER needs; checkpointed.
struct TimeStepHistory {
    double residual = 0.0;          ///< r_n, of the last step
    double previous_residual = 0.0; ///< r_{n−1}
    bool is_converged = true;       ///< the last step's outer iterations converged

    /// After a step with residual r.
    void push(double r, bool converged) noexcept
    {
        previous_residual = residual;
        residual = r;
        is_converged = converged;
    }
};

/// The smallest step time.max_courant may ask for before the run is stopped as diverged:
/// time.min_dt if given, else this share of time.dt.
inline constexpr double collapsed_step_share = 1e-6;

/// Whether the Courant limit asks for a step shorter than `min_dt` [s] at `speed_per_cell`
/// [1/s]: a flow whose speed grows as Δt shrinks, which is a diverged solution and not a fast
/// one. Without the test such a run marches on at ever smaller steps and never ends (the
/// 200-sphere soak, 2026-11-28: Δt from 5e-4 s to 1e-96 s over 900 steps at a Courant number of
/// 0.38, the velocity growing as 1/Δt). The end-time landing is not tested: its last step may be
/// short by design. Pure.
[[nodiscard]] bool is_step_collapsed(const TimeStepSettings& settings, double speed_per_cell,
                                     double min_dt) noexcept;

/// When a step is taken again from its start at half its Δt (time.max_retries and the
/// time.retry_* keys; only with time.max_courant, whose controller then grows Δt back by at
/// most max_growth a step). A step that blows up (NumericalError) is always retried; a finished
/// one if its report crosses one of the optional limits.
struct RetrySettings {
    int max_retries = 0;                 ///< time.max_retries: retries of one step at most
    std::optional<double> mass_residual; ///< time.retry_mass_residual
    std::optional<double> courant;       ///< time.retry_courant
};

/// The Courant number after it above which a finished step is retried when the case names no
/// time.retry_courant: this many times time.max_courant. The controller predicts the step from
/// its start, so the flow may end it faster than asked: up to 2.34 times the limit in a run
/// that did not fail (the heavy disk of AdaptiveTimeStep.*, C = 0.5). A step ending four times
/// beyond it has failed, whatever the cause: the Gondret St 27 sphere at Δt 1e-4 s ended one
/// at 28 times (8.4), 3 d above the wall, its outer iterations unconverged in that step and the
/// one before. Not every failure gets that far: the step before it ended at 1.69 times, and
/// St 152's stall in contact (since mended) at 1.9 times (docs/method.md §1, "The time step's
/// length", Retries).
inline constexpr double default_retry_courant_factor = 4.0;

/// time.retry_courant if the case gives it, else default_retry_courant_factor × time.max_courant
/// (none without the Courant limit, where nothing is retried). Pure.
[[nodiscard]] std::optional<double> retry_courant_limit(std::optional<double> retry_courant,
                                                        std::optional<double> max_courant) noexcept;

/// Why the finished step of `report` is to be retried (the limit it crossed, in words), or
/// empty if it is to be kept. Pure.
[[nodiscard]] std::string retry_reason(const RetrySettings& retry, const StepReport& report);

/// Whether a step of `dt` [s] that failed after `retries` retries may be taken again at
/// dt/2: the step is adaptive (time.max_courant), retries are left, and dt/2 is no shorter
/// than `min_dt` [s]. Pure.
[[nodiscard]] bool may_retry(const TimeStepSettings& settings, const RetrySettings& retry,
                             int retries, double dt, double min_dt) noexcept;

/// Δt [s] for a step from `time` [s] after one of `dt` [s], given the largest speed per cell
/// `speed_per_cell` = max |u|/h over the fluid and the bodies [1/s] now. The step lands on the
/// end time and on `landing` [s], if given and ahead (a body's release: bodies.release_time),
/// rather than stepping past them. Pure.
[[nodiscard]] double next_time_step(const TimeStepSettings& settings, double dt, double time,
                                    double speed_per_cell, const TimeStepHistory& history,
                                    std::optional<double> landing = std::nullopt);

} // namespace fddem
