// SPDX-License-Identifier: MIT
#pragma once
/// Loops over boxes of indices: the only place with OpenMP pragmas for field loops
/// (STYLE.md §13). Every loop runs over a box the caller passes (the owned part of the grid),
/// and every reduction over the grid ends in the Communicator the caller passes (one process:
/// the identity; several: an MPI_Allreduce of the per-process results).

#include "fddem/core/index.hpp"
#include "fddem/grid/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace fddem {

/// Below this many points a loop runs on one thread: the fork/join would cost more. (The
/// `is_threaded` flags below are read only by OpenMP pragmas, hence [[maybe_unused]] for builds
/// without OpenMP.)
inline constexpr std::size_t min_points_for_threads = 8192;

/// Calls f(index) for every index in `box`, in parallel over the outermost axis.
/// `f` must not write to any location another index writes. `points_per_index` is the work
/// one call does, in grid points (it decides whether threads pay off).
template <int Dim, class F>
void for_each_index(const Box<Dim>& box, F&& f, std::size_t points_per_index = 1)
{
    static_assert(Dim == 2 || Dim == 3, "fddem grids are 2D or 3D");
    [[maybe_unused]] const bool is_threaded =
        box.size() * points_per_index >= min_points_for_threads;
    if constexpr (Dim == 2) {
#pragma omp parallel for schedule(static) if (is_threaded)
        for (int j = box.lo[1]; j < box.hi[1]; ++j) {
            for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                f(Index<2>{i, j});
            }
        }
    } else {
#pragma omp parallel for schedule(static) if (is_threaded)
        for (int k = box.lo[2]; k < box.hi[2]; ++k) {
            for (int j = box.lo[1]; j < box.hi[1]; ++j) {
                for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                    f(Index<3>{i, j, k});
                }
            }
        }
    }
}

/// Calls f(row_start) once per row of `box` along axis 0 (row_start has axis 0 = box.lo[0]);
/// `f` loops over the row itself, so inner loops see unit stride. Rows run in parallel.
template <int Dim, class F>
void for_each_row(const Box<Dim>& box, F&& f)
{
    Box<Dim> rows = box;
    rows.hi[0] = rows.lo[0] + 1;
    for_each_index(rows, std::forward<F>(f), static_cast<std::size_t>(box.extent(0)));
}

/// Runs `stages` passes over the rows of `box` (along axis 0) as a wavefront over its planes
/// (the slices across the outermost axis, Dim − 1): pass q visits plane k at front t = k + q,
/// and within a front the passes go in order. So pass q meets plane k after pass q − 1 has
/// been over planes k and k + 1, and before pass q + 1 comes to plane k − 1. A pass whose
/// stencil reads its own plane and the two beside it therefore reads what the passes run one
/// after the other would give, bit for bit, while the few planes between the first pass and
/// the last stay in cache. f(q, row_start) is called for each row of a plane, the rows of one
/// plane in parallel (so f must not write where another row of the plane reads); then, unless
/// `plane_done` is nullptr, plane_done(q, plane) once, on one thread, before the next pass
/// comes to the plane. (Blocks of 2–8 planes per pass, which meet the threads less often,
/// were measured slower: ten Cate E4 at d/h 15.75 on two threads, momentum +17–37 %.)
template <int Dim, class F, class G>
void for_each_plane_wavefront(const Box<Dim>& box, int stages, F&& f, G&& plane_done)
{
    constexpr auto outer = static_cast<std::size_t>(Dim - 1);
    const int first = box.lo[outer];
    const int planes = box.hi[outer] - first;
    if (box.size() == 0 || stages <= 0) {
        return;
    }
    Box<Dim> rows = box;
    rows.hi[0] = rows.lo[0] + 1;
    const int rows_per_plane = static_cast<int>(rows.size()) / planes;
    [[maybe_unused]] const bool is_threaded = box.size() >= min_points_for_threads;
#pragma omp parallel if (is_threaded)
    for (int front = 0; front < planes + stages - 1; ++front) {
        for (int q = 0; q < stages; ++q) {
            const int plane = first + front - q;
            if (plane < first || plane >= box.hi[outer]) {
                continue;
            }
#pragma omp for schedule(static)
            for (int r = 0; r < rows_per_plane; ++r) {
                Index<Dim> row = rows.lo;
                row[outer] = plane;
                if constexpr (Dim == 3) {
                    row[1] = rows.lo[1] + r;
                }
                f(q, row);
            }
            if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<G>>) {
#pragma omp single
                plane_done(q, plane);
            }
        }
    }
}

/// Calls f(index) for every index of `box` serially, x fastest (file output order).
template <int Dim, class F>
void for_each_cell_in_vtk_order(const Box<Dim>& box, F&& f)
{
    if constexpr (Dim == 2) {
        for (int j = box.lo[1]; j < box.hi[1]; ++j) {
            for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                f(Index<2>{i, j});
            }
        }
    } else {
        for (int k = box.lo[2]; k < box.hi[2]; ++k) {
            for (int j = box.lo[1]; j < box.hi[1]; ++j) {
                for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                    f(Index<3>{i, j, k});
                }
            }
        }
    }
}

/// max(a, b) of values ≥ 0 that reads a NaN b as +∞. std::max(a, NaN) and OpenMP's max
/// reduction drop a NaN, and a blown-up residual would look converged.
[[nodiscard]] inline double max_keeping_nan(double a, double b) noexcept
{
    return std::isnan(b) ? std::numeric_limits<double>::infinity() : std::max(a, b);
}

/// Max over `box` (owned entries) of g(index) (g ≥ 0), over all processes of `comm`.
template <int Dim, class G>
[[nodiscard]] double max_over(const Communicator& comm, const Box<Dim>& box, G&& g)
{
    double result = 0.0;
    [[maybe_unused]] const bool is_threaded = box.size() >= min_points_for_threads;
    if constexpr (Dim == 2) {
#pragma omp parallel for schedule(static) reduction(max : result) if (is_threaded)
        for (int j = box.lo[1]; j < box.hi[1]; ++j) {
            for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                result = max_keeping_nan(result, g(Index<2>{i, j}));
            }
        }
    } else {
#pragma omp parallel for schedule(static) reduction(max : result) if (is_threaded)
        for (int k = box.lo[2]; k < box.hi[2]; ++k) {
            for (int j = box.lo[1]; j < box.hi[1]; ++j) {
                for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                    result = max_keeping_nan(result, g(Index<3>{i, j, k}));
                }
            }
        }
    }
    return comm.max(result);
}

/// Max over the rows of `box` (along axis 0) of g(row_start) (g ≥ 0), rows in parallel, over
/// all processes of `comm`.
template <int Dim, class G>
[[nodiscard]] double max_over_rows(const Communicator& comm, const Box<Dim>& box, G&& g)
{
    Box<Dim> rows = box;
    rows.hi[0] = rows.lo[0] + 1;
    double result = 0.0;
    [[maybe_unused]] const bool is_threaded = box.size() >= min_points_for_threads;
    if constexpr (Dim == 2) {
#pragma omp parallel for schedule(static) reduction(max : result) if (is_threaded)
        for (int j = rows.lo[1]; j < rows.hi[1]; ++j) {
            result = max_keeping_nan(result, g(Index<2>{rows.lo[0], j}));
        }
    } else {
#pragma omp parallel for schedule(static) reduction(max : result) if (is_threaded)
        for (int k = rows.lo[2]; k < rows.hi[2]; ++k) {
            for (int j = rows.lo[1]; j < rows.hi[1]; ++j) {
                result = max_keeping_nan(result, g(Index<3>{rows.lo[0], j, k}));
            }
        }
    }
    return comm.max(result);
}

/// Sum over `box` (owned entries) of g(index), over all processes of `comm`. Partial sums are
/// taken per outermost-axis slab and added in slab order, so the result is bit-identical for
/// any thread count (issue 5: identical reruns).
template <int Dim, class G>
[[nodiscard]] double sum_over(const Communicator& comm, const Box<Dim>& box, G&& g)
{
    const int outer = Dim - 1;
    const int n_slabs = std::max(box.extent(outer), 0);
    std::vector<double> partial(static_cast<std::size_t>(n_slabs), 0.0);
    [[maybe_unused]] const bool is_threaded = box.size() >= min_points_for_threads;
#pragma omp parallel for schedule(static) if (is_threaded)
    for (int s = 0; s < n_slabs; ++s) {
        Box<Dim> slab = box;
        slab.lo[static_cast<std::size_t>(outer)] = box.lo[static_cast<std::size_t>(outer)] + s;
        slab.hi[static_cast<std::size_t>(outer)] = slab.lo[static_cast<std::size_t>(outer)] + 1;
        double acc = 0.0;
        if constexpr (Dim == 2) {
            const int j = slab.lo[1];
            for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                acc += g(Index<2>{i, j});
            }
        } else {
            const int k = slab.lo[2];
            for (int j = box.lo[1]; j < box.hi[1]; ++j) {
                for (int i = box.lo[0]; i < box.hi[0]; ++i) {
                    acc += g(Index<3>{i, j, k});
                }
            }
        }
        partial[static_cast<std::size_t>(s)] = acc;
    }
    double result = 0.0;
    for (const double p : partial) {
        result += p;
    }
    return comm.sum(result);
}

} // namespace fddem
