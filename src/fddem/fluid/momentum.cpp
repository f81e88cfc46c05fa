// SPDX-License-Identifier: MIT
// Momentum equations (7)–(8), dimensional form, implicit Euler (or BDF2, time.scheme):
//   ρf ΔV (u_P − ũ_P^n)/Δt_e + Σ_faces F u_face = Σ_faces μ A ∂u/∂n − (p_P − p_W) ΔV/h + f ΔV,
// with Δt_e = Δt and ũ^n = u^n for Euler, and BDF2's leading coefficient folded into Δt_e and
// its u^{n−1} into ũ^n (core/time_scheme.hpp),
// where F = ρf A u_n is the mass flux through a face of the velocity control volume (taken
// from the latest outer iterate: Picard linearisation) and f the force per unit volume on the
// fluid (ρf λ* from the particles, plus any uniform body force). In Patankar's form:
//   a_P u_P = Σ a_nb u_nb − (p_P − p_W) ΔV/h + b,
//   a_nb = D + max(∓F, 0),  a_P = Σ a_nb + ρf ΔV/Δt_e + ΔF,  D = μ A/h,
// with the convection upwinded implicitly and corrected to central differences in b from the
// latest iterate (deferred correction), so that the converged answer is second order.
// Walls and inflows: the normal velocity on a boundary face is known (it enters as a fixed
// neighbour, and the mass fluxes through boundary faces come from it); a tangential neighbour
// across a wall or an inflow is the ghost value u_g = (8 u_w − 6 u_P + u_E)/3 (quadratic
// through the wall value), folded into the coefficients: a_P += 2 a_W, a_E += a_W/3,
// b += 8/3 a_W u_w, a_W = 0. Outflows: a neighbour across the outflow, or the outflow face
// itself for the normal component, equals u_P (zero gradient): a_P −= a_E, a_E = 0.

#include "fddem/fluid/momentum.hpp"

#include "fddem/grid/halo_exchange.hpp"
#include "fddem/grid/loops.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <type_traits>

namespace fddem {

namespace {

/// The assembly for one component; `axis` is a template parameter so that the branches on
/// it resolve at compile time and the row loop can vectorise.
template <int Dim, int axis>
double assemble_component(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                          const FluidProperties& fluid, const MomentumSettings& settings,
                          const TimeLevels& time, const FluidState<Dim>& state,
                          MomentumSystem<Dim>& system)
{
    const Box<Dim> box = unknown_faces(grid, bc, axis);
    const double volume = grid.cell_volume();
    const double rho = fluid.density;
    const double a_time = rho * volume / time.dt_effective;
    const double gamma = settings.convection == ConvectionScheme::central ? 1.0 : 0.0;
    const double* ua = state.u[axis].data();
    const double* ua_n = state.u_n[axis].data();
    // BDF2's u^{n−1}; none for Euler, whose ũ^n is u^n itself (bit for bit as before).
    const double* ua_nm1 = time.has_history() ? state.u_nm1[axis].data() : nullptr;
    const double history_weight = time.history_weight;
    const double* force = state.body_force[axis].data();
    const double* p = state.p.data();
    const std::ptrdiff_t s_axis = grid.stride(axis);
    const double pressure_factor = volume / grid.spacing(axis);

    struct AxisTerms {
        std::ptrdiff_t stride;
        double flux_factor; ///< ρf A / 2 [kg/(m·s)] per (m/s)
        double diffusion;   ///< μ A / h [kg/s]
        const double* u;    ///< the velocity component along this axis
        double wall_low;    ///< this component's wall velocity on the low side [m/s]
        double wall_high;
        bool is_bounded;        ///< not periodic
        BoundaryKind kind_low;  ///< the low side's kind (if bounded)
        BoundaryKind kind_high; ///< the high side's kind (if bounded)
        int n;
    };
    std::array<AxisTerms, Dim> terms{};
    for (int d = 0; d < Dim; ++d) {
        const double area = volume / grid.spacing(d);
        terms[static_cast<std::size_t>(d)] = {
            grid.stride(d),    0.5 * rho * area,    fluid.viscosity * area / grid.spacing(d),
            state.u[d].data(), bc.wall(d, 0)[axis], bc.wall(d, 1)[axis],
            !bc.periodic(d),   bc.side_kind(d, 0),  bc.side_kind(d, 1),
            grid.cells(d)};
    }
    double* a_p_out = system.a_p.data();
    double* b_out = system.b.data();
    double* u_old = system.u_old.data();
    std::array<double*, 2 * Dim> a_nb_out{};
    for (std::size_t k = 0; k < a_nb_out.size(); ++k) {
        a_nb_out[k] = system.a_nb[k].data();
    }

    // Which boundary treatment a face's low and high sides get along each axis. Along the row
    // axis (0) only the row's first and last faces have any, along the others the whole row
    // shares them: the row's interior runs one branch-free body, which vectorises.
    struct SideKinds {
        std::array<bool, Dim> wall_low{};
        std::array<bool, Dim> wall_high{};
        std::array<bool, Dim> open_low{};
        std::array<bool, Dim> open_high{};
    };
    const auto side_kinds = [&](const Index<Dim>& c) {
        SideKinds k;
        for (int d = 0; d < Dim; ++d) {
            const auto sd = static_cast<std::size_t>(d);
            const AxisTerms& t = terms[sd];
            // The neighbour across the low (high) side is outside the box: a wall ghost
            // (tangential components next to a wall or an inflow), or equal to u_P (next to an
            // outflow; for the normal component, the outflow face itself).
            const bool is_first = t.is_bounded && c[sd] == (d == axis ? 1 : 0);
            const bool is_last = t.is_bounded && c[sd] == t.n - 1;
            k.wall_low[sd] = d != axis && is_first && t.kind_low != BoundaryKind::outflow;
            k.wall_high[sd] = d != axis && is_last && t.kind_high != BoundaryKind::outflow;
            k.open_low[sd] = is_first && t.kind_low == BoundaryKind::outflow;
            k.open_high[sd] = is_last && t.kind_high == BoundaryKind::outflow;
        }
        return k;
    };
    // One face: its coefficients and source written, its residual |r|/a_P returned. With
    // `has_sides` false the boundary treatment is compiled out (a face with no side kinds).
    const auto assemble_face = [&](std::ptrdiff_t o, const SideKinds& k, auto has_sides) {
        double a_p = a_time;
        const double level =
            ua_nm1 == nullptr ? ua_n[o] : ua_n[o] + history_weight * (ua_n[o] - ua_nm1[o]);
        double b = a_time * level + force[o] * volume;
        double neighbours = 0.0; // Σ a_nb u_nb, for the residual
        for (int d = 0; d < Dim; ++d) {
            const auto sd = static_cast<std::size_t>(d);
            const AxisTerms& t = terms[sd];
            const std::ptrdiff_t s = t.stride;
            // Mass fluxes through the low and high faces of the velocity control volume:
            // along `axis` they sit at cell centres, across it at cell edges (on the
            // boundary, from the boundary faces' normal velocity: zero at a wall).
            double flux_low = 0.0;
            double flux_high = 0.0;
            if (d == axis) {
                flux_low = t.flux_factor * (ua[o - s] + ua[o]);
                flux_high = t.flux_factor * (ua[o] + ua[o + s]);
            } else {
                flux_low = t.flux_factor * (t.u[o] + t.u[o - s_axis]);
                flux_high = t.flux_factor * (t.u[o + s] + t.u[o + s - s_axis]);
            }
            double a_low = t.diffusion + std::max(flux_low, 0.0);
            double a_high = t.diffusion + std::max(-flux_high, 0.0);
            a_p += a_low + a_high + (flux_high - flux_low);

            // Deferred correction: central minus upwind face values, latest iterate.
            const double u_low = ua[o - s];
            const double u_high = ua[o + s];
            const double u_here = ua[o];
            const double high_correction =
                0.5 * (u_here + u_high) - (flux_high > 0.0 ? u_here : u_high);
            const double low_correction =
                0.5 * (u_low + u_here) - (flux_low > 0.0 ? u_low : u_here);
            b -= gamma * (flux_high * high_correction - flux_low * low_correction);

            if (!has_sides) {
                a_nb_out[2 * sd][o] = a_low;
                a_nb_out[2 * sd + 1][o] = a_high;
                neighbours += a_low * u_low + a_high * u_high;
                continue;
            }
            if (k.wall_low[sd]) {
                a_p += 2.0 * a_low;
                a_high += a_low / 3.0;
                b += 8.0 / 3.0 * a_low * t.wall_low;
                a_low = 0.0;
            }
            if (k.wall_high[sd]) {
                a_p += 2.0 * a_high;
                a_low += a_high / 3.0;
                b += 8.0 / 3.0 * a_high * t.wall_high;
                a_high = 0.0;
            }
            if (k.open_low[sd]) {
                a_p -= a_low;
                a_low = 0.0;
            }
            if (k.open_high[sd]) {
                a_p -= a_high;
                a_high = 0.0;
            }
            a_nb_out[2 * sd][o] = a_low;
            a_nb_out[2 * sd + 1][o] = a_high;
            neighbours += a_low * u_low + a_high * u_high;
        }
        a_p_out[o] = a_p;
        b_out[o] = b;
        u_old[o] = ua[o];
        const double residual =
            b - (p[o] - p[o - s_axis]) * pressure_factor + neighbours - a_p * ua[o];
        return std::abs(residual) / a_p;
    };

    return max_over_rows(grid.communicator(), box, [&](const Index<Dim>& row) {
        const std::ptrdiff_t row_offset = grid.offset(row) - box.lo[0];
        const int lo = box.lo[0];
        const int hi = box.hi[0];
        if (hi <= lo) {
            return 0.0; // no unknown face in this row
        }
        Index<Dim> c = row;
        double row_max = 0.0;
        // The two end faces, with whatever boundary treatment they have ...
        const auto end_face = [&](int i) {
            c[0] = i;
            row_max = max_keeping_nan(
                row_max, assemble_face(row_offset + i, side_kinds(c), std::true_type{}));
        };
        end_face(lo);
        if (hi - 1 > lo) {
            end_face(hi - 1);
        }
        // ... and the interior faces, which share the row's kinds (none along the row axis).
        c[0] = lo + 1;
        const SideKinds interior = side_kinds(c);
        const auto none = [](const std::array<bool, Dim>& flags) {
            return std::none_of(flags.begin(), flags.end(), [](bool f) { return f; });
        };
        if (none(interior.wall_low) && none(interior.wall_high) && none(interior.open_low) &&
            none(interior.open_high)) {
            for (int i = lo + 1; i < hi - 1; ++i) {
                row_max = max_keeping_nan(
                    row_max, assemble_face(row_offset + i, interior, std::false_type{}));
            }
        } else {
            for (int i = lo + 1; i < hi - 1; ++i) {
                row_max = max_keeping_nan(
                    row_max, assemble_face(row_offset + i, interior, std::true_type{}));
            }
        }
        return row_max;
    });
}

} // namespace

template <int Dim>
double assemble_momentum(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                         const FluidProperties& fluid, const MomentumSettings& settings,
                         const TimeLevels& time, const FluidState<Dim>& state, int axis,
                         MomentumSystem<Dim>& system)
{
    if (axis == 0) {
        return assemble_component<Dim, 0>(grid, bc, fluid, settings, time, state, system);
    }
    if constexpr (Dim == 3) {
        if (axis == 2) {
            return assemble_component<Dim, 2>(grid, bc, fluid, settings, time, state, system);
        }
    }
    return assemble_component<Dim, 1>(grid, bc, fluid, settings, time, state, system);
}

namespace {

/// The system of one component divided by a_P/α (MomentumSystem's scratch arrays): what a
/// sweep and the multigrid's residual read.
template <int Dim>
struct ScaledSystem {
    const double* source = nullptr;            ///< α (b − pressure term + relaxation) / a_P
    std::array<const double*, 2 * Dim> c_nb{}; ///< α a_nb / a_P
    std::array<std::ptrdiff_t, Dim> strides{};
    /// Writes source and c_nb of the faces [lo, hi) of the row at `row_offset` (grid.offset of
    /// the row's index 0) from the unscaled system.
    std::function<void(std::ptrdiff_t row_offset, int lo, int hi)> scale_row;

    /// The Gauss–Seidel value at `o`: s + Σ c_nb u_nb.
    [[nodiscard]] double relaxed(const double* u, std::ptrdiff_t o) const noexcept
    {
        double value = source[o];
        for (std::size_t d = 0; d < strides.size(); ++d) {
            value += c_nb[2 * d][o] * u[o - strides[d]] + c_nb[2 * d + 1][o] * u[o + strides[d]];
        }
        return value;
    }
    /// The residual at `o` divided by a_P/α: s − u + Σ c_nb u_nb.
    [[nodiscard]] double residual(const double* u, std::ptrdiff_t o) const noexcept
    {
        double value = source[o] - u[o];
        for (std::size_t d = 0; d < strides.size(); ++d) {
            value += c_nb[2 * d][o] * u[o - strides[d]] + c_nb[2 * d + 1][o] * u[o + strides[d]];
        }
        return value;
    }
};

/// The scaled system: folds the pressure gradient, the relaxation term and 1/a_P in once,
/// since they stay fixed during the sweeps. Writes nothing: its scale_row fills the rows
/// (scale_box all of them at once; the wavefront of `sweeps` row by row, just before its first
/// sweep reads them).
template <int Dim>
ScaledSystem<Dim> scale_system(const MacGrid<Dim>& grid, int axis, double alpha,
                               const FluidState<Dim>& state, MomentumSystem<Dim>& system)
{
    const double relax_factor = 1.0 / alpha - 1.0;
    const double pressure_factor = grid.cell_volume() / grid.spacing(axis);
    const std::ptrdiff_t s_axis = grid.stride(axis);
    const double* p = state.p.data();
    const double* a_p = system.a_p.data();
    const double* b = system.b.data();
    const double* u_old = system.u_old.data();
    double* source = system.scaled_source.data();
    std::array<const double*, 2 * Dim> a_nb{};
    std::array<double*, 2 * Dim> c_out{};
    ScaledSystem<Dim> scaled;
    for (std::size_t k = 0; k < a_nb.size(); ++k) {
        a_nb[k] = system.a_nb[k].data();
        c_out[k] = system.scaled_nb[k].data();
        scaled.c_nb[k] = c_out[k];
    }
    for (int d = 0; d < Dim; ++d) {
        scaled.strides[static_cast<std::size_t>(d)] = grid.stride(d);
    }
    scaled.source = source;
    scaled.scale_row = [=](std::ptrdiff_t row_offset, int lo, int hi) {
        for (int i = lo; i < hi; ++i) {
            const std::ptrdiff_t o = row_offset + i;
            const double scale = alpha / a_p[o];
            source[o] = scale * (b[o] - (p[o] - p[o - s_axis]) * pressure_factor +
                                 relax_factor * a_p[o] * u_old[o]);
            for (std::size_t k = 0; k < c_out.size(); ++k) {
                c_out[k][o] = scale * a_nb[k][o];
            }
        }
    };
    return scaled;
}

/// The whole system scaled (ScaledSystem::scale_row over every row of `box`).
template <int Dim>
void scale_box(const MacGrid<Dim>& grid, const Box<Dim>& box, const ScaledSystem<Dim>& scaled)
{
    for_each_row(box, [&](const Index<Dim>& row) {
        scaled.scale_row(grid.offset(row) - box.lo[0], box.lo[0], box.hi[0]);
    });
}

/// Relaxes the faces of one colour (parity of the index sum) in the row of `box` that starts at
/// `row`: u ← s + Σ c_nb u_nb, in place.
template <int Dim>
void relax_row(const MacGrid<Dim>& grid, const Box<Dim>& box, const ScaledSystem<Dim>& scaled,
               const Index<Dim>& row, int colour, double* ua)
{
    int parity = 0;
    for (const int x : row) {
        parity += x;
    }
    const int first = box.lo[0] + (((parity - colour) % 2) + 2) % 2;
    const std::ptrdiff_t row_offset = grid.offset(row) - box.lo[0];
    for (int i = first; i < box.hi[0]; i += 2) {
        const std::ptrdiff_t o = row_offset + i;
        ua[o] = scaled.relaxed(ua, o);
    }
}

/// One red-black Gauss–Seidel sweep of `u` over `box`. A face only reads faces of the other
/// colour, so each colour updates in parallel without races; only images of owned faces (across
/// a periodic side or from the next block) are read with a non-zero coefficient (wall neighbours
/// are folded into the coefficients), and only across the block's faces, one layer deep, so
/// those are the only ghosts refilled between the colours (HaloExchange::fill_faces; the caller
/// fills them all afterwards).
template <int Dim>
void red_black_sweep(const MacGrid<Dim>& grid, const Box<Dim>& box, const ScaledSystem<Dim>& scaled,
                     GridArray<Dim>& u)
{
    for (int colour = 0; colour < 2; ++colour) {
        for_each_row(box, [&](const Index<Dim>& row) {
            relax_row<Dim>(grid, box, scaled, row, colour, u.data());
        });
        HaloExchange<Dim>(grid).fill_faces(u);
    }
}

/// `count` red-black sweeps of `u` over `box`, after scaling the system's rows if `scale_first`.
/// In 3D, on a grid not split along x or y (HaloExchange::keeps_slices_apart), the scaling and
/// the colours of all the sweeps run as one wavefront over the z slices
/// (for_each_plane_wavefront), each colour refreshing a slice's periodic images once it has
/// been over it (fill_plane). A face reads only its own slice and the two beside it, so the
/// values are those of the sweeps one after the other, bit for bit, while the coefficient
/// arrays come from memory once for all the `count` sweeps instead of once per colour. Where
/// the z slices go on beyond the block (z split over ranks, or periodic), the wavefront runs
/// from the middle slice to both ends at once, and after each colour has reached the ends the
/// end slices are exchanged along z (fill_faces_axis: the one slice beside the block) for the
/// next colour: one message each way per colour and neighbour, as the colours one after the
/// other have. Images the sweeps do not read (deeper halo layers; the z ghost slices at walls;
/// w's boundary slices) are made right by the caller's full fill. (2D keeps
/// the sweeps one after the other: its slices are single rows, and the wavefront would run them on
/// one thread.)
template <int Dim>
void sweeps(const MacGrid<Dim>& grid, const Box<Dim>& box, const ScaledSystem<Dim>& scaled,
            int count, bool scale_first, GridArray<Dim>& u)
{
    const HaloExchange<Dim> halo(grid);
    // (Not constexpr: 2D compiles it, never runs it.) On a grid split along z every rank takes
    // the wavefront, whatever its threads: the two ways exchange different halos, and all the
    // ranks must take the same one.
    if (Dim == 3 && halo.keeps_slices_apart() && (grid.is_split(Dim - 1) || wavefront_pays(box))) {
        const int pre = scale_first ? 1 : 0;
        double* ua = u.data();
        const auto stage = [&](int q, const Index<Dim>& row) {
            if (q < pre) {
                scaled.scale_row(grid.offset(row) - box.lo[0], box.lo[0], box.hi[0]);
            } else {
                relax_row<Dim>(grid, box, scaled, row, (q - pre) % 2, ua);
            }
        };
        const auto refresh_plane = [&](int q, int plane) {
            if (q >= pre) {
                halo.fill_plane(u, plane);
            }
        };
        const auto exchange_ends = [&](int q) {
            if (q >= pre) {
                halo.fill_faces_axis(u, Dim - 1);
            }
        };
        const int stages = pre + 2 * count;
        const bool has_images_in_planes = grid.is_periodic(0) || grid.is_periodic(1);
        const bool has_ends = grid.is_split(Dim - 1) || grid.is_periodic(Dim - 1);
        if (has_ends && has_images_in_planes) {
            for_each_plane_wavefront(box, stages, true, stage, refresh_plane, exchange_ends);
        } else if (has_ends) {
            for_each_plane_wavefront(box, stages, true, stage, nullptr, exchange_ends);
        } else if (has_images_in_planes) {
            for_each_plane_wavefront(box, stages, false, stage, refresh_plane, nullptr);
        } else {
            for_each_plane_wavefront(box, stages, false, stage, nullptr, nullptr);
        }
        return;
    }
    if (scale_first) {
        scale_box(grid, box, scaled);
    }
    for (int k = 0; k < count; ++k) {
        red_black_sweep(grid, box, scaled, u);
    }
}

/// The finest level of the multigrid: the unscaled system on the grid arrays (a_P/α − a_nb).
template <int Dim>
StencilView<Dim> fine_level(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                            const Box<Dim>& box, double alpha, const MomentumSystem<Dim>& system)
{
    StencilView<Dim> fine;
    for (int d = 0; d < Dim; ++d) {
        const auto sd = static_cast<std::size_t>(d);
        fine.n[sd] = box.extent(d);
        fine.periodic[sd] = bc.periodic(d);
        fine.stride[sd] = grid.stride(d);
    }
    fine.origin = grid.offset(box.lo);
    fine.diagonal = system.a_p.data();
    fine.diagonal_scale = 1.0 / alpha;
    for (std::size_t k = 0; k < fine.a_nb.size(); ++k) {
        fine.a_nb[k] = system.a_nb[k].data();
    }
    return fine;
}

/// coarse.rhs = the fine residual a_P/α · (s − u + Σ c_nb u_nb) summed over each block, and
/// coarse.x = 0: one coarse row at a time, reading its fine rows with unit stride (cheaper than
/// restrict_sum's call per unknown). On a split grid `fine` is this rank's part of the whole
/// level (`part`): only the blocks that meet it are written, and coarse.rhs and coarse.x must
/// be zero elsewhere. `coarse`'s arrays hold the coarse unknowns from `origin` on.
template <int Dim>
void restrict_residual(const StencilView<Dim>& fine, const LevelPart<Dim>& part,
                       const ScaledSystem<Dim>& scaled, const double* a_p, double alpha,
                       const double* u, const Index<Dim>& origin, CoarseLevel<Dim>& coarse)
{
    // The coarse rows the part meets, and the coarse columns [first, last] along x.
    Box<Dim> coarse_rows = coarse_part_box<Dim>(part, fine.n);
    const int first = coarse_rows.lo[0];
    const auto width = static_cast<std::size_t>(coarse_rows.hi[0] - first);
    coarse_rows.hi[0] = first + 1;
    for_each_index(
        coarse_rows,
        [&](const Index<Dim>& coarse_row) {
            const std::size_t out = coarse.offset(coarse_row - origin);
            std::fill_n(coarse.rhs.begin() + static_cast<std::ptrdiff_t>(out), width, 0.0);
            std::fill_n(coarse.x.begin() + static_cast<std::ptrdiff_t>(out), width, 0.0);
            for (int member = 0; member < (1 << (Dim - 1)); ++member) {
                Index<Dim> i{};
                bool is_inside = true;
                for (int d = 1; d < Dim; ++d) {
                    const auto sd = static_cast<std::size_t>(d);
                    i[sd] = 2 * coarse_row[sd] + ((member >> (d - 1)) & 1) - part.offset[sd];
                    is_inside = is_inside && i[sd] >= 0 && i[sd] < fine.n[sd];
                }
                if (!is_inside) {
                    continue;
                }
                const std::ptrdiff_t row_offset = fine.at(i);
                for (int x = 0; x < fine.n[0]; ++x) {
                    const std::ptrdiff_t o = row_offset + x;
                    coarse.rhs[out + static_cast<std::size_t>((x + part.offset[0]) / 2 - first)] +=
                        a_p[o] / alpha * scaled.residual(u, o);
                }
            }
        },
        (std::size_t{1} << Dim) * width);
}

/// u += P coarse.x: each fine unknown takes its block's correction (`coarse`'s arrays hold the
/// coarse unknowns from `origin` on).
template <int Dim>
void add_coarse_correction(const Box<Dim>& box, const StencilView<Dim>& fine,
                           const LevelPart<Dim>& part, const Index<Dim>& origin,
                           const CoarseLevel<Dim>& coarse, double* u)
{
    for_each_row(box, [&](const Index<Dim>& row) {
        Index<Dim> i = row - box.lo;
        const std::ptrdiff_t row_offset = fine.at(i);
        Index<Dim> at = i + part.offset; // the index in the whole level
        for (int x = 0; x < fine.n[0]; ++x) {
            at[0] = x + part.offset[0];
            u[row_offset + x] += coarse.x[coarse.offset(coarse_index<Dim>(at) - origin)];
        }
    });
}

/// The unknown faces of component `axis` in the whole domain: unknown_faces on one process.
template <int Dim>
Box<Dim> whole_unknown_faces(const MacGrid<Dim>& grid, int axis)
{
    Box<Dim> box = grid.cell_box();
    if (!grid.is_periodic(axis)) {
        box.lo[static_cast<std::size_t>(axis)] = 1; // face 0 and face n are boundary faces
    }
    return box;
}

/// The multigrid's levels below `fine`: on one process the whole hierarchy
/// (build_coarse_levels), on a split grid the split levels and the root's gathered level
/// (linsolve/split_multigrid.hpp; `part` is where this rank's part of the whole level sits;
/// the levels' boxes and routes are kept from the system's first solve).
template <int Dim>
void build_levels(const MacGrid<Dim>& grid, const StencilView<Dim>& fine,
                  const LevelPart<Dim>& part, MomentumSystem<Dim>& system)
{
    if (!grid.communicator().uses_mpi()) {
        build_coarse_levels(fine, system.coarse_levels);
        return;
    }
    if (coarse_extent<Dim>(part.whole_n) == part.whole_n) {
        system.split_levels.levels.clear(); // every extent is 1: nothing to merge
        return;
    }
    build_split_levels<Dim>(grid.communicator(), fine, part, system.split_levels);
}

/// max |s − u + Σ c_nb u_nb| over `box`, all ranks: the residual over a_P/α (with α = 1 the
/// normalised residual max |r/a_P| of assemble_momentum). Reads u's ghosts.
template <int Dim>
double scaled_residual(const MacGrid<Dim>& grid, const Box<Dim>& box,
                       const ScaledSystem<Dim>& scaled, const GridArray<Dim>& u)
{
    const double* ua = u.data();
    return max_over_rows(grid.communicator(), box, [&](const Index<Dim>& row) {
        const std::ptrdiff_t start = grid.offset(row);
        double largest = 0.0;
        for (int i = 0; i < box.hi[0] - box.lo[0]; ++i) {
            largest = max_keeping_nan(largest, std::abs(scaled.residual(ua, start + i)));
        }
        return largest;
    });
}

} // namespace

template <int Dim>
void solve_momentum(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                    const MomentumSettings& settings, MomentumSystem<Dim>& system, int axis,
                    FluidState<Dim>& state)
{
    (void)solve_momentum_to(grid, bc, settings, system, axis, state, MomentumStop{});
}

template <int Dim>
MomentumSolveResult solve_momentum_to(const MacGrid<Dim>& grid, const BoundaryConditions<Dim>& bc,
                                      const MomentumSettings& settings, MomentumSystem<Dim>& system,
                                      int axis, FluidState<Dim>& state, const MomentumStop& stop)
{
    const Box<Dim> box = unknown_faces(grid, bc, axis);
    const double alpha = settings.relaxation;
    GridArray<Dim>& u = state.u[axis];
    const ScaledSystem<Dim> scaled = scale_system(grid, axis, alpha, state, system);
    const bool is_stopped_by_residual = stop.residual > 0.0;
    // After each round (the sweeps, or the V-cycles, of one outer iteration), with a stop: the
    // residual, and whether it is small enough or the rounds are spent.
    MomentumSolveResult result;
    const auto is_done = [&] {
        ++result.rounds;
        if (!is_stopped_by_residual) {
            return true;
        }
        result.residual = scaled_residual(grid, box, scaled, u);
        return result.residual <= stop.residual || result.rounds >= stop.max_rounds;
    };

    if (settings.cycles == 0) {
        for (bool is_first = true;; is_first = false) {
            sweeps(grid, box, scaled, settings.sweeps, is_first, u);
            fill_component_ghosts(grid, bc, axis, u);
            if (is_done()) {
                return result;
            }
        }
    }
    scale_box(grid, box, scaled); // the restriction reads the scaled residual everywhere

    const StencilView<Dim> fine = fine_level(grid, bc, box, alpha, system);
    const Box<Dim> whole = whole_unknown_faces(grid, axis);
    const LevelPart<Dim> part{box.lo - whole.lo, whole.hi - whole.lo};
    const bool is_split = grid.communicator().uses_mpi();
    // Rebuilt at every solve: a hierarchy kept for the whole time step (the coefficients
    // change between outer iterations) made the eighteen-disk case blow up at a collision.
    // (On a split grid only the operator is rebuilt; the levels' boxes and routes are kept.)
    build_levels<Dim>(grid, fine, part, system);
    const bool has_coarse_levels =
        is_split ? !system.split_levels.levels.empty() : !system.coarse_levels.empty();
    const int pre_sweeps = settings.sweeps / 2;
    const int post_sweeps = settings.sweeps - pre_sweeps;
    do {
        for (int cycle = 0; cycle < settings.cycles; ++cycle) {
            sweeps(grid, box, scaled, pre_sweeps, false, u);
            if (has_coarse_levels) {
                if (is_split) {
                    SplitLevel<Dim>& coarse = system.split_levels.levels.front();
                    std::fill(coarse.local.rhs.begin(), coarse.local.rhs.end(), 0.0);
                    restrict_residual<Dim>(fine, part, scaled, system.a_p.data(), alpha, u.data(),
                                           coarse.stored.lo, coarse.local);
                    split_v_cycle(grid.communicator(), system.split_levels, 2);
                    add_coarse_correction<Dim>(box, fine, part, coarse.stored.lo, coarse.local,
                                               u.data());
                } else {
                    CoarseLevel<Dim>& coarse = system.coarse_levels.front();
                    restrict_residual<Dim>(fine, part, scaled, system.a_p.data(), alpha, u.data(),
                                           Index<Dim>{}, coarse);
                    coarse_v_cycle(system.coarse_levels, 0, 2);
                    add_coarse_correction<Dim>(box, fine, part, Index<Dim>{}, coarse, u.data());
                }
                // The post-smoothing sweeps read only the face ghosts; fill_component_ghosts
                // below fills them all.
                HaloExchange<Dim>(grid).fill_faces(u);
            }
            sweeps(grid, box, scaled, post_sweeps, false, u);
        }
        fill_component_ghosts(grid, bc, axis, u);
    } while (!is_done());
    return result;
}

template <int Dim>
double time_term_share(const MacGrid<Dim>& grid, const FluidProperties& fluid, double dt)
{
    const double volume = grid.cell_volume();
    const double time = fluid.density * volume / dt;
    double links = 0.0;
    for (int d = 0; d < Dim; ++d) {
        const double h = grid.spacing(d);
        links += 2.0 * fluid.viscosity * (volume / h) / h;
    }
    return time / (time + links);
}

int momentum_cycles_for(MomentumSolver solver, int cycles, double time_share)
{
    switch (solver) {
    case MomentumSolver::gauss_seidel:
        return 0;
    case MomentumSolver::multigrid:
        return cycles;
    case MomentumSolver::automatic:
        break;
    }
    return time_share < multigrid_time_share ? cycles : 0;
}

template double time_term_share<2>(const MacGrid<2>&, const FluidProperties&, double);
template double time_term_share<3>(const MacGrid<3>&, const FluidProperties&, double);
template double assemble_momentum<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                     const FluidProperties&, const MomentumSettings&,
                                     const TimeLevels&, const FluidState<2>&, int,
                                     MomentumSystem<2>&);
template double assemble_momentum<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                     const FluidProperties&, const MomentumSettings&,
                                     const TimeLevels&, const FluidState<3>&, int,
                                     MomentumSystem<3>&);
template void solve_momentum<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                const MomentumSettings&, MomentumSystem<2>&, int, FluidState<2>&);
template void solve_momentum<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                const MomentumSettings&, MomentumSystem<3>&, int, FluidState<3>&);
template MomentumSolveResult solve_momentum_to<2>(const MacGrid<2>&, const BoundaryConditions<2>&,
                                                  const MomentumSettings&, MomentumSystem<2>&, int,
                                                  FluidState<2>&, const MomentumStop&);
template MomentumSolveResult solve_momentum_to<3>(const MacGrid<3>&, const BoundaryConditions<3>&,
                                                  const MomentumSettings&, MomentumSystem<3>&, int,
                                                  FluidState<3>&, const MomentumStop&);

} // namespace fddem
