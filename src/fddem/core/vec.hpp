// SPDX-License-Identifier: MIT
#pragma once
/// Small fixed-size vectors typed by dimension (STYLE.md §4).

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <cmath>
#include <span>
#include <vector>

namespace fddem {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

/// A Dim × Dim matrix (a resistance tensor).
template <int Dim>
using Matrix = Eigen::Matrix<double, Dim, Dim>;

/// The values of a list of small vectors (λ or I(u) on the markers) as one span of doubles, for
/// the mixing of the outer iterate and the sums over MPI ranks: a Vec<Dim> is Dim contiguous
/// doubles.
template <int Dim>
[[nodiscard]] std::span<double> flat_values(std::vector<Vec<Dim>>& values)
{
    static_assert(sizeof(Vec<Dim>) == Dim * sizeof(double));
    return values.empty() ? std::span<double>()
                          : std::span<double>(values.front().data(), Dim * values.size());
}

/// Angular velocity and torque: a scalar about z in 2D, a vector in 3D.
template <int Dim>
struct Angular;
template <>
struct Angular<2> {
    using type = double;
};
template <>
struct Angular<3> {
    using type = Vec<3>;
};
template <int Dim>
using AngularVec = typename Angular<Dim>::type;

/// A zero angular quantity (Eigen leaves a default-constructed vector uninitialised).
template <int Dim>
[[nodiscard]] AngularVec<Dim> zero_angular()
{
    if constexpr (Dim == 2) {
        return 0.0;
    } else {
        return Vec<3>::Zero();
    }
}

/// |ω|: the magnitude of an angular quantity in either dimension.
template <int Dim>
[[nodiscard]] double magnitude(const AngularVec<Dim>& omega)
{
    if constexpr (Dim == 2) {
        return std::abs(omega);
    } else {
        return omega.norm();
    }
}

/// ω × r for a scalar ω about z (2D).
inline Vec<2> cross(double omega, const Vec<2>& r)
{
    return {-omega * r.y(), omega * r.x()};
}
inline Vec<3> cross(const Vec<3>& omega, const Vec<3>& r)
{
    return omega.cross(r);
}

/// r × f in 2D: its z-component (in 3D the same call is cross(Vec<3>, Vec<3>) above).
inline double cross(const Vec<2>& r, const Vec<2>& f)
{
    return r.x() * f.y() - r.y() * f.x();
}

} // namespace fddem
