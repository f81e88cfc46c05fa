// SPDX-License-Identifier: MIT
#include "fddem/linsolve/anderson_mixing.hpp"

#include "fddem/core/errors.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fddem {
namespace {

// A kernel of its own (STYLE.md §4): its vectors are flat concatenations of grid arrays and
// marker lists, not boxes of a grid, so grid/loops.hpp's loops do not apply.
// Block of the sums: long enough to amortise the partial sums, short enough for several per
// thread at the paper's grid sizes (10⁵ values); fixed, so that sums do not depend on threads.
constexpr std::size_t block_size = 4096;
// Below this many values a loop is not worth a parallel region (grid/loops.hpp's 8192 cells
// are 16384 values of a 2D component and its neighbour).
constexpr std::size_t min_size_for_threads = 16384;

/// f(i) for i in [0, n), threaded when long (each element independent of the others).
template <class F>
void for_each_element(std::size_t n, F&& f)
{
    const auto count = static_cast<std::ptrdiff_t>(n);
    [[maybe_unused]] const bool is_threaded = n >= min_size_for_threads;
#pragma omp parallel for schedule(static) if (is_threaded)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        f(static_cast<std::size_t>(i));
    }
}

/// The number of leading segments with a positive weight (the measured ones).
std::size_t measured_segments(std::span<const MixedSegment> segments)
{
    for (const MixedSegment& segment : segments) {
        if (!(segment.weight >= 0.0)) {
            throw std::logic_error("AndersonMixing: a segment's weight must be 0 or positive");
        }
    }
    std::size_t n = 0;
    while (n < segments.size() && segments[n].weight > 0.0) {
        ++n;
    }
    for (std::size_t s = n; s < segments.size(); ++s) {
        if (segments[s].weight != 0.0) {
            throw std::logic_error("AndersonMixing: measured segments must come first");
        }
    }
    return n;
}

std::size_t total_size(std::span<const MixedSegment> segments, std::size_t count)
{
    std::size_t n = 0;
    for (std::size_t s = 0; s < count; ++s) {
        n += segments[s].values.size();
    }
    return n;
}

/// f(weight · segment value, flat index) over the first `count` segments, in order.
template <class F>
void for_each_in_segments(std::span<const MixedSegment> segments, std::size_t count, F&& f)
{
    std::size_t offset = 0;
    for (std::size_t s = 0; s < count; ++s) {
        const std::span<double> values = segments[s].values;
        const double weight = segments[s].weight;
        for_each_element(values.size(), [&](std::size_t i) { f(weight * values[i], offset + i); });
        offset += values.size();
    }
}

/// f(segment value, flat index) over all segments, in order.
template <class F>
void for_each_value(std::span<const MixedSegment> segments, F&& f)
{
    std::size_t offset = 0;
    for (const MixedSegment& segment : segments) {
        const std::span<double> values = segment.values;
        for_each_element(values.size(), [&](std::size_t i) { f(values[i], offset + i); });
        offset += values.size();
    }
}

} // namespace

double blocked_dot(std::span<const double> a, std::span<const double> b)
{
    assert(a.size() == b.size());
    const std::size_t n = a.size();
    const std::size_t blocks = (n + block_size - 1) / block_size;
    std::vector<double> partial(blocks, 0.0);
    const auto count = static_cast<std::ptrdiff_t>(blocks);
    [[maybe_unused]] const bool is_threaded = n >= min_size_for_threads;
#pragma omp parallel for schedule(static) if (is_threaded)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
        const auto first = static_cast<std::size_t>(k) * block_size;
        const std::size_t end = std::min(n, first + block_size);
        double acc = 0.0;
        for (std::size_t i = first; i < end; ++i) {
            acc += a[i] * b[i];
        }
        partial[static_cast<std::size_t>(k)] = acc;
    }
    double sum = 0.0;
    for (const double p : partial) {
        sum += p;
    }
    return sum;
}

double round_to_significant_bits(double x, int bits)
{
    FDDEM_ASSERT(bits >= 1, "round_to_significant_bits needs at least one bit");
    if (x == 0.0 || !std::isfinite(x) || bits >= std::numeric_limits<double>::digits) {
        return x;
    }
    int exponent = 0;
    // x = mantissa · 2^exponent, |mantissa| in [0.5, 1)
    const double mantissa = std::frexp(x, &exponent);
    if (exponent >= std::numeric_limits<double>::max_exponent) {
        return x; // |x| ≥ 2¹⁰²³: rounding up could overflow
    }
    // std::nearbyint in the default rounding mode: ties to even. Scaling by powers of two is exact.
    return std::ldexp(std::nearbyint(std::ldexp(mantissa, bits)), exponent - bits);
}

AndersonMixing::AndersonMixing(int depth, int weight_bits, double max_step_ratio)
    : depth_(std::max(depth, 0)), weight_bits_(std::max(weight_bits, 0)),
      max_step_ratio_(std::max(max_step_ratio, 0.0)), delta_f_(static_cast<std::size_t>(depth_)),
      delta_g_(static_cast<std::size_t>(depth_)),
      gram_(static_cast<std::size_t>(depth_ * depth_), 0.0)
{
}

void AndersonMixing::reset() noexcept
{
    has_previous_ = false;
    columns_ = 0;
    newest_ = -1;
    gamma_.clear();
    step_ratio_ = 0.0;
}

void AndersonMixing::remember(std::span<const MixedSegment> segments)
{
    if (depth_ == 0) {
        return;
    }
    const std::size_t norm_segments = measured_segments(segments);
    x_.resize(total_size(segments, norm_segments));
    for_each_in_segments(segments, norm_segments, [&](double v, std::size_t i) { x_[i] = v; });
}

bool AndersonMixing::mix(std::span<const MixedSegment> segments)
{
    if (depth_ == 0) {
        return true;
    }
    const std::size_t norm_segments = measured_segments(segments);
    const std::size_t measured = total_size(segments, norm_segments);
    const std::size_t all = total_size(segments, segments.size());
    if (measured != x_.size()) {
        throw std::logic_error("AndersonMixing::mix: the state's layout changed since remember()");
    }
    const auto m = static_cast<std::size_t>(depth_);
    if (has_previous_) {
        if (f_previous_.size() != measured || g_previous_.size() != all) {
            throw std::logic_error("AndersonMixing::mix: the state's layout changed");
        }
        // The newest column: ΔF = f_k − f_{k−1}, ΔG = G(x_k) − G(x_{k−1}); then f_k, G(x_k)
        // become the previous ones.
        newest_ = (newest_ + 1) % depth_;
        columns_ = std::min(columns_ + 1, depth_);
        const auto s = static_cast<std::size_t>(newest_);
        std::vector<double>& df = delta_f_[s];
        std::vector<double>& dg = delta_g_[s];
        df.resize(measured);
        dg.resize(all);
        for_each_in_segments(segments, norm_segments, [&](double g, std::size_t i) {
            const double f = g - x_[i];
            df[i] = f - f_previous_[i];
            f_previous_[i] = f;
        });
        for_each_value(segments, [&](double g, std::size_t i) {
            dg[i] = g - g_previous_[i];
            g_previous_[i] = g;
        });
        for (std::size_t j = 0; j < static_cast<std::size_t>(columns_); ++j) {
            const double value = blocked_dot(df, delta_f_[j]);
            gram_[s * m + j] = value;
            gram_[j * m + s] = value;
        }
    } else {
        f_previous_.resize(measured);
        g_previous_.resize(all);
        for_each_in_segments(segments, norm_segments,
                             [&](double g, std::size_t i) { f_previous_[i] = g - x_[i]; });
        for_each_value(segments, [&](double g, std::size_t i) { g_previous_[i] = g; });
        has_previous_ = true;
    }
    gamma_.clear();
    if (columns_ == 0) {
        return true;
    }

    // γ from the normal equations ΔFᵀΔF γ = ΔFᵀ f_k, by a pseudo-inverse that drops the
    // directions with eigenvalues below 1e-12 of the largest: nearly parallel columns (a
    // converged mode) would otherwise get huge weights of opposite sign.
    const auto n = static_cast<Eigen::Index>(columns_);
    Eigen::MatrixXd gram(n, n);
    Eigen::VectorXd rhs(n);
    for (Eigen::Index a = 0; a < n; ++a) {
        const auto sa = static_cast<std::size_t>(a);
        for (Eigen::Index b = 0; b < n; ++b) {
            gram(a, b) = gram_[sa * m + static_cast<std::size_t>(b)];
        }
        rhs(a) = blocked_dot(delta_f_[sa], f_previous_);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
    const Eigen::VectorXd& values = eigen.eigenvalues();
    const double cutoff = 1e-12 * values.cwiseAbs().maxCoeff();
    Eigen::VectorXd projected = eigen.eigenvectors().transpose() * rhs;
    for (Eigen::Index k = 0; k < n; ++k) {
        projected(k) = values(k) > cutoff ? projected(k) / values(k) : 0.0;
    }
    Eigen::VectorXd gamma = eigen.eigenvectors() * projected;
    if (weight_bits_ > 0) { // see the header: the same γ on any number of ranks
        for (Eigen::Index k = 0; k < n; ++k) {
            gamma(k) = round_to_significant_bits(gamma(k), weight_bits_);
        }
    }
    for (int k = 0; k < columns_; ++k) { // newest first
        gamma_.push_back(gamma(static_cast<Eigen::Index>((newest_ - k + depth_) % depth_)));
    }

    // The step's bound (see the header): Σ γ_j ΔG_j over the measured part, weighted like f_k.
    std::vector<double> step(measured, 0.0);
    {
        std::size_t offset = 0;
        for (std::size_t s = 0; s < norm_segments; ++s) {
            const double weight = segments[s].weight;
            for_each_element(segments[s].values.size(), [&](std::size_t i) {
                double value = 0.0;
                for (Eigen::Index j = 0; j < n; ++j) {
                    value += gamma(j) * delta_g_[static_cast<std::size_t>(j)][offset + i];
                }
                step[offset + i] = weight * value;
            });
            offset += segments[s].values.size();
        }
    }
    const double step_norm = std::sqrt(blocked_dot(step, step));
    const double residual_norm = std::sqrt(blocked_dot(f_previous_, f_previous_));
    step_ratio_ = residual_norm > 0.0 ? step_norm / residual_norm
                  : step_norm > 0.0   ? std::numeric_limits<double>::infinity()
                                      : 0.0;
    if (max_step_ratio_ > 0.0 && step_ratio_ > max_step_ratio_) {
        // Refused: G(x_k) stays, and the differences start again from it (f_previous_ and
        // g_previous_ hold f_k and G(x_k) already).
        columns_ = 0;
        newest_ = -1;
        return false;
    }

    // x_{k+1} = G(x_k) − Σ γ_j ΔG_j
    std::size_t offset = 0;
    for (const MixedSegment& segment : segments) {
        const std::span<double> out = segment.values;
        for_each_element(out.size(), [&](std::size_t i) {
            double value = out[i];
            for (Eigen::Index j = 0; j < n; ++j) {
                value -= gamma(j) * delta_g_[static_cast<std::size_t>(j)][offset + i];
            }
            out[i] = value;
        });
        offset += out.size();
    }
    return true;
}

} // namespace fddem
