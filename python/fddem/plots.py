"""Drawing on matplotlib axes: each function draws one kind of panel and knows nothing about
files. figures.py puts them together for a run; tools/validate.py and the tools' scripts call
them too, so every kind of plot is written once.
"""

import numpy as np
from matplotlib.patches import Circle

from .slices import AXIS_NAMES

# One look for every figure.
STYLE = {
    "figure.dpi": 100,
    "savefig.dpi": 130,
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 7.5,
    "legend.frameon": False,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "lines.linewidth": 1.1,
    "image.cmap": "viridis",
}
REFERENCE_STYLE = {"marker": "o", "ms": 4, "mfc": "none", "ls": "none", "color": "k"}
BODY_FACE, BODY_EDGE = "0.92", "0.1"
MANY_BODIES = 10  # above this many, bodies are coloured by id with a colour bar, not a legend


def body_colours(ids):
    """A colour per body id: tab10 for a few bodies, viridis by id for many."""
    import matplotlib

    ids = list(ids)
    if len(ids) <= MANY_BODIES:
        cycle = matplotlib.colormaps["tab10"]
        return {body: cycle(k % 10) for k, body in enumerate(ids)}
    cmap = matplotlib.colormaps["viridis"]
    top = max(max(ids), 1)
    return {body: cmap(body / top) for body in ids}


def finish_bodies_legend(fig, ax, colours):
    """A legend for a few bodies, a colour bar of the body id for many."""
    import matplotlib

    if len(colours) <= MANY_BODIES:
        ax.legend(ncol=1 if len(colours) <= 4 else 2)
        return
    mappable = matplotlib.cm.ScalarMappable(
        norm=matplotlib.colors.Normalize(0, max(colours)), cmap="viridis")
    fig.colorbar(mappable, ax=ax, label="body id", shrink=0.8)


# --- fields ---------------------------------------------------------------------------------


def flow_field(ax, plane, units, cuts=(), vmax=None, streamlines=1.0, colour="speed"):
    """A plane of the flow: |u| (or the vorticity) in colour, in-plane streamlines, and the bodies
    the plane cuts (slices.bodies_cut_by_plane) as filled circles. `streamlines` is their
    density (matplotlib's streamplot; 0: none). Returns the image."""
    a, b = plane["axes"]
    if colour == "vorticity":
        values = plane["vorticity"]
        limit = vmax or float(np.max(np.abs(values))) or 1.0
        image = ax.imshow(values, origin="lower", extent=plane["extent"], cmap="RdBu_r",
                          vmin=-limit, vmax=limit, interpolation="bilinear")
    else:
        values = plane["speed"]
        image = ax.imshow(values, origin="lower", extent=plane["extent"], vmin=0,
                          vmax=vmax or float(np.max(values)) or 1.0, interpolation="bilinear")
    if streamlines and np.max(np.hypot(plane["ua"], plane["ub"])) > 0:
        ax.streamplot(plane["a"], plane["b"], plane["ua"], plane["ub"], color="w",
                      linewidth=0.5, arrowsize=0.6, density=streamlines)
    draw_bodies(ax, cuts)
    ax.set_xlim(plane["extent"][:2])
    ax.set_ylim(plane["extent"][2:])
    ax.set_aspect("equal")
    ax.grid(False)
    ax.set_xlabel(units.label(AXIS_NAMES[a], "length"))
    ax.set_ylabel(units.label(AXIS_NAMES[b], "length"))
    return image


def draw_bodies(ax, cuts):
    """Bodies as filled circles (`cuts` from slices.bodies_cut_by_plane); returns the patches."""
    patches = []
    for _, a, b, radius in cuts:
        patches.append(ax.add_patch(Circle((a, b), radius, facecolor=BODY_FACE,
                                           edgecolor=BODY_EDGE, lw=0.6, zorder=3)))
    return patches


def centrelines(ax, vertical, horizontal, units, reference=None):
    """Cavity-style centre-line profiles on one axes: u along the vertical centre line (u
    against y) and v along the horizontal one (x against v), with a reference's points.
    `vertical` = (y, u), `horizontal` = (x, v)."""
    ax.plot(vertical[1], vertical[0], color="C0", label="fddem: u on the vertical centre line")
    ax.plot(horizontal[0], horizontal[1], color="C3",
            label="fddem: v on the horizontal centre line")
    if reference is not None:
        ax.plot(reference["u"][1], reference["u"][0], **REFERENCE_STYLE,
                label=f"{reference['label']}: u")
        ax.plot(reference["v"][0], reference["v"][1], **{**REFERENCE_STYLE, "marker": "s"},
                label=f"{reference['label']}: v")
    ax.set_xlabel(f"{units.label('u', 'velocity')}  ·  {units.label('x', 'length')}")
    ax.set_ylabel(f"{units.label('y', 'length')}  ·  {units.label('v', 'velocity')}")
    ax.legend(loc="best")


def wake_axis(ax, x, u, x_rear, units, band=None, band_label=None, scale=1.0):
    """u along a cylinder's wake axis from its rear point, the reference recirculation length
    shaded. `scale` divides the distance (e.g. by D for L/D)."""
    ax.plot((np.asarray(x) - x_rear) / scale, u, label="fddem: u on the wake axis")
    if band is not None:
        ax.axvspan(band[0], band[1], color="k", alpha=0.25, label=band_label)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("(x − x_rear) / D" if scale != 1.0 else
                  units.label("x − x_rear", "length"))
    ax.set_ylabel(units.label("u", "velocity"))
    ax.legend()


def line_sample(ax, name, columns, units):
    """A line sample: each velocity component and p against the distance along the line."""
    points = np.stack([columns[k] for k in ("x", "y", "z") if k in columns], axis=1)
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
    for component in ("u", "v", "w"):
        if component in columns:
            ax.plot(s, columns[component], label=component)
    ax.set_xlabel(units.label(f"distance along {name}", "length"))
    ax.set_ylabel(units.label("velocity", "velocity"))
    twin = ax.twinx()
    twin.plot(s, columns["p"], color="0.4", ls="--", lw=0.9, label="p (right axis)")
    twin.set_ylabel(units.label("p", "pressure"))
    twin.grid(False)
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [line.get_label() for line in lines])


# --- histories ------------------------------------------------------------------------------


def history(ax, t, values, label=None, reference=None, reference_label=None, **style):
    """One quantity against time, with an optional constant reference as a dashed line."""
    ax.plot(t, values, label=label, **style)
    if reference is not None:
        ax.axhline(reference, color="k", ls="--", lw=0.9, label=reference_label)
    if label or reference_label:
        ax.legend()


def body_series(ax, histories, column, colours, ylabel, units, scale=1.0):
    """One column of particles.csv against time, a line per body."""
    for body, h in histories.items():
        ax.plot(h["time"], h[column] / scale, color=colours[body], lw=0.9, label=f"body {body}")
    ax.set_xlabel(units.label("t", "time"))
    ax.set_ylabel(ylabel)


def trajectories(ax, histories, colours, axes, origin, size, units, radii=None):
    """Body centres' paths projected on the plane of `axes` (a, b), in the box: a dot at the
    start and the body drawn at its last position."""
    a, b = axes
    names = {0: "x", 1: "y", 2: "z"}
    for body, h in histories.items():
        ax.plot(h[names[a]], h[names[b]], color=colours[body], lw=0.8, label=f"body {body}")
        ax.plot(h[names[a]][0], h[names[b]][0], "o", ms=2.5, color=colours[body])
        if radii is not None:
            ax.add_patch(Circle((h[names[a]][-1], h[names[b]][-1]), radii[body],
                                facecolor="none", edgecolor=colours[body], lw=0.8))
    ax.set_xlim(origin[a], origin[a] + size[a])
    ax.set_ylim(origin[b], origin[b] + size[b])
    ax.set_aspect("equal")
    ax.set_xlabel(units.label(names[a], "length"))
    ax.set_ylabel(units.label(names[b], "length"))


def contact_events(ax, histories, colours, units):
    """When each body felt a contact force (rows of particles.csv with a non-zero mean contact
    force over the step's DEM sub-steps): a tick per body and row."""
    for body, h in histories.items():
        force = contact_force(h)
        touching = force > 0.0
        ax.plot(h["time"][touching], np.full(np.count_nonzero(touching), body), "|",
                color=colours[body], ms=4, mew=0.8)
    ax.set_xlabel(units.label("t", "time"))
    ax.set_ylabel("body id")
    ax.set_ylim(-0.5, max(histories) + 0.5)
    ax.grid(axis="y", alpha=0.0)


def contact_force(h):
    """|mean contact force| per row of one body's history."""
    components = [h[c] for c in ("contact_fx", "contact_fy", "contact_fz") if c in h]
    return np.sqrt(sum(c**2 for c in components))


def phase_shares(ax, phases, total):
    """Horizontal bars: each phase's share of the wall time of the time loop."""
    names = [n for n in ("momentum", "pressure", "coupling", "contact", "other") if n in phases]
    seconds = np.array([phases[n] for n in names])
    shares = 100.0 * seconds / max(total, seconds.sum(), 1e-300)
    bars = ax.barh(names, shares, color=[f"C{k}" for k in range(len(names))])
    for bar, share, s in zip(bars, shares, seconds):
        ax.text(bar.get_width() + 1, bar.get_y() + bar.get_height() / 2, f"{share:.0f} % ({s:.3g} s)",
                va="center", fontsize=7.5)
    ax.set_xlim(0, 119)
    ax.invert_yaxis()
    ax.set_xlabel("share of the time loop's wall time [%]")
    ax.grid(axis="y", alpha=0.0)
