// SPDX-License-Identifier: MIT
#pragma once
/// Moments of inertia as eq. (14) uses them: a number in 2D (about z), a 3 × 3 tensor in 3D,
/// so that the update takes the tensor J of the paper's eq. (14) with its gyroscopic term
/// ω × (J·ω). A ball's tensor is isotropic; the interface is the general one for later shapes.

#include "fddem/bodies/orientation.hpp"
#include "fddem/core/vec.hpp"

#include <span>

namespace fddem {

template <int Dim>
struct InertiaOf;
template <>
struct InertiaOf<2> {
    using type = double;
};
template <>
struct InertiaOf<3> {
    using type = Eigen::Matrix3d;
};
/// J [kg·m²] (2D: per unit depth), or a geometric second moment [m⁵] (2D: m⁴).
template <int Dim>
using Inertia = typename InertiaOf<Dim>::type;

/// The isotropic tensor with `moment` about every axis through the centre.
template <int Dim>
[[nodiscard]] Inertia<Dim> isotropic_inertia(double moment)
{
    if constexpr (Dim == 2) {
        return moment;
    } else {
        return moment * Eigen::Matrix3d::Identity();
    }
}

/// J·ω.
template <int Dim>
[[nodiscard]] AngularVec<Dim> apply(const Inertia<Dim>& inertia, const AngularVec<Dim>& omega)
{
    return inertia * omega;
}

/// ω with J·ω = `moment`; J is symmetric positive definite.
template <int Dim>
[[nodiscard]] AngularVec<Dim> solve(const Inertia<Dim>& inertia, const AngularVec<Dim>& moment)
{
    if constexpr (Dim == 2) {
        return moment / inertia;
    } else {
        return inertia.ldlt().solve(moment);
    }
}

/// ω × (J·ω), eq. (14)'s gyroscopic term: zero in 2D, and for an isotropic J.
template <int Dim>
[[nodiscard]] AngularVec<Dim> gyroscopic(const Inertia<Dim>& inertia, const AngularVec<Dim>& omega)
{
    if constexpr (Dim == 2) {
        return 0.0;
    } else {
        return omega.cross(inertia * omega);
    }
}

/// A body-frame tensor in the world frame: R J Rᵀ.
template <int Dim>
[[nodiscard]] Inertia<Dim> inertia_in_world(const Orientation<Dim>& orientation,
                                            const Inertia<Dim>& body)
{
    if constexpr (Dim == 2) {
        return body;
    } else {
        const Eigen::Matrix3d r = orientation.toRotationMatrix();
        return r * body * r.transpose();
    }
}

/// Σ_l ΔV_l (|r_l|² 1 − r_l r_lᵀ) over a set of points (2D: Σ ΔV_l |r_l|², about z): the
/// geometric second-moment tensor of the volume the points represent, in the frame of the
/// offsets.
template <int Dim>
[[nodiscard]] Inertia<Dim> second_moment_tensor(std::span<const Vec<Dim>> offsets,
                                                std::span<const double> volumes)
{
    Inertia<Dim> sum = isotropic_inertia<Dim>(0.0);
    for (std::size_t l = 0; l < offsets.size(); ++l) {
        if constexpr (Dim == 2) {
            sum += volumes[l] * offsets[l].squaredNorm();
        } else {
            sum += volumes[l] * (offsets[l].squaredNorm() * Eigen::Matrix3d::Identity() -
                                 offsets[l] * offsets[l].transpose());
        }
    }
    return sum;
}

} // namespace fddem
