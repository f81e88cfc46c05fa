// SPDX-License-Identifier: MIT
#pragma once
/// The eigenvalues of the three-point second difference that the FFT Poisson solvers divide by
/// (linsolve/fft_poisson.hpp, linsolve/fft_mpi_poisson.hpp).

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fddem {

/// Eigenvalue of the 1-D three-point second difference for mode m of n cells of size h:
/// periodic (real Fourier, half-complex storage: modes m and n − m share a frequency)
/// λ = −(2 − 2 cos(2πk/n))/h², k = min(m, n − m); zero-gradient walls (DCT-II)
/// λ = −(2 − 2 cos(πm/n))/h².
[[nodiscard]] inline double laplacian_eigenvalue(int m, int n, double h, bool is_periodic)
{
    const double theta =
        is_periodic ? 2.0 * std::numbers::pi * std::min(m, n - m) / n : std::numbers::pi * m / n;
    return -(2.0 - 2.0 * std::cos(theta)) / (h * h);
}

} // namespace fddem
