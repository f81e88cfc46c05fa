"""The figures that fit a run: `plot_run(run, out_dir)` decides from the case and the outputs
which to draw, writes them and returns their paths. Each `*_figure(run, …)` returns a figure, or
None when it does not apply to the run.

    overview     the run at a glance: the flow at the last frame (a mid-plane in 3D) with the
                 bodies, and beside it the centre-line profiles against published data (no
                 bodies), the trajectories and speeds (free bodies) or the forces (fixed ones)
    solver       outer iterations, residuals, Δt and Courant number against time; the phase
                 shares of the wall time (summary.json)
    snapshots    the flow with the bodies at up to six frames (paper Figs. 5, 9, 10)
    slices       3D: the three mid-planes, spheres cut by each plane
    samples      the line samples (a cylinder's wake axis against its reference)
    positions, velocities, energy, trajectories, contacts, forces
                 the bodies (paper Figs. 6-8 and 11-13): centres, velocities and angular
                 velocities, kinetic energies, paths, contact events, hydrodynamic forces
    settling     the settling velocity against the analytic one (paper Figs. 3-4)
    uhlmann      the DKT run against Uhlmann (2005) Figs. 6-8, where that data is present
"""

import os

import numpy as np

from . import plots, references, slices
from .plots import STYLE

MAX_SNAPSHOTS = 6


def pyplot():
    """matplotlib's pyplot on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update(STYLE)
    return plt


def save_one_panel(path, draw, title, size=(7, 4.5), grid_which="major"):
    """One axes drawn by draw(axes), with a legend, a light grid and `title`, saved to `path`
    (the figure of the tools/compare_*.py scripts); returns the path."""
    plt = pyplot()
    fig, axes = plt.subplots(figsize=size)
    draw(axes)
    axes.legend(fontsize=8)
    axes.grid(alpha=0.3, which=grid_which)
    axes.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def comparison_parser(description):
    """The command line of a tools/compare_*.py script: RUN_DIR ..., -o PNG, --label NAME ..."""
    import argparse

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("-o", "--output")
    parser.add_argument("--label", nargs="+", help="legend labels, one per run")
    return parser


def run_labels(parser, args):
    """One label per run: the --label given, or each run directory's name."""
    if args.label and len(args.label) != len(args.runs):
        parser.error("give one --label per run")
    return args.label or [os.path.basename(os.path.normpath(r)) for r in args.runs]


def _panel_size(run, width=4.2, widest=10.0, tallest=8.0):
    """(width, height) in inches of a panel showing the box's display plane: `width` wide
    (at most `tallest` high) when the box is taller than wide, else wide enough for a
    2.2-inch height (at most `widest`)."""
    a, b = display_axes(run)
    aspect = run.size[b] / run.size[a]
    if aspect >= 1.0:
        height = min(width * aspect, tallest)
        return height / aspect, height
    width = min(max(width, 2.2 / aspect), widest)
    return width, width * aspect


def display_axes(run):
    """The in-plane axes (a, b) of the plane that shows a run: (x, y) in 2D; in 3D the gravity
    axis and the longer of the other two (a vertical mid-plane), or (x, y) without gravity."""
    if run.dimension == 2:
        return 0, 1
    gravity = np.abs(np.array(run.case.get("fluid", {}).get("gravity", [0, 0, 0]), float))
    if not gravity.any():
        return 0, 1
    down = int(np.argmax(gravity))
    others = [k for k in range(3) if k != down]
    across = max(others, key=lambda k: run.size[k])
    return tuple(sorted((across, down)))


def display_normal(run):
    a, b = display_axes(run)
    return 2 if run.dimension == 2 else ({0, 1, 2} - {a, b}).pop()


def plane_at_frame(run, index, normal_axis=None, position=None, frame=None):
    """(plane slice, bodies cut by it) at field frame `index`."""
    if normal_axis is None:
        normal_axis = display_normal(run)
    frame = frame if frame is not None else run.field(index)
    plane = slices.plane_slice(frame, normal_axis, position)
    cuts = []
    bodies = run.bodies_at_frame(index)
    if bodies is not None:
        cuts = slices.bodies_cut_by_plane(bodies["centre"], bodies["radius"], normal_axis,
                                          plane["position"] if run.dimension == 3 else 0.0)
    return plane, cuts, frame["time"]


def _colourbar(fig, image, ax, run, label="|u|"):
    fig.colorbar(image, ax=ax, shrink=0.85, label=run.units.label(label, "velocity"))


def _body_histories(run):
    histories = run.body_histories()
    return histories, plots.body_colours(sorted(histories))


def _free(run, histories):
    return {b: h for b, h in histories.items()
            if run.body(b).get("motion", "free") != "fixed"}


# --- the overview ---------------------------------------------------------------------------


def overview_figure(run):
    if len(run.frame_times) == 0:
        return None
    plt = pyplot()
    width, height = _panel_size(run)
    wide = width > 1.6 * height
    side_width = 4.2
    if wide:
        fig, axes = plt.subplots(2, 1, figsize=(width + 1.2, height + 3.4),
                                 gridspec_kw={"height_ratios": [height, 3.0]})
    else:
        n_side = 2 if run.has_bodies and run.has_free_bodies else 1
        fig, axes = plt.subplots(1, 1 + n_side, figsize=(width + 1.4 + side_width * n_side,
                                                         max(height, 3.4) + 0.6),
                                 gridspec_kw={"width_ratios": [width + 1.0]
                                              + [side_width] * n_side})
    axes = list(np.atleast_1d(axes))
    plane, cuts, time = plane_at_frame(run, -1)
    image = plots.flow_field(axes[0], plane, run.units, cuts)
    _colourbar(fig, image, axes[0], run)
    where = "" if run.dimension == 2 else (
        f", plane {slices.AXIS_NAMES[plane['normal_axis']]} = {plane['position']:.3g}")
    when = ("at the steady state" if run.is_steady
            else f"at t = {time:.4g} {run.units.unit('time')}")
    axes[0].set_title(f"|u| and streamlines {when}{where}")
    if not run.has_bodies:
        _centrelines_panel(run, axes[1])
    elif run.has_free_bodies:
        histories, colours = _body_histories(run)
        free = _free(run, histories)
        a, b = display_axes(run)
        plots.trajectories(axes[1], free, colours, (a, b), run.origin, run.size, run.units,
                           {k: run.body_radius(k) for k in free})
        axes[1].set_title("trajectories (dot: start, circle: end)")
        if len(axes) > 2:
            speed_panel(axes[2], run, free, colours)
    else:
        forces_panel(axes[1], run)
    fig.suptitle(run.title)
    fig.tight_layout()
    return fig


def speed_panel(ax, run, histories, colours):
    for body, h in histories.items():
        speed = np.sqrt(sum(h[c] ** 2 for c in ("u", "v", "w") if c in h))
        ax.plot(h["time"], speed, color=colours[body], lw=0.9, label=f"body {body}")
    ax.set_xlabel(run.units.label("t", "time"))
    ax.set_ylabel(run.units.label("|U|", "velocity"))
    ax.set_title("body speeds")
    if len(histories) <= 4:
        ax.legend()


def centreline_profiles(run):
    """(vertical (y, u), horizontal (x, v)) through the middle of the box: the cavity's samples
    when the run has them, else the last field frame's mid-plane."""
    samples = run.samples(as_frame=False)
    if "vertical_centerline" in samples and "horizontal_centerline" in samples:
        vertical, horizontal = samples["vertical_centerline"], samples["horizontal_centerline"]
        return (vertical["y"], vertical["u"]), (horizontal["x"], horizontal["v"]), True
    plane = slices.plane_slice(run.field(-1), 2)
    a, b = plane["axes"]
    yb, ua_b, _ = slices.line_profile(plane, b)
    xa, _, ub_a = slices.line_profile(plane, a)
    return (yb, ua_b), (xa, ub_a), False


def _centrelines_panel(run, ax):
    vertical, horizontal, sampled = centreline_profiles(run)
    reference = references.ghia(references.case_directory(run.path))
    plots.centrelines(ax, vertical, horizontal, run.units, reference)
    source = "samples/" if sampled else "the last field frame"
    ax.set_title(f"centre-line profiles (from {source})")


# --- solver history -------------------------------------------------------------------------


def solver_figure(run):
    solver = run.solver(as_frame=False)
    if len(solver["time"]) == 0:
        return None
    plt = pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(10, 6.4))
    units = run.units
    if run.is_steady:  # pseudo-time: the step is the measure of progress
        t, t_label = solver["step"], "step (pseudo-time march to the steady state)"
    else:
        t, t_label = solver["time"], units.label("t", "time")
    marker = "o" if len(t) < 60 else None
    ax = axes[0, 0]
    ax.plot(t, solver["outer_iterations"], lw=0.8, marker=marker, ms=3, label="per step")
    unconverged = solver["is_converged"] == 0
    if unconverged.any():
        ax.plot(t[unconverged], solver["outer_iterations"][unconverged], "x", color="C3", ms=4,
                label="not converged")
    ax.set_ylabel("SIMPLE outer iterations per step")
    twin = ax.twinx()
    twin.plot(t, solver["total_outer_iterations"], color="0.35", ls="--", lw=0.9,
              label="cumulative (right)")
    twin.set_ylabel("cumulative outer iterations")
    twin.grid(False)
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [line.get_label() for line in lines], loc="upper center")
    ax.set_title("outer iterations")
    ax = axes[0, 1]
    tolerance = run.case.get("simple", {}).get("tolerance")
    for column, label in (("mass_residual", "mass"), ("momentum_residual", "momentum"),
                          ("rate_of_change", "rate of change (steady-state measure)")):
        values = np.where(solver[column] > 0, solver[column], np.nan)
        ax.semilogy(t, values, lw=0.9, marker=marker, ms=3, label=label)
    if tolerance:
        ax.axhline(tolerance, color="k", ls=":", lw=0.9, label="SIMPLE tolerance")
    ax.set_ylabel("normalised residual [–]")
    ax.set_title("residuals at the end of each step")
    ax.legend()
    ax = axes[1, 0]
    ax.plot(t, solver["dt"], marker=marker, ms=3, label="Δt")
    if run.is_steady:
        ax.set_yscale("log")
    ax.set_ylabel(units.label("Δt", "time"))
    twin = ax.twinx()
    twin.plot(t, solver["courant"], color="C1", lw=0.9, marker=marker, ms=3,
              label="Courant number (right)")
    if run.is_steady:
        twin.set_yscale("log")
    twin.set_ylabel("Courant number [–]")
    twin.grid(False)
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [line.get_label() for line in lines])
    ax.set_title("time step")
    for ax in axes[:, 0].tolist() + [axes[0, 1]]:
        ax.set_xlabel(t_label)
    summary = run.summary
    ax = axes[1, 1]
    phases = summary.get("wall_seconds_by_phase")
    if phases:
        total = float(summary.get("wall_seconds_stepping", sum(phases.values())))
        plots.phase_shares(ax, phases, total)
        ax.set_title(f"wall time: {total:.3g} s for {summary.get('steps', len(t))} steps "
                     f"({summary.get('pressure_solver', '')})")
    else:
        ax.set_axis_off()
        ax.text(0.5, 0.5, "no summary.json (run unfinished)", ha="center", transform=ax.transAxes)
    status = summary.get("status", "running")
    fig.suptitle(f"{run.title}\nsolver history ({status})")
    fig.tight_layout()
    return fig


# --- flow pictures --------------------------------------------------------------------------


def snapshot_indices(frame_times, times=None, count=MAX_SNAPSHOTS):
    """Indices of the frames to show: nearest to each of `times`, else up to `count` spread
    evenly from the first to the last."""
    n = len(frame_times)
    if times:
        return sorted({int(np.argmin(np.abs(frame_times - t))) for t in times})
    return sorted({int(round(k)) for k in np.linspace(0, n - 1, min(n, count))})


def snapshots_figure(run, times=None):
    n_frames = len(run.frame_times)
    if (n_frames < 3 or run.is_steady) and not times:
        return None  # a pseudo-time march's frames are not a history
    indices = snapshot_indices(run.frame_times, times)
    planes = [plane_at_frame(run, k) for k in indices]
    vmax = max(float(np.max(p["speed"])) for p, _, _ in planes) or 1.0
    width, height = _panel_size(run, 3.0)
    n = len(planes)
    if height > 1.6 * width:
        rows, cols = 1, n
    elif width > 1.6 * height:
        rows, cols = n, 1
    else:
        cols = min(n, 3)
        rows = -(-n // cols)
    plt = pyplot()
    fig, axes = plt.subplots(rows, cols, figsize=(cols * width + 1.4, rows * height + 1.0),
                             squeeze=False, sharex=True, sharey=True, layout="constrained")
    image = None
    for ax, (plane, cuts, time) in zip(axes.flat, planes):
        image = plots.flow_field(ax, plane, run.units, cuts, vmax=vmax, streamlines=0.6)
        ax.set_title(f"t = {time:.3g} {run.units.unit('time')}")
    for ax in axes.flat[n:]:
        ax.set_axis_off()
    for ax in axes[:, 1:].flat:
        ax.set_ylabel("")
    for ax in axes[:-1, :].flat:
        ax.set_xlabel("")
    fig.colorbar(image, ax=axes, shrink=0.8, label=run.units.label("|u|", "velocity"))
    fig.suptitle(f"{run.title}\n|u| and streamlines" + ("" if run.dimension == 2 else (
        f" on the plane {slices.AXIS_NAMES[display_normal(run)]} = mid")))
    return fig


def slices_figure(run):
    """3D: the flow on the three mid-planes of the last frame, spheres cut by each."""
    if run.dimension != 3 or len(run.frame_times) == 0:
        return None
    plt = pyplot()
    frame = run.field(-1)
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.6), layout="constrained")
    vmax = float(np.max(np.linalg.norm(frame["velocity"], axis=-1))) or 1.0
    image = None
    for ax, normal in zip(axes, (2, 1, 0)):
        plane, cuts, time = plane_at_frame(run, -1, normal, frame=frame)
        image = plots.flow_field(ax, plane, run.units, cuts, vmax=vmax)
        name = slices.AXIS_NAMES[normal]
        ax.set_title(f"mid-plane {name} = {plane['position']:.3g} {run.units.unit('length')}")
    fig.colorbar(image, ax=axes, shrink=0.8, label=run.units.label("|u|", "velocity"))
    fig.suptitle(f"{run.title}\n|u|, in-plane streamlines and the spheres cut by each plane, "
                 f"t = {frame['time']:.4g} {run.units.unit('time')}")
    return fig


def samples_figure(run):
    samples = {name: columns for name, columns in run.samples(as_frame=False).items()
               if len(columns["p"]) >= 5
               and name not in ("vertical_centerline", "horizontal_centerline")}
    if not samples:
        return None
    plt = pyplot()
    fig, axes = plt.subplots(1, len(samples), figsize=(5.2 * len(samples), 3.9), squeeze=False)
    for ax, (name, columns) in zip(axes.flat, samples.items()):
        if name == "wake_axis" and run.has_bodies:
            _wake_axis_panel(ax, run, columns)
        else:
            plots.line_sample(ax, name, columns, run.units)
            ax.set_title(f"line sample {name}")
    fig.suptitle(run.title)
    fig.tight_layout()
    return fig


def _wake_axis_panel(ax, run, columns):
    """u on a cylinder's wake axis from its rear point, against the case's reference."""
    body = run.bodies[0]
    diameter = float(body["diameter"])
    x_rear = float(body["position"][0]) + 0.5 * diameter
    case_dir = references.case_directory(run.path)
    bounds = references.schafer_turek(case_dir)
    unbounded = references.unbounded_cylinder(case_dir)
    if bounds is not None:
        plots.wake_axis(ax, columns["x"], columns["u"], x_rear, run.units,
                        bounds["recirculation_length"], f"L_a, {bounds['label']}")
    elif unbounded is not None:
        lengths = [r[2] for r in unbounded if r[2] is not None and r[1] is not None]
        plots.wake_axis(ax, columns["x"], columns["u"], x_rear, run.units,
                        (min(lengths), max(lengths)), "L/D, Fornberg (1980) – Dennis & Chang (1970)",
                        scale=diameter)
    else:
        plots.wake_axis(ax, columns["x"], columns["u"], x_rear, run.units)
    ax.set_title("u on the wake axis (recirculation: u < 0)")


# --- bodies ---------------------------------------------------------------------------------


def _series_figure(run, panels, title):
    """A grid of per-body time series: panels = [(column, label, kind)]."""
    histories, colours = _body_histories(run)
    if not histories:
        return None
    plt = pyplot()
    cols = min(len(panels), 3)
    rows = -(-len(panels) // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.3 * cols + 0.8, 3.4 * rows), squeeze=False)
    for ax, (column, label, kind) in zip(axes.flat, panels):
        plots.body_series(ax, histories, column, colours, run.units.label(label, kind), run.units)
    for ax in axes.flat[len(panels):]:
        ax.set_axis_off()
    plots.finish_bodies_legend(fig, axes.flat[len(panels) - 1], colours)
    fig.suptitle(f"{run.title}\n{title}")
    fig.tight_layout()
    return fig


def positions_figure(run):
    if not (run.has_bodies and run.has_free_bodies):
        return None
    names = "xyz"[: run.dimension]
    return _series_figure(run, [(c, f"{c} of the centre", "length") for c in names],
                          "centre positions (paper Figs. 6 and 12)")


def velocities_figure(run):
    if not (run.has_bodies and run.has_free_bodies):
        return None
    panels = [(c, c, "velocity") for c in "uvw"[: run.dimension]]
    if run.dimension == 2:
        panels.append(("omega", "ω", "angular_velocity"))
    else:
        panels += [(f"omega_{c}", f"ω_{c}", "angular_velocity") for c in "xyz"]
    return _series_figure(run, panels, "velocity and angular velocity (paper Figs. 7 and 11)")


def energy_figure(run):
    if not (run.has_bodies and run.has_free_bodies):
        return None
    histories, colours = _body_histories(run)
    free = _free(run, histories)
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    time = next(iter(free.values()))["time"]
    totals = [np.zeros_like(time), np.zeros_like(time)]
    few = len(free) <= plots.MANY_BODIES
    for body, h in free.items():
        mass, inertia = run.body_mass_and_inertia(body)
        speed2 = sum(h[c] ** 2 for c in ("u", "v", "w") if c in h)
        spin2 = h["omega"] ** 2 if "omega" in h else sum(h[f"omega_{c}"] ** 2 for c in "xyz")
        energies = (0.5 * mass * speed2, 0.5 * inertia * spin2)
        for k in range(2):
            if len(energies[k]) == len(time):
                totals[k] += energies[k]
            if few and len(free) > 1:
                axes[k].plot(h["time"], energies[k], color=colours[body], lw=0.7,
                             label=f"body {body}")
    what = "sum over the bodies" if len(free) > 1 else None
    for ax, total, name in zip(axes, totals, ("translational", "rotational")):
        ax.plot(time, total, color="k", lw=1.3, label=what)
        ax.set_xlabel(run.units.label("t", "time"))
        ax.set_ylabel(run.units.label(f"{name} kinetic energy", "energy"))
        ax.set_title(f"{name}: " + ("½ m |U|²" if name == "translational" else "½ J ω²"))
        if what:
            ax.legend(ncol=2)
    depth = " per unit depth (disks)" if run.dimension == 2 else " (spheres)"
    fig.suptitle(f"{run.title}\nkinetic energy of the bodies{depth} (paper Fig. 8)")
    fig.tight_layout()
    return fig


def trajectories_figure(run):
    if not (run.has_bodies and run.has_free_bodies):
        return None
    histories, colours = _body_histories(run)
    free = _free(run, histories)
    radii = {k: run.body_radius(k) for k in free}
    plt = pyplot()
    planes = [display_axes(run)] if run.dimension == 2 else [(0, 1), (0, 2), (1, 2)]
    run_planes = planes
    width, height = _panel_size(run, 3.6)
    fig, axes = plt.subplots(1, len(run_planes), figsize=(len(run_planes) * width + 1.6,
                                                          height + 1.0), squeeze=False)
    for ax, plane in zip(axes.flat, run_planes):
        plots.trajectories(ax, free, colours, plane, run.origin, run.size, run.units, radii)
    plots.finish_bodies_legend(fig, axes.flat[-1], colours)
    fig.suptitle(f"{run.title}\ntrajectories (dot: start, circle: end; paper Fig. 13)")
    fig.tight_layout()
    return fig


def contacts_figure(run):
    if not run.has_contacts:
        return None
    histories, colours = _body_histories(run)
    if not any(np.any(plots.contact_force(h) > 0) for h in histories.values()):
        return None
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10.5, 3.9))
    plots.contact_events(axes[0], histories, colours, run.units)
    axes[0].set_title("bodies in contact (rows of particles.csv)")
    time = next(iter(histories.values()))["time"]
    forces = np.array([plots.contact_force(h) for h in histories.values()
                       if len(h["time"]) == len(time)])
    axes[1].plot(time, np.count_nonzero(forces > 0, axis=0), color="C0",
                 label="bodies in contact")
    axes[1].set_ylabel("bodies in contact")
    axes[1].yaxis.get_major_locator().set_params(integer=True)
    axes[1].set_xlabel(run.units.label("t", "time"))
    twin = axes[1].twinx()
    largest = np.where(forces.max(axis=0) > 0, forces.max(axis=0), np.nan)
    twin.semilogy(time, largest, color="C3", lw=0.8, label="largest contact force (right)")
    twin.set_ylabel(run.units.label("largest |F_c|", "force"))
    twin.grid(False)
    lines = axes[1].get_lines() + twin.get_lines()
    axes[1].legend(lines, [line.get_label() for line in lines])
    overlap = run.summary.get("max_relative_overlap")
    axes[1].set_title("contacts" + (f" (largest overlap {100 * overlap:.2g} % of the radius, "
                                    f"t = {run.summary.get('max_overlap_time', 0):.3g})"
                                    if overlap is not None else ""))
    fig.suptitle(f"{run.title}\ncontact events: mean DEM contact force over each step")
    fig.tight_layout()
    return fig


def forces_panel(ax, run, histories=None):
    """Hydrodynamic force on the bodies; as drag and lift coefficients with an inflow, against
    the case's published values."""
    histories = histories or run.body_histories()
    speed = run.mean_inflow_speed()
    colours = plots.body_colours(sorted(histories))
    density = float(run.case["fluid"]["density"])
    case_dir = references.case_directory(run.path)
    for body, h in histories.items():
        if speed is not None:
            diameter = float(run.body(body)["diameter"])
            area = diameter if run.dimension == 2 else np.pi * diameter**2 / 4
            scale = 0.5 * density * speed**2 * area
            ax.plot(h["time"], h["fx"] / scale, color=colours[body], label=f"C_D, body {body}")
            ax.plot(h["time"], h["fy"] / scale, color=colours[body], ls="--",
                    label=f"C_L, body {body}")
        else:
            for column, style in (("fx", "-"), ("fy", "--"), ("fz", ":")):
                if column in h:
                    ax.plot(h["time"], h[column], color=colours[body], ls=style,
                            label=f"{column}, body {body}")
    if speed is not None:
        bounds = references.schafer_turek(case_dir)
        if bounds is not None:
            for quantity, name in (("drag_coefficient", "C_D"), ("lift_coefficient", "C_L")):
                ax.axhspan(*bounds[quantity], color="k", alpha=0.3,
                           label=f"{name}, {bounds['label']}")
        for source, drag, _ in references.unbounded_cylinder(case_dir) or []:
            if drag is not None:
                ax.axhline(drag, color="k", lw=0.7, ls=":", label=f"C_D, {source} (unbounded)")
        ax.set_ylabel("C_D = 2F_x/(ρŪ²D), C_L = 2F_y/(ρŪ²D)")
    else:
        ax.set_ylabel(run.units.label("hydrodynamic force", "force"))
    ax.set_xlabel(run.units.label("t", "time"))
    ax.set_title("hydrodynamic force on the bodies" + (
        "" if speed is not None else " (solid F_x, dashed F_y" + (
            ", dotted F_z)" if run.dimension == 3 else ")")))
    if len(histories) <= 4:
        ax.legend(ncol=2 if len(ax.get_lines()) > 6 else 1)


def forces_figure(run):
    if not run.has_bodies:
        return None
    histories = run.body_histories()
    if not histories:
        return None
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10.5, 3.9))
    forces_panel(axes[0], run, histories)
    colours = plots.body_colours(sorted(histories))
    torque = "torque" if run.dimension == 2 else "torque_z"
    plots.body_series(axes[1], histories, torque, colours,
                      run.units.label("hydrodynamic torque" + ("" if run.dimension == 2 else " (z)"),
                                      "torque"), run.units)
    axes[1].set_title("hydrodynamic torque")
    fig.suptitle(f"{run.title}\nforces of the last step at each row of particles.csv")
    fig.tight_layout()
    return fig


def settling_figure(runs, labels=None):
    """Paper Figs. 3-4: settling velocity / U_c and cumulative outer iterations against
    t U_c / D, one curve per run, for runs whose case derived U_c (summary.json)."""
    runs = [r for r in runs if "characteristic_velocity" in r.summary and r.has_bodies]
    if not runs:
        return None
    labels = labels or [r.title for r in runs]
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.5, 4.0))
    for run, label in zip(runs, labels):
        velocity = float(run.summary["characteristic_velocity"])
        time = float(run.summary.get("characteristic_time", 1.0))
        first = run.body_histories()[0]
        left.plot(first["time"] / time, -first["v"] / velocity, label=label)
        solver = run.solver(as_frame=False)
        right.plot(solver["time"] / time, solver["total_outer_iterations"], label=label)
    left.axhline(1.0, color="k", lw=0.9, ls="--", label="analytic (Happel & Brenner 1965)")
    left.set_xlabel("t U_c / D")
    left.set_ylabel("settling velocity / U_c")
    left.set_title("settling velocity (paper Figs. 3-4, left)")
    left.legend()
    right.set_xlabel("t U_c / D")
    right.set_ylabel("cumulative SIMPLE outer iterations")
    right.set_title("SIMPLE outer iterations (paper Figs. 3-4, right)")
    right.legend()
    fig.tight_layout()
    return fig


def floor_of(run):
    """(axis, side, face position) of the wall that gravity points at, or None: no gravity, or
    that side is periodic, an inflow or an outflow. side is -1 (the low face) or +1."""
    gravity = np.array(run.case.get("fluid", {}).get("gravity", [0.0] * run.dimension), float)
    if not np.any(gravity):
        return None
    axis = int(np.argmax(np.abs(gravity)))
    periodic = run.case["domain"].get("periodic", False)
    if (periodic if isinstance(periodic, bool) else periodic[axis]):
        return None
    side = -1 if gravity[axis] < 0 else 1
    name = f"{'xyz'[axis]}_{'low' if side < 0 else 'high'}"
    if run.case.get("boundaries", {}).get(name, "wall") != "wall":
        return None
    face = run.origin[axis] + (0.0 if side < 0 else run.size[axis])
    return axis, side, face


def settling_gap_figure(run):
    """Free bodies under gravity: the speed along gravity and the gap between the body's surface
    and the wall gravity points at, both against time (the ten Cate plots, in any dimension)."""
    if not (run.has_bodies and run.has_free_bodies):
        return None
    floor = floor_of(run)
    if floor is None:
        return None
    axis, side, face = floor
    histories, colours = _body_histories(run)
    free = _free(run, histories)
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.5, 4.0))
    position, velocity = "xyz"[axis], "uvw"[axis]
    few = len(free) <= plots.MANY_BODIES
    for body, h in free.items():
        radius = run.body_radius(body)
        gap = side * (face - h[position]) - radius
        style = {"color": colours[body], "lw": 1.0 if few else 0.5}
        left.plot(h["time"], side * h[velocity], label=f"body {body}" if few else None, **style)
        right.plot(h["time"], gap / (2.0 * radius), **style)
    left.set_xlabel(run.units.label("t", "time"))
    left.set_ylabel(run.units.label(f"speed along gravity ({'−' if side < 0 else '+'}"
                                    f"{position})", "velocity"))
    left.set_title("settling velocity")
    right.set_xlabel(run.units.label("t", "time"))
    right.set_ylabel("gap to the wall / d")
    right.set_title(f"gap to the {position}_{'low' if side < 0 else 'high'} wall")
    right.axhline(0.0, color="k", lw=0.7)
    for ax in (left, right):
        ax.grid(alpha=0.3)
    if few and len(free) > 1:
        left.legend(ncol=2, fontsize="small")
    fig.suptitle(f"{run.title}\nsettling velocity and gap to the wall against time")
    fig.tight_layout()
    return fig


def uhlmann_figure(run):
    """The DKT validation run against Uhlmann (2005), where the digitised data is present."""
    directory = references.uhlmann_directory()
    if directory is None or not references.names_uhlmann(references.case_directory(run.path)):
        return None
    from . import uhlmann

    fig, _ = uhlmann.comparison_figure(run, directory, mirror=None)
    return fig


def figure_makers(run, times=None):
    """(name, function returning a figure or None), in the order they are written."""
    return [
        ("overview", lambda: overview_figure(run)),
        ("solver", lambda: solver_figure(run)),
        ("snapshots", lambda: snapshots_figure(run, times)),
        ("slices", lambda: slices_figure(run)),
        ("samples", lambda: samples_figure(run)),
        ("positions", lambda: positions_figure(run)),
        ("velocities", lambda: velocities_figure(run)),
        ("energy", lambda: energy_figure(run)),
        ("trajectories", lambda: trajectories_figure(run)),
        ("contacts", lambda: contacts_figure(run)),
        ("forces", lambda: forces_figure(run)),
        ("settling", lambda: settling_figure([run])),
        ("settling_gap", lambda: settling_gap_figure(run)),
        ("uhlmann", lambda: uhlmann_figure(run)),
    ]


def save(fig, path_without_extension, formats, dpi=None):
    """Write `fig` in each format (PNG at `dpi`, default STYLE's); returns the paths."""
    paths = []
    for extension in formats:
        path = f"{path_without_extension}.{extension}"
        fig.savefig(path, dpi=dpi or STYLE["savefig.dpi"])
        paths.append(path)
    pyplot().close(fig)
    return paths


def plot_run(run, out_dir, formats=("png",), times=None, only=None, report=print, dpi=None):
    """Write every figure that fits `run` into `out_dir`; returns the paths written."""
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for name, make in figure_makers(run, times):
        if only and name not in only:
            continue
        fig = make()
        if fig is None:
            continue
        paths = save(fig, os.path.join(out_dir, name), formats, dpi)
        for path in paths:
            report(path)
        written += paths
    return written
