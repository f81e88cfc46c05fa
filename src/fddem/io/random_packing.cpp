// SPDX-License-Identifier: MIT
#include "fddem/io/random_packing.hpp"

#include "fddem/core/errors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

namespace fddem {
namespace {

/// Placed balls by cell of a uniform grid, hashed into buckets: a trial centre is compared with
/// the balls of its own and the neighbouring cells only. Cells are as wide as the farthest
/// reach of a conflict (both radii and the gap), so no conflict is missed; balls of other cells
/// that share a bucket are merely compared too. Hashing keeps the memory to the number of balls
/// however large the region is.
template <int Dim>
class BallHash {
public:
    BallHash(const Vec<Dim>& origin, double cell_width, std::size_t n_balls)
        : origin_(origin), cell_width_(cell_width),
          buckets_(std::bit_ceil(std::max<std::size_t>(2 * n_balls, 16)))
    {
    }

    void insert(const PlacedBall<Dim>& ball)
    {
        balls_.push_back(ball);
        buckets_[bucket(cell_of(ball.centre))].push_back(balls_.size() - 1);
    }

    /// Whether a ball of `radius` at `centre` would leave less than `gap` to a placed one.
    [[nodiscard]] bool conflicts(const Vec<Dim>& centre, double radius, double gap) const
    {
        const Eigen::Matrix<long, Dim, 1> cell = cell_of(centre);
        Eigen::Matrix<long, Dim, 1> offset = Eigen::Matrix<long, Dim, 1>::Constant(-1);
        while (true) {
            for (const std::size_t k : buckets_[bucket(cell + offset)]) {
                const PlacedBall<Dim>& ball = balls_[k];
                const double reach = radius + ball.radius + gap;
                if ((ball.centre - centre).squaredNorm() < reach * reach) {
                    return true;
                }
            }
            int axis = 0;
            while (axis < Dim && offset[axis] == 1) {
                offset[axis++] = -1;
            }
            if (axis == Dim) {
                return false;
            }
            ++offset[axis];
        }
    }

private:
    [[nodiscard]] Eigen::Matrix<long, Dim, 1> cell_of(const Vec<Dim>& x) const
    {
        return ((x - origin_) / cell_width_).array().floor().template cast<long>();
    }

    [[nodiscard]] std::size_t bucket(const Eigen::Matrix<long, Dim, 1>& cell) const
    {
        // Large odd multipliers (Teschner et al. 2003 use primes the same way) spread
        // neighbouring cells over the buckets; their count is a power of two.
        constexpr std::uint64_t multipliers[3] = {0x9E3779B97F4A7C15ULL, 0xC2B2AE3D27D4EB4FULL,
                                                  0x165667B19E3779F9ULL};
        std::uint64_t hash = 0;
        for (int axis = 0; axis < Dim; ++axis) {
            hash ^= static_cast<std::uint64_t>(cell[axis]) * multipliers[axis];
        }
        hash ^= hash >> 29U;
        return static_cast<std::size_t>(hash & (buckets_.size() - 1));
    }

    Vec<Dim> origin_;
    double cell_width_;
    std::vector<PlacedBall<Dim>> balls_;
    std::vector<std::vector<std::size_t>> buckets_;
};

} // namespace

template <int Dim>
Packing<Dim> random_packing(const PackingRequest<Dim>& request)
{
    const double radius = 0.5 * request.diameter;
    const Vec<Dim> margin = Vec<Dim>::Constant(radius + request.gap);
    const Vec<Dim> low = request.low + margin;
    const Vec<Dim> span = request.high - margin - low;
    if ((span.array() < 0.0).any() || request.diameter <= 0.0 || request.gap < 0.0) {
        throw InternalError("random_packing: the region does not hold one ball with its gap");
    }
    double largest = radius;
    for (const PlacedBall<Dim>& ball : request.obstacles) {
        largest = std::max(largest, ball.radius);
    }
    BallHash<Dim> placed(request.low, radius + largest + request.gap,
                         request.obstacles.size() + static_cast<std::size_t>(request.count));
    for (const PlacedBall<Dim>& ball : request.obstacles) {
        placed.insert(ball);
    }

    std::mt19937_64 random(request.seed);
    Packing<Dim> packing;
    const long max_trials = request.count * request.trials_per_ball;
    while (static_cast<long>(packing.centres.size()) < request.count &&
           packing.trials < max_trials) {
        Vec<Dim> centre;
        for (int axis = 0; axis < Dim; ++axis) {
            centre[axis] = low[axis] + uniform_unit(random()) * span[axis];
        }
        ++packing.trials;
        if (placed.conflicts(centre, radius, request.gap)) {
            continue;
        }
        placed.insert({centre, radius});
        packing.centres.push_back(centre);
    }
    return packing;
}

template Packing<2> random_packing<2>(const PackingRequest<2>&);
template Packing<3> random_packing<3>(const PackingRequest<3>&);

} // namespace fddem
