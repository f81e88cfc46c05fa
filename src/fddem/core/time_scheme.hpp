// SPDX-License-Identifier: MIT
#pragma once
/// The time derivative of the momentum equations (7)–(8) and of the bodies' eqs. (13)–(14):
/// implicit Euler, as the paper, or the second-order backward difference formula (BDF2),
/// time.scheme. Both are written in one form, so that every stage keeps the paper's Euler
/// shape and only two numbers change:
///
///   ∂u/∂t at t^{n+1} ≈ (u^{n+1} − ũ^n) / Δt_e.
///
/// Euler: Δt_e = Δt, ũ^n = u^n.
/// BDF2 with variable steps (ω = Δt_n/Δt_{n−1}): the derivative at t^{n+1} of the parabola
/// through the three levels (variable-step BDF, Hairer, Nørsett & Wanner 1993, §III.5),
///
///   ∂u/∂t ≈ [(1+2ω)/(1+ω) u^{n+1} − (1+ω) u^n + ω²/(1+ω) u^{n−1}] / Δt_n,
///
/// which is the form above with Δt_e = Δt_n (1+ω)/(1+2ω) (the leading coefficient folded into
/// the step) and ũ^n = u^n + w (u^n − u^{n−1}), w = ω²/(1+2ω) (the coefficients of u^n and
/// u^{n−1} sum to the leading one). With a constant step Δt_e = 2Δt/3 and w = 1/3.

namespace fddem {

/// time.scheme
enum class TimeScheme { euler, bdf2 };

/// The two numbers of one step's time derivative (see above).
struct TimeLevels {
    double dt_effective;         ///< Δt_e [s]: Δt over the leading coefficient
    double history_weight = 0.0; ///< w in ũ^n = u^n + w (u^n − u^{n−1}); 0: implicit Euler
    double step_ratio = 0.0;     ///< ω = Δt_n/Δt_{n−1}; 0 at a run's first step

    [[nodiscard]] bool has_history() const noexcept { return history_weight != 0.0; }
    /// ũ^n from the level-n and level-(n−1) values (numbers or small vectors).
    template <class T>
    [[nodiscard]] T history(const T& now, const T& before) const
    {
        return has_history() ? T(now + history_weight * (now - before)) : now;
    }
};

/// The time levels of a step of `dt` [s] that follows one of `previous_dt` [s]. BDF2 needs
/// u^{n−1}: with previous_dt ≤ 0 (the first step of a run) it falls back to implicit Euler.
[[nodiscard]] TimeLevels time_levels(TimeScheme scheme, double dt, double previous_dt);

} // namespace fddem
