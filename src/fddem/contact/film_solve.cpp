// SPDX-License-Identifier: MIT
#include "fddem/contact/film_solve.hpp"

#include "fddem/core/errors.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace fddem {
namespace {

constexpr long none = -1;

/// Degrees of freedom of a body's rotation: 1 in 2D, 3 in 3D.
template <int Dim>
constexpr int angular_size = Dim == 2 ? 1 : 3;

/// Systems up to this many unknowns are factorised dense, larger ones iterated (GapSystem).
// 24: eight bodies' normal unknowns in 3D, four bodies' with their spins; a dense LDLT of that
// size costs about what a few CG iterations over the gaps do (a choice, not tuned to a case).
constexpr long largest_dense = 24;

template <int Dim>
bool is_wall(std::size_t b)
{
    return b == FilmGap<Dim>::wall;
}

/// The gap at the sub-step's start, h0 (the geometry's overlap turned round).
template <int Dim>
double gap_of(const FilmGap<Dim>& gap)
{
    return -gap.geometry.overlap;
}

/// Whether the film acts on a gap that moves at `rate` over the sub-step: its correction is
/// not zero over the gap's travel (out of the range, or overlapping with lubrication.in_contact
/// "off", it is). A gap it does not act on changes nothing in the solve (G is flat over its
/// travel) and joins no component: a body with one film besides its contacts keeps the sweep's
/// bits.
template <int Dim>
bool acts(const FilmGap<Dim>& gap, double rate, double step, const LubricationSettings& settings)
{
    const double h0 = gap_of(gap);
    const LubricationResistance mean = lubrication_correction_over<Dim>(
        h0, h0 + step * rate, gap.first_radius, gap.second_radius, settings, gap.shell_gap);
    return mean.normal != 0.0 || mean.tangential != 0.0;
}

/// A set of gaps joined by the free bodies they share, and those bodies.
struct Component {
    std::vector<std::size_t> gaps;
    std::vector<std::size_t> bodies;
};

/// The components of the gaps of `active` (union–find over the free bodies; a gap between
/// bodies that are not free is a component of its own, without bodies). In the order of their
/// first gap, each one's gaps and bodies in increasing index.
template <int Dim>
std::vector<Component> components_of(std::span<const FilmBody<Dim>> bodies,
                                     std::span<const FilmGap<Dim>> gaps,
                                     std::span<const std::size_t> active)
{
    std::vector<std::size_t> root(bodies.size());
    std::iota(root.begin(), root.end(), std::size_t{0});
    const auto find = [&](std::size_t b) {
        while (root[b] != b) {
            root[b] = root[root[b]];
            b = root[b];
        }
        return b;
    };
    const auto is_free = [&](std::size_t b) { return !is_wall<Dim>(b) && bodies[b].is_free; };
    for (const std::size_t k : active) {
        if (is_free(gaps[k].first) && is_free(gaps[k].second)) {
            const std::size_t x = find(gaps[k].first);
            const std::size_t y = find(gaps[k].second);
            root[std::max(x, y)] = std::min(x, y);
        }
    }
    std::vector<Component> components;
    std::vector<long> component_of_root(bodies.size(), none);
    std::vector<char> is_taken(bodies.size(), 0);
    for (const std::size_t k : active) {
        const FilmGap<Dim>& g = gaps[k];
        const std::size_t anchor = is_free(g.first) ? g.first : g.second;
        if (!is_free(anchor)) {
            components.push_back({{k}, {}});
            continue;
        }
        const std::size_t r = find(anchor);
        if (component_of_root[r] == none) {
            component_of_root[r] = static_cast<long>(components.size());
            components.emplace_back();
        }
        Component& c = components[static_cast<std::size_t>(component_of_root[r])];
        c.gaps.push_back(k);
        for (const std::size_t b : {g.first, g.second}) {
            if (is_free(b) && is_taken[b] == 0) {
                is_taken[b] = 1;
                c.bodies.push_back(b);
            }
        }
    }
    for (Component& c : components) {
        std::sort(c.bodies.begin(), c.bodies.end());
    }
    return components;
}

/// A component's system M + Σ_k w_k J_kᵀ J_k, with M a diagonal mass (per body: `Width`
/// entries) and J_k = [J_k,first | J_k,second] a gap's Jacobian (`Rows` × `Width` per side), in
/// the unknowns of the component's bodies (local index i: unknowns Width i to Width i + Width − 1).
/// Small systems are factorised dense; larger ones are solved by conjugate gradients with the
/// bodies' diagonal blocks as the preconditioner, without assembling the matrix. Written here
/// rather than with Eigen's sparse solvers: at a pile's 75–150 unknowns their ordering and
/// symbolic pass at every sub-step took most of the run (measured), and the product over the
/// gaps is the one a split run will apply with messages between ranks.
template <int Rows, int Width>
class GapSystem {
public:
    using Side = Eigen::Matrix<double, Rows, Width>;
    using Block = Eigen::Matrix<double, Width, Width>;
    using Part = Eigen::Matrix<double, Width, 1>;

    explicit GapSystem(std::size_t bodies) : mass_(bodies, Part::Zero()) {}

    void clear() { terms_.clear(); }
    void set_mass(std::size_t body, const Part& mass) { mass_[body] = mass; }
    /// A gap's term w Jᵀ J; `first` or `second` none for a side without unknowns.
    void add(long first, const Side& on_first, long second, const Side& on_second, double weight)
    {
        terms_.push_back({first, second, on_first, on_second, weight});
    }

    [[nodiscard]] long size() const { return Width * static_cast<long>(mass_.size()); }

    /// The product of the system with `x`.
    [[nodiscard]] Eigen::VectorXd apply(const Eigen::VectorXd& x) const
    {
        Eigen::VectorXd y(size());
        for (std::size_t i = 0; i < mass_.size(); ++i) {
            y.segment<Width>(at(i)) = mass_[i].cwiseProduct(x.segment<Width>(at(i)));
        }
        for (const Term& t : terms_) {
            Eigen::Matrix<double, Rows, 1> jx = Eigen::Matrix<double, Rows, 1>::Zero();
            if (t.first != none) {
                jx += t.on_first * x.segment<Width>(Width * t.first);
            }
            if (t.second != none) {
                jx += t.on_second * x.segment<Width>(Width * t.second);
            }
            jx *= t.weight;
            if (t.first != none) {
                y.segment<Width>(Width * t.first) += t.on_first.transpose() * jx;
            }
            if (t.second != none) {
                y.segment<Width>(Width * t.second) += t.on_second.transpose() * jx;
            }
        }
        return y;
    }

    /// The solution for `right`, to `tolerance` of its norm when iterated; `is_met` false if
    /// the iteration stopped at its limit above that (a factorised solve meets it).
    [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& right, double tolerance,
                                        bool& is_met) const
    {
        if (size() <= largest_dense) {
            Eigen::VectorXd x = dense_solve(right);
            is_met = x.allFinite();
            return x;
        }
        return conjugate_gradients(right, tolerance, is_met);
    }

private:
    struct Term {
        long first;
        long second;
        Side on_first;
        Side on_second;
        double weight;
    };

    [[nodiscard]] static long at(std::size_t body) { return Width * static_cast<long>(body); }

    [[nodiscard]] Eigen::VectorXd dense_solve(const Eigen::VectorXd& right) const
    {
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(size(), size());
        for (std::size_t i = 0; i < mass_.size(); ++i) {
            dense.block<Width, Width>(at(i), at(i)).diagonal() = mass_[i];
        }
        for (const Term& t : terms_) {
            const std::array<long, 2> side{t.first, t.second};
            const std::array<const Side*, 2> jac{&t.on_first, &t.on_second};
            for (int a = 0; a < 2; ++a) {
                for (int b = 0; b < 2; ++b) {
                    if (side[a] != none && side[b] != none) {
                        dense.block<Width, Width>(Width * side[a], Width * side[b]) +=
                            t.weight * jac[a]->transpose() * *jac[b];
                    }
                }
            }
        }
        const Eigen::LDLT<Eigen::MatrixXd> factors(dense);
        if (factors.info() != Eigen::Success) {
            throw InternalError("joint film solve: a system that should be positive definite "
                                "did not factorise (a NaN in a body's state?)");
        }
        return factors.solve(right);
    }

    [[nodiscard]] Eigen::VectorXd conjugate_gradients(const Eigen::VectorXd& right,
                                                      double tolerance, bool& is_met) const
    {
        std::vector<Block> blocks(mass_.size());
        for (std::size_t i = 0; i < mass_.size(); ++i) {
            blocks[i] = mass_[i].asDiagonal();
        }
        for (const Term& t : terms_) {
            if (t.first != none) {
                blocks[static_cast<std::size_t>(t.first)] +=
                    t.weight * t.on_first.transpose() * t.on_first;
            }
            if (t.second != none) {
                blocks[static_cast<std::size_t>(t.second)] +=
                    t.weight * t.on_second.transpose() * t.on_second;
            }
        }
        std::vector<Eigen::LDLT<Block>> inverse;
        inverse.reserve(blocks.size());
        for (const Block& b : blocks) {
            inverse.emplace_back(b);
        }
        const auto precondition = [&](const Eigen::VectorXd& r) {
            Eigen::VectorXd z(size());
            for (std::size_t i = 0; i < inverse.size(); ++i) {
                z.segment<Width>(at(i)) = inverse[i].solve(Part(r.segment<Width>(at(i))));
            }
            return z;
        };
        Eigen::VectorXd x = Eigen::VectorXd::Zero(size());
        const double goal = tolerance * right.norm();
        is_met = std::isfinite(goal);
        if (goal == 0.0 || !is_met) {
            return x;
        }
        Eigen::VectorXd r = right;
        Eigen::VectorXd z = precondition(r);
        Eigen::VectorXd p = z;
        double rz = r.dot(z);
        // A safeguard only: in exact arithmetic CG ends within size() iterations; this leaves
        // room for round-off and returns the best iterate if the goal is never met.
        const long limit = 10 * size() + 100;
        for (long i = 0; i < limit && r.norm() > goal; ++i) {
            const Eigen::VectorXd q = apply(p);
            const double alpha = rz / p.dot(q);
            x += alpha * p;
            r -= alpha * q;
            z = precondition(r);
            const double next = r.dot(z);
            p = z + (next / rz) * p;
            rz = next;
        }
        // Written so that a NaN counts as not met.
        is_met = r.norm() <= goal && x.allFinite();
        return x;
    }

    std::vector<Part> mass_;
    std::vector<Term> terms_;
};

/// The normal part of one component with two or more gaps: film_step's equation for all of
/// them at once (film_solve.hpp), by Newton's method with a line search on Φ. The unknowns are
/// the changes Δv of the component's bodies, `slot[b]` body b's index in the component.
template <int Dim>
class NormalFilms {
public:
    NormalFilms(std::span<const FilmBody<Dim>> bodies, std::span<const FilmGap<Dim>> gaps,
                const Component& component, std::span<const long> slot, double step,
                const LubricationSettings& settings)
        : bodies_(bodies), gaps_(gaps), component_(component), slot_(slot),
          size_(Dim * static_cast<long>(component.bodies.size())), step_(step), settings_(settings),
          system_(component.bodies.size())
    {
    }

    /// The changes Δv that solve it, to 1e-13 of `scale` (the largest |ḣ*| of its gaps).
    /// `is_met` false if Newton's iteration stopped at its limit before that.
    Eigen::VectorXd solve(double scale, int& iterations, bool& is_met)
    {
        is_met = false;
        Eigen::VectorXd dv = Eigen::VectorXd::Zero(size_);
        Eigen::VectorXd f = gradient(dv);
        for (iterations = 0; iterations < max_iterations;) {
            assemble_hessian(dv);
            // An inexact direction only slows the last iterations: each solves to 1e-12.
            bool is_direction_met = true; // an inexact direction is corrected by the next one
            const Eigen::VectorXd d = -system_.solve(f, 1e-12, is_direction_met);
            ++iterations;
            const double slope0 = d.dot(f);
            if (!(slope0 < 0.0)) {
                // no descent left: ∇Φ is zero to round-off (a NaN is not met)
                is_met = !std::isnan(slope0);
                break;
            }
            Eigen::VectorXd next = gradient(Eigen::VectorXd(dv + d));
            double alpha = 1.0;
            if (d.dot(next) > 0.25 * -slope0) {
                alpha = search(dv, d, slope0, d.dot(next));
                next = gradient(Eigen::VectorXd(dv + alpha * d));
            }
            dv += alpha * d;
            f = next;
            // The undamped step: a damped one may be short because the search stopped early.
            if (d.lpNorm<Eigen::Infinity>() <= tolerance * scale ||
                next_step_bound(f) <= tolerance * scale) {
                is_met = true;
                break;
            }
        }
        return dv;
    }

private:
    /// A safeguard: the problem is strictly convex and Newton with the line search converges
    /// in a few iterations (4 in the tests' non-linear column); the last iterate is kept.
    static constexpr int max_iterations = 100;
    static constexpr double tolerance = 1e-13;

    /// A bound on the largest entry of the next Newton step H⁻¹f without solving for it: H ≥ M,
    /// so |H⁻¹f|_M ≤ |f|_M⁻¹, and an entry is at most |·|_M over the root of the smallest mass.
    /// Where the films are weak it ends the iteration one solve early.
    [[nodiscard]] double next_step_bound(const Eigen::VectorXd& f) const
    {
        double sum = 0.0;
        double smallest = std::numeric_limits<double>::infinity();
        for (const std::size_t b : component_.bodies) {
            sum += f.segment<Dim>(slot_of(b)).squaredNorm() / bodies_[b].mass;
            smallest = std::min(smallest, bodies_[b].mass);
        }
        return std::sqrt(sum / smallest);
    }

    /// The first unknown of body b (none for a wall or a body that is not free).
    [[nodiscard]] long slot_of(std::size_t b) const
    {
        return is_wall<Dim>(b) || slot_[b] == none ? none : Dim * slot_[b];
    }

    /// The gap rate r_k of gap k at the change `dv`.
    [[nodiscard]] double rate(std::size_t k, const Eigen::VectorXd& dv) const
    {
        const FilmGap<Dim>& g = gaps_[k];
        double r = -g.geometry.overlap_rate;
        if (const long s = slot_of(g.second); s != none) {
            r += g.geometry.normal.dot(dv.segment<Dim>(s));
        }
        if (const long s = slot_of(g.first); s != none) {
            r -= g.geometry.normal.dot(dv.segment<Dim>(s));
        }
        return r;
    }

    /// ∇Φ at `dv`: M Δv + Σ_k B_kᵀ [G_k(h1) − G_k(h0)], the bracket the travel times the mean
    /// correction over it.
    [[nodiscard]] Eigen::VectorXd gradient(const Eigen::VectorXd& dv) const
    {
        Eigen::VectorXd f(size_);
        for (const std::size_t b : component_.bodies) {
            f.segment<Dim>(slot_of(b)) = bodies_[b].mass * dv.segment<Dim>(slot_of(b));
        }
        for (const std::size_t k : component_.gaps) {
            const FilmGap<Dim>& g = gaps_[k];
            const double h0 = gap_of(g);
            const double travel = step_ * rate(k, dv);
            const double change =
                travel * lubrication_correction_over<Dim>(h0, h0 + travel, g.first_radius,
                                                          g.second_radius, settings_, g.shell_gap)
                             .normal;
            if (const long s = slot_of(g.second); s != none) {
                f.segment<Dim>(s) += change * g.geometry.normal;
            }
            if (const long s = slot_of(g.first); s != none) {
                f.segment<Dim>(s) -= change * g.geometry.normal;
            }
        }
        return f;
    }

    /// ∇²Φ at `dv`: M + Σ_k Δt c_corr,k(h1) B_kᵀ B_k.
    void assemble_hessian(const Eigen::VectorXd& dv)
    {
        system_.clear();
        for (const std::size_t b : component_.bodies) {
            system_.set_mass(static_cast<std::size_t>(slot_[b]),
                             Eigen::Matrix<double, Dim, 1>::Constant(bodies_[b].mass));
        }
        for (const std::size_t k : component_.gaps) {
            const FilmGap<Dim>& g = gaps_[k];
            const double h1 = gap_of(g) + step_ * rate(k, dv);
            const double c =
                step_ * lubrication_correction<Dim>(h1, g.first_radius, g.second_radius, settings_,
                                                    g.shell_gap)
                            .normal;
            const Eigen::Matrix<double, 1, Dim> row = g.geometry.normal.transpose();
            system_.add(local(g.first), -row, local(g.second), row, c);
        }
    }

    [[nodiscard]] long local(std::size_t b) const { return is_wall<Dim>(b) ? none : slot_[b]; }

    /// The step α along `d`: 1 unless Φ's slope there is above a quarter of |its slope at 0|
    /// (the curvature condition); else the slope's root, bracketed in (0, 1) because Φ is
    /// convex, to that tolerance (regula falsi, Illinois variant).
    [[nodiscard]] double search(const Eigen::VectorXd& dv, const Eigen::VectorXd& d, double slope0,
                                double slope1) const
    {
        const auto slope = [&](double alpha) {
            return d.dot(gradient(Eigen::VectorXd(dv + alpha * d)));
        };
        double hi = 1.0;
        double slope_hi = slope1;
        double lo = 0.0;
        double slope_lo = slope0;
        double alpha = 1.0;
        int side = 0;
        for (int i = 0; i < 60; ++i) { // a safeguard: the bracket shrinks every iteration
            alpha = (lo * slope_hi - hi * slope_lo) / (slope_hi - slope_lo);
            const double s = slope(alpha);
            if (std::abs(s) <= 0.25 * -slope0) {
                return alpha;
            }
            if (s < 0.0) {
                lo = alpha;
                slope_lo = s;
                if (side == -1) {
                    slope_hi *= 0.5;
                }
                side = -1;
            } else {
                hi = alpha;
                slope_hi = s;
                if (side == 1) {
                    slope_lo *= 0.5;
                }
                side = 1;
            }
        }
        return alpha;
    }

    std::span<const FilmBody<Dim>> bodies_;
    std::span<const FilmGap<Dim>> gaps_;
    const Component& component_;
    std::span<const long> slot_;
    long size_;
    double step_;
    const LubricationSettings& settings_;
    GapSystem<1, Dim> system_;
};

/// The columns of ω ↦ ω × l (Dim × angular_size).
template <int Dim>
Eigen::Matrix<double, Dim, angular_size<Dim>> turning(const Vec<Dim>& lever)
{
    Eigen::Matrix<double, Dim, angular_size<Dim>> x;
    if constexpr (Dim == 2) {
        x.col(0) = cross(1.0, lever);
    } else {
        for (int a = 0; a < 3; ++a) {
            x.col(a) = cross(Vec<3>(Vec<3>::Unit(a)), lever);
        }
    }
    return x;
}

/// The angular velocity stored at `at` of `w`.
template <int Dim>
AngularVec<Dim> angular_of(const Eigen::VectorXd& w, long at)
{
    if constexpr (Dim == 2) {
        return w[at];
    } else {
        return w.segment<3>(at);
    }
}

/// One gap alone (no other gap shares a free body with it): the sweep's step (lone_film_impulse).
template <int Dim>
void single_gap(std::span<const FilmBody<Dim>> bodies, const FilmGap<Dim>& g, double step,
                const LubricationSettings& settings, Vec<Dim>& on_second, JointFilms<Dim>& out)
{
    const auto body = [&](std::size_t b) { return is_wall<Dim>(b) ? nullptr : &bodies[b]; };
    const std::optional<Vec<Dim>> impulse =
        lone_film_impulse<Dim>(g, body(g.first), body(g.second), step, settings);
    if (!impulse) {
        return;
    }
    on_second = *impulse;
    const auto push = [&](std::size_t b, const Vec<Dim>& on_body, const Vec<Dim>& lever) {
        if (!is_wall<Dim>(b) && bodies[b].is_free) {
            out.velocity_change[b] += on_body / bodies[b].mass;
            out.omega_change[b] += cross(lever, on_body) / bodies[b].inertia;
        }
    };
    push(g.first, Vec<Dim>(-on_second), g.geometry.lever_first);
    push(g.second, on_second, g.geometry.lever_second);
}

/// The tangential part of a component with two or more gaps: backward Euler on every gap's
/// slip at once, with the mean resistances c̄_t and the slips after the normal impulses
/// (`slip`, one per gap of the component). Adds each gap's tangential impulse to `on_second` and
/// the bodies' changes to `out`.
template <int Dim>
void tangential_films(std::span<const FilmBody<Dim>> bodies, std::span<const FilmGap<Dim>> gaps,
                      const Component& component, std::span<const long> slot,
                      std::span<const double> resistance, std::span<const Vec<Dim>> slip,
                      double step, JointFilms<Dim>& out)
{
    constexpr int width = Dim + angular_size<Dim>;
    using Jacobian = Eigen::Matrix<double, Dim, width>;
    const long size = width * static_cast<long>(component.bodies.size());
    const auto local = [&](std::size_t b) { return is_wall<Dim>(b) ? none : slot[b]; };
    const auto slot_of = [&](std::size_t b) { return local(b) == none ? none : width * local(b); };
    // C_k's block of one side: ± P [1 | ω ↦ ω × l].
    const auto jacobian = [](const Vec<Dim>& normal, const Vec<Dim>& lever, double sign) {
        const Matrix<Dim> p = Matrix<Dim>::Identity() - normal * normal.transpose();
        Jacobian c;
        c.template leftCols<Dim>() = sign * p;
        c.template rightCols<angular_size<Dim>>() = sign * p * turning<Dim>(lever);
        return c;
    };
    GapSystem<Dim, width> system(component.bodies.size());
    Eigen::VectorXd right = Eigen::VectorXd::Zero(size);
    for (const std::size_t b : component.bodies) {
        Eigen::Matrix<double, width, 1> mass;
        mass.template head<Dim>().setConstant(bodies[b].mass);
        mass.template tail<angular_size<Dim>>().setConstant(bodies[b].inertia);
        system.set_mass(static_cast<std::size_t>(slot[b]), mass);
    }
    for (std::size_t i = 0; i < component.gaps.size(); ++i) {
        const FilmGap<Dim>& g = gaps[component.gaps[i]];
        const double c = step * resistance[i];
        const Jacobian first = jacobian(g.geometry.normal, g.geometry.lever_first, -1.0);
        const Jacobian second = jacobian(g.geometry.normal, g.geometry.lever_second, 1.0);
        if (const long s = slot_of(g.first); s != none) {
            right.segment<width>(s) -= c * first.transpose() * slip[i];
        }
        if (const long s = slot_of(g.second); s != none) {
            right.segment<width>(s) -= c * second.transpose() * slip[i];
        }
        system.add(local(g.first), first, local(g.second), second, c);
    }
    // Linear and solved once (no Newton to absorb an inexact solve): tighter than the normal
    // part's 1e-12 directions.
    bool is_met = true;
    const Eigen::VectorXd dw = system.solve(right, 1e-13, is_met);
    out.n_unfinished += is_met ? 0 : 1;
    for (std::size_t i = 0; i < component.gaps.size(); ++i) {
        const std::size_t k = component.gaps[i];
        const FilmGap<Dim>& g = gaps[k];
        Vec<Dim> after = slip[i];
        if (const long s = slot_of(g.first); s != none) {
            after +=
                jacobian(g.geometry.normal, g.geometry.lever_first, -1.0) * dw.segment<width>(s);
        }
        if (const long s = slot_of(g.second); s != none) {
            after +=
                jacobian(g.geometry.normal, g.geometry.lever_second, 1.0) * dw.segment<width>(s);
        }
        out.on_second[k] += -step * resistance[i] * after;
    }
    for (const std::size_t b : component.bodies) {
        out.velocity_change[b] += dw.segment<Dim>(slot_of(b));
        out.omega_change[b] += angular_of<Dim>(dw, slot_of(b) + Dim);
    }
}

/// A component of two or more gaps: the normal Newton solve, then the slips.
template <int Dim>
void joint_gaps(std::span<const FilmBody<Dim>> bodies, std::span<const FilmGap<Dim>> gaps,
                const Component& component, double step, const LubricationSettings& settings,
                std::vector<long>& slot, JointFilms<Dim>& out)
{
    for (std::size_t i = 0; i < component.bodies.size(); ++i) {
        slot[component.bodies[i]] = static_cast<long>(i);
    }
    double scale = 0.0;
    for (const std::size_t k : component.gaps) {
        scale = std::max(scale, std::abs(gaps[k].geometry.overlap_rate));
    }
    NormalFilms<Dim> normal(bodies, gaps, component, slot, step, settings);
    int iterations = 0;
    bool is_met = true;
    const Eigen::VectorXd dv = scale > 0.0 ? normal.solve(scale, iterations, is_met)
                                           : Eigen::VectorXd(Eigen::VectorXd::Zero(
                                                 Dim * static_cast<long>(component.bodies.size())));
    out.n_newton_iterations += iterations;
    out.n_unfinished += is_met ? 0 : 1;
    const auto moved = [&](std::size_t b) {
        return is_wall<Dim>(b) || slot[b] == none ? Vec<Dim>(Vec<Dim>::Zero())
                                                  : Vec<Dim>(dv.segment<Dim>(Dim * slot[b]));
    };
    std::vector<double> resistance(component.gaps.size());
    std::vector<Vec<Dim>> slip(component.gaps.size());
    for (std::size_t i = 0; i < component.gaps.size(); ++i) {
        const std::size_t k = component.gaps[i];
        const FilmGap<Dim>& g = gaps[k];
        const Vec<Dim> relative = moved(g.second) - moved(g.first);
        const double h0 = gap_of(g);
        const double travel = step * (-g.geometry.overlap_rate + g.geometry.normal.dot(relative));
        const LubricationResistance mean = lubrication_correction_over<Dim>(
            h0, h0 + travel, g.first_radius, g.second_radius, settings, g.shell_gap);
        // J_k = G(h0) − G(h1) on the second body along n (film_step's impulse).
        out.on_second[k] = -travel * mean.normal * g.geometry.normal;
        resistance[i] = mean.tangential;
        // The normal impulses move the bodies along the other gaps' normals, and so the slip.
        const Matrix<Dim> p =
            Matrix<Dim>::Identity() - g.geometry.normal * g.geometry.normal.transpose();
        slip[i] = g.geometry.slip_velocity + p * relative;
    }
    for (const std::size_t b : component.bodies) {
        out.velocity_change[b] += moved(b);
    }
    tangential_films<Dim>(bodies, gaps, component, slot, resistance, slip, step, out);
    for (const std::size_t b : component.bodies) {
        slot[b] = none;
    }
}

} // namespace

template <int Dim>
std::optional<Vec<Dim>> lone_film_impulse(const FilmGap<Dim>& gap, const FilmBody<Dim>* first,
                                          const FilmBody<Dim>* second, double step,
                                          const LubricationSettings& settings)
{
    const ContactGeometry<Dim>& g = gap.geometry;
    const double h0 = gap_of(gap);
    const double rate = -g.overlap_rate; // ḣ = v·n, < 0 approaching
    if (h0 >= settings.range && h0 + step * rate >= settings.range) {
        return std::nullopt; // out of the range now and after the drift
    }
    const auto inverse = [](const FilmBody<Dim>* b, bool is_mass) {
        return b != nullptr && b->is_free ? 1.0 / (is_mass ? b->mass : b->inertia) : 0.0;
    };
    const double mass_sum = inverse(first, true) + inverse(second, true);
    const double turn_sum = g.lever_first.squaredNorm() * inverse(first, false) +
                            g.lever_second.squaredNorm() * inverse(second, false);
    const FilmStep film = film_step<Dim>(h0, rate, mass_sum, step, gap.first_radius,
                                         gap.second_radius, settings, gap.shell_gap);
    if (film.normal_impulse == 0.0 && film.tangential == 0.0) {
        return std::nullopt;
    }
    return Vec<Dim>(film.normal_impulse * g.normal +
                    damping_impulse(1.0, film.tangential, mass_sum + turn_sum, step) *
                        g.slip_velocity);
}

template <int Dim>
JointFilms<Dim> joint_film_impulses(std::span<const FilmBody<Dim>> bodies,
                                    std::span<const FilmGap<Dim>> gaps, double step,
                                    const LubricationSettings& settings)
{
    JointFilms<Dim> out;
    std::vector<char> is_active(gaps.size(), 0);
    std::vector<std::size_t> active;
    for (std::size_t k = 0; k < gaps.size(); ++k) {
        if (acts(gaps[k], -gaps[k].geometry.overlap_rate, step, settings)) {
            is_active[k] = 1;
            active.push_back(k);
        }
    }
    std::vector<long> slot(bodies.size(), none);
    // Solved again with the gaps the films' velocities newly reach, until there are none.
    for (;;) {
        out.on_second.assign(gaps.size(), Vec<Dim>::Zero());
        out.velocity_change.assign(bodies.size(), Vec<Dim>::Zero());
        out.omega_change.assign(bodies.size(), zero_angular<Dim>());
        out.n_newton_iterations = 0;
        out.n_unfinished = 0;
        for (const Component& c : components_of<Dim>(bodies, gaps, active)) {
            if (c.gaps.size() == 1) {
                single_gap<Dim>(bodies, gaps[c.gaps[0]], step, settings, out.on_second[c.gaps[0]],
                                out);
            } else {
                joint_gaps<Dim>(bodies, gaps, c, step, settings, slot, out);
            }
        }
        bool is_widened = false;
        for (std::size_t k = 0; k < gaps.size(); ++k) {
            const FilmGap<Dim>& g = gaps[k];
            if (is_active[k] != 0) {
                continue;
            }
            double rate = -g.geometry.overlap_rate;
            if (!is_wall<Dim>(g.second)) {
                rate += g.geometry.normal.dot(out.velocity_change[g.second]);
            }
            rate -= g.geometry.normal.dot(out.velocity_change[g.first]);
            if (acts(g, rate, step, settings)) {
                is_active[k] = 1;
                is_widened = true;
            }
        }
        if (!is_widened) {
            return out;
        }
        active.clear();
        for (std::size_t k = 0; k < gaps.size(); ++k) {
            if (is_active[k] != 0) {
                active.push_back(k);
            }
        }
    }
}

template std::optional<Vec<2>> lone_film_impulse<2>(const FilmGap<2>&, const FilmBody<2>*,
                                                    const FilmBody<2>*, double,
                                                    const LubricationSettings&);
template std::optional<Vec<3>> lone_film_impulse<3>(const FilmGap<3>&, const FilmBody<3>*,
                                                    const FilmBody<3>*, double,
                                                    const LubricationSettings&);
template JointFilms<2> joint_film_impulses<2>(std::span<const FilmBody<2>>,
                                              std::span<const FilmGap<2>>, double,
                                              const LubricationSettings&);
template JointFilms<3> joint_film_impulses<3>(std::span<const FilmBody<3>>,
                                              std::span<const FilmGap<3>>, double,
                                              const LubricationSettings&);

} // namespace fddem
