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
///
/// The weights γ are rounded to `weight_bits` significant bits (default 12, the case key
/// simple.acceleration_weight_bits: a relative change of at most 2⁻¹² = 2.4e-4). Unrounded, γ is
/// a steep function of the iterates near convergence (ΔF is a difference of nearly equal
/// residuals), and the mixed iteration amplified a round-off difference in its inputs by up to 1e4
/// per time step: a run on two ranks, whose sums are added in another order, left the
/// one-process run by 1.7e-4 within six steps (docs/parallel.md, "Anderson mixing and the same
/// answer"). Rounded, the same γ comes out of both runs unless an unrounded γ lies within its
/// round-off of a rounding boundary; with the same γ, the update is affine in the iterates, so a
/// difference between the runs is carried by fixed weights instead of moving them.
///
/// The step may be bounded (a safeguard of the kind Walker & Ni §5 and Henderson & Varadhan, J.
/// Comput. Graph. Stat. 28 (2019) 834, discuss): the extrapolation x_{k+1} − G(x_k) = −Σ γ_i ΔG_i,
/// measured like f_k, at most `max_step_ratio` times ‖f_k‖. On a linear iteration that contracts
/// its slowest mode by ρ, the step to the fixed point is ρ/(1 − ρ) ‖f_k‖ along it, so a bound of
/// 100 leaves the mixing every mode with ρ ≤ 0.99. A larger step is a secant through residuals
/// that have stopped shrinking (a floor below which G's residual wanders): tiny, nearly
/// parallel ΔF give γ of 10–100, and the whole carried state (the fluid) is thrown along a
/// difference the measured part cannot see. Such a step is refused: the segments keep G(x_k), and
/// the mixing restarts from this iterate (its f_k and G(x_k) are the next differences' base).
/// Off by default: on the paper's Fig. 3, whose tolerance lies near that floor, a bound of 100
/// left 67 of 600 steps unconverged where the unbounded mixing converges all (docs/method.md §4,
/// "The mixing's step bounded").
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
    /// The significant bits γ is rounded to (0: not rounded).
    static constexpr int default_weight_bits = 12;
    /// The largest ‖x_{k+1} − G(x_k)‖ / ‖f_k‖ a mix() may take (see above; 0: not bounded).
    static constexpr double default_max_step_ratio = 0.0;

    /// `depth` = m, the number of differences kept (0: plain fixed-point iteration);
    /// `weight_bits`: γ rounded to that many significant bits (0: not rounded);
    /// `max_step_ratio`: the bound on the step (0: none).
    explicit AndersonMixing(int depth, int weight_bits = default_weight_bits,
                            double max_step_ratio = default_max_step_ratio);

    /// Forgets the history: the next remember()/mix() pair starts afresh (a new time step).
    void reset() noexcept;

    /// Takes x_k: the measured segments of the state before an iteration.
    void remember(std::span<const MixedSegment> segments);

    /// The segments hold G(x_k) of the x_k last remembered; overwrites them with x_{k+1}. The
    /// first call after reset() leaves them as they are, and so does a refused step. Returns
    /// false for a refused step (the mixing then restarts from this iterate), true otherwise.
    bool mix(std::span<const MixedSegment> segments);

    [[nodiscard]] int depth() const noexcept { return depth_; }
    /// The weights γ of the last mix() (newest difference first), for tests and diagnostics.
    [[nodiscard]] const std::vector<double>& last_weights() const noexcept { return gamma_; }
    /// ‖x_{k+1} − G(x_k)‖ / ‖f_k‖ of the last mix() that had weights (also of a refused one).
    [[nodiscard]] double last_step_ratio() const noexcept { return step_ratio_; }

private:
    int depth_;
    int weight_bits_;
    double max_step_ratio_;
    double step_ratio_ = 0.0;
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

/// x rounded to the nearest number with `bits` significant bits (ties to even; bits ≥ 1): a
/// relative change of at most 2^−bits. 0, infinities, NaN, |x| ≥ 2¹⁰²³ (whose rounding could
/// overflow) and bits ≥ 53 (a double's own precision) give x as it is.
[[nodiscard]] double round_to_significant_bits(double x, int bits);

/// Σ a_i b_i, in blocks added in block order (thread-count independent).
[[nodiscard]] double blocked_dot(std::span<const double> a, std::span<const double> b);

} // namespace fddem
