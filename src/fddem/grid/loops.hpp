// SPDX-License-Identifier: MIT
#pragma once
/// Loops over boxes of indices: the only place with OpenMP pragmas for field loops
/// (STYLE.md §13). Every loop runs over a box the caller passes (the owned part of the grid),
/// and every reduction over the grid ends in the Communicator the caller passes (one process:
/// the identity; several: an MPI_Allreduce of the per-process results).

#include "fddem/core/index.hpp"
#include "fddem/grid/communicator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

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
/// (the slices across the outermost axis, Dim − 1). Pass q visits plane k at front t = k + q,
/// and within a front the passes go in order. So pass q meets plane k after pass q − 1 has
/// been over planes k and k + 1, and before pass q + 1 comes to plane k − 1. A pass whose
/// stencil reads its own plane and the two beside it therefore reads what the passes run one
/// after the other would give, bit for bit, while the few planes between the first pass and
/// the last stay in cache. f(q, row_start) is called for each row of a plane, the rows of one
/// front's planes in parallel (so f must not write where another row of the same pass reads);
/// then, unless `plane_done` is nullptr, plane_done(q, plane) for each of them, on one thread,
/// before the next pass comes to the plane. (Blocks of 2–8 planes per pass, which meet the
/// threads less often, were measured slower: ten Cate E4 at d/h 15.75 on two threads, momentum
/// +17–37 %.)
///
/// With `from_the_middle`, the wavefront starts at the middle plane and runs to both ends at
/// once (the lower half downwards, the same rule mirrored; a half with one plane more than the
/// other starts one front earlier), so that every pass reaches the first and the last plane at
/// the same front. Then, unless `at_the_ends` is nullptr, at_the_ends(q) runs on the main thread
/// once pass q has been over both end planes and before pass q + 1 comes to them: the place to
/// exchange the end planes with whatever lies beyond them (another rank's block, or the other
/// end across a periodic side), which then enter the next pass as the planes beside the ends.
template <int Dim, class F, class G, class H>
void for_each_plane_wavefront(const Box<Dim>& box, int stages, bool from_the_middle, F&& f,
                              G&& plane_done, H&& at_the_ends)
{
    constexpr auto outer = static_cast<std::size_t>(Dim - 1);
    const int first = box.lo[outer];
    const int planes = box.hi[outer] - first;
    if (box.size() == 0 || stages <= 0) {
        if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<H>>) {
            for (int q = 0; q < stages; ++q) {
                at_the_ends(q); // the others' exchanges wait for this one's
            }
        }
        return;
    }
    // The halves [first, centre) (downwards) and [centre, hi) (upwards), and the front at which
    // each starts its first plane.
    const int down = from_the_middle ? planes / 2 : 0;
    const int up = planes - down;
    const int centre = first + down;
    const int up_start = 0;
    const int down_start = up > down ? 1 : 0;
    const int last_front = std::max(up - 1 + up_start, down - 1 + down_start) + stages - 1;
    const int ends_front = std::max(up - 1 + up_start, down - 1 + down_start); // pass 0's
    Box<Dim> rows = box;
    rows.hi[0] = rows.lo[0] + 1;
    const int rows_per_plane = static_cast<int>(rows.size()) / planes;
    [[maybe_unused]] const bool is_threaded = box.size() >= min_points_for_threads;
#pragma omp parallel if (is_threaded)
    for (int front = 0; front <= last_front; ++front) {
        for (int q = 0; q < stages; ++q) {
            std::array<int, 2> visited{};
            int n_visited = 0;
            const int up_plane = centre + front - q - up_start;
            if (up_plane >= centre && up_plane < box.hi[outer]) {
                visited[static_cast<std::size_t>(n_visited++)] = up_plane;
            }
            const int down_plane = centre - 1 - (front - q - down_start);
            if (down_plane >= first && down_plane < centre) {
                visited[static_cast<std::size_t>(n_visited++)] = down_plane;
            }
            if (n_visited == 0) {
                continue;
            }
#pragma omp for schedule(static)
            for (int r = 0; r < n_visited * rows_per_plane; ++r) {
                Index<Dim> row = rows.lo;
                row[outer] = visited[static_cast<std::size_t>(r / rows_per_plane)];
                if constexpr (Dim == 3) {
                    row[1] = rows.lo[1] + r % rows_per_plane;
                }
                f(q, row);
            }
            if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<G>>) {
#pragma omp single
                for (int v = 0; v < n_visited; ++v) {
                    plane_done(q, visited[static_cast<std::size_t>(v)]);
                }
            }
        }
        if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<H>>) {
            const int q = front - ends_front;
            if (q >= 0 && q < stages) {
                // On the main thread (MPI_THREAD_FUNNELED: it may send messages), the others
                // waiting.
#pragma omp masked
                at_the_ends(q);
#pragma omp barrier
            }
        }
    }
}

/// Whether for_each_plane_wavefront pays over `box` with the threads at hand: on one thread
/// always (it only reorders the work), on several only where a slice has at least
/// min_points_for_threads points, since every pass over every slice costs the threads a
/// meeting. (Measured on two threads: ten Cate E4 at d/h 15.75, slices of 105 × 105 faces,
/// momentum 4.92 s against 8.12 s colour by colour; a sphere in a 96 × 48 × 48 box, slices of
/// 96 × 48, 1.61 s against 1.34 s; on one thread that box gains, 1.95–2.02 s against 2.16 s.)
template <int Dim>
[[nodiscard]] bool wavefront_pays(const Box<Dim>& box)
{
#ifdef _OPENMP
    const int outer = box.extent(Dim - 1);
    if (omp_get_max_threads() > 1 && outer > 0 &&
        box.size() / static_cast<std::size_t>(outer) < min_points_for_threads) {
        return false;
    }
#endif
    return box.size() > 0;
}

/// The wavefront from the first plane to the last (no exchange at the ends).
template <int Dim, class F, class G>
void for_each_plane_wavefront(const Box<Dim>& box, int stages, F&& f, G&& plane_done)
{
    for_each_plane_wavefront(box, stages, false, std::forward<F>(f), std::forward<G>(plane_done),
                             nullptr);
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
