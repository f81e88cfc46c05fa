// SPDX-License-Identifier: MIT
#pragma once
/// Anderson acceleration of a fixed-point iteration x ← G(x) (Anderson 1965; in the form of
/// Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715, "Algorithm AA", without damping).
///
/// With the residuals f_k = G(x_k) − x_k of the last m + 1 iterates, the next iterate is
///   x_{k+1} = G(x_k) − Σ_i γ_i ΔG_i,   γ = argmin ‖f_k − Σ_i γ_i ΔF_i‖₂,
/// where ΔF_i = f_{i+1} − f_i and ΔG_i = G(x_{i+1}) − G(x_i). The weights of the G(x_i) in
/// x_{k+1} sum to one, so a linear constraint that every G(x) satisfies (a discretely
/// divergence-free velocity, affine boundary values) holds for x_{k+1} too.
///
/// fddem uses it on the SIMPLE outer iterations of a step with bodies (docs/method.md §2): in
/// a crowd of bodies the error decays along one collective mode of the bodies and the fluid
/// between them, by a nearly constant factor (0.83–0.92 per iteration in the Figs. 9–13 pile,
/// successive changes of the body velocities parallel to a cosine of 0.999), the case the
/// method handles best.
///
/// Written here rather than taken from a library: Debian has it only inside nonlinear-solver
/// suites (PETSc's SNESANDERSON, SUNDIALS' KINSOL) that own the state vector and the
/// iteration, while fddem's state lives in its grid arrays and marker lists; the method itself
/// is a few vector updates and an m × m least-squares problem (Eigen).
///
/// The state is a list of segments (spans over the live arrays) with the same layout at every
/// call between resets. Segments with a positive weight enter the least-squares norm, each
/// entry multiplied by its segment's weight (e.g. an angular velocity by a radius, to compare
/// it with velocities); they must come first. Segments of weight 0 are carried along: mixed
/// with the same γ, but not measured. Sums are taken in fixed blocks added in block order, so
/// the result is bit-identical for any thread count.

#include <cstddef>
#include <span>
#include <vector>

namespace fddem {

/// One part of the mixed state: live values and their weight in the norm (0: carried).
struct MixedSegment {
    std::span<double> values;
    double weight = 0.0;
};

class AndersonMixing {
public:
    /// `depth` = m, the number of differences kept (0: plain fixed-point iteration).
    explicit AndersonMixing(int depth);

    /// Forgets the history: the next remember()/mix() pair starts afresh (a new time step).
    void reset() noexcept;

    /// Takes x_k: the measured segments of the state before an iteration.
    void remember(std::span<const MixedSegment> segments);

    /// The segments hold G(x_k) of the x_k last remembered; overwrites them with x_{k+1}. The
    /// first call after reset() leaves them as they are.
    void mix(std::span<const MixedSegment> segments);

    [[nodiscard]] int depth() const noexcept { return depth_; }
    /// The weights γ of the last mix() (newest difference first), for tests and diagnostics.
    [[nodiscard]] const std::vector<double>& last_weights() const noexcept { return gamma_; }

private:
    int depth_;
    std::vector<double> x_;          ///< the measured part of x_k, weighted
    std::vector<double> f_previous_; ///< f_{k−1} (measured part, weighted)
    std::vector<double> g_previous_; ///< G(x_{k−1}) (all segments)
    bool has_previous_ = false;
    /// ΔF (measured part) and ΔG (all) columns: a ring of `depth_` slots, `columns_` of them
    /// filled, the newest at `newest_`.
    std::vector<std::vector<double>> delta_f_;
    std::vector<std::vector<double>> delta_g_;
    int columns_ = 0;
    int newest_ = -1;
    std::vector<double> gram_; ///< ΔFᵀΔF of the slots (depth × depth, row-major)
    std::vector<double> gamma_;
};

/// Σ a_i b_i, in blocks added in block order (thread-count independent).
[[nodiscard]] double blocked_dot(std::span<const double> a, std::span<const double> b);

} // namespace fddem
