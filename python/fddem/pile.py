"""A pile of balls settled from random insertion: the soak of issues 14 and 16
(cases/validation/sphere_pile_soak, tools/check_pile.py).

What a soak asks of a long run with many contacts, each measured from the run's own files:
- no blow-up: the run completed (summary.json status);
- no escape: every centre inside the box at every output of particles.csv, and the same number of
  bodies at every output as at the first;
- contact overlaps below a bound, relative to the radius: the largest over every DEM sub-step
  (summary.json max_relative_overlap), and, as a cross-check from the positions alone, the largest
  ball–ball and ball–wall overlap at the outputs;
- at rest: every free body slower than time.rest_speed (|U| + |ω|R) at the end, the run having
  ended on that criterion (summary.json at_rest_since).

One diameter for all bodies (a single [[bodies]] entry), as in the soak's case.
"""
import numpy as np

from . import io

SPEED_COLUMNS = ("u", "v", "w")
OMEGA_COLUMNS_3D = ("omega_x", "omega_y", "omega_z")


class PileError(ValueError):
    """A run the pile checks cannot read (named in the message)."""


def _radius(case):
    diameters = {entry.get("diameter") for entry in case.get("bodies", [])}
    if len(diameters) != 1 or None in diameters:
        raise PileError("the pile checks need one [[bodies]] diameter shared by every body, "
                        f"got {sorted(str(d) for d in diameters)}")
    return 0.5 * float(diameters.pop())


def box(case):
    """(lower corner, upper corner, periodic flags) of the case's domain."""
    domain = case["domain"]
    size = np.asarray(domain["size"], dtype=float)
    origin = np.asarray(domain.get("origin", [0.0] * len(size)), dtype=float)
    periodic = np.asarray(domain.get("periodic", [False] * len(size)), dtype=bool)
    return origin, origin + size, periodic


def frames(run_dir):
    """The outputs of particles.csv: times (n,), ids (m,), centres (n, m, dim) and speeds
    |U| + |ω|R (n, m). Raises PileError when the outputs do not all hold the same bodies."""
    case = io.read_case(run_dir)
    radius = _radius(case)
    dim = len(case["domain"]["size"])
    rows = io.read_particle_rows(run_dir)
    times = np.unique(rows["time"])
    ids = np.unique(rows["id"].astype(int))
    counts = np.array([np.count_nonzero(rows["time"] == t) for t in times])
    if np.any(counts != len(ids)):
        worst = int(np.argmax(np.abs(counts - len(ids))))
        raise PileError(f"{run_dir}/particles.csv: {counts[worst]} bodies at t = {times[worst]:g}, "
                        f"{len(ids)} in the whole run: a body appeared or went missing")
    order = np.lexsort((rows["id"], rows["time"]))
    axes = ("x", "y", "z")[:dim]
    centres = np.stack([rows[a][order] for a in axes], axis=-1).reshape(len(times), len(ids), dim)
    velocity = np.stack([rows[c][order] for c in SPEED_COLUMNS[:dim]], axis=-1)
    if dim == 3:
        omega = np.linalg.norm(np.stack([rows[c][order] for c in OMEGA_COLUMNS_3D], axis=-1), axis=-1)
    else:
        omega = np.abs(rows["omega"][order])
    speeds = (np.linalg.norm(velocity, axis=-1) + omega * radius).reshape(len(times), len(ids))
    return times, ids, centres, speeds


def largest_overlaps(centres, radius, low, high, periodic):
    """Per output, the largest ball–ball and ball–wall overlap over the radius (0 if none).
    centres: (n, m, dim). Pairs are taken across periodic sides by the nearest image."""
    length = high - low
    pair = np.zeros(len(centres))
    wall = np.zeros(len(centres))
    upper = np.triu_indices(centres.shape[1], k=1)
    for k, x in enumerate(centres):
        d = x[:, None, :] - x[None, :, :]
        d -= np.where(periodic, np.round(d / length) * length, 0.0)
        distance = np.linalg.norm(d, axis=-1)[upper]
        pair[k] = max(0.0, float(np.max(2.0 * radius - distance, initial=0.0))) / radius
        bounded = ~periodic
        if np.any(bounded):
            clearance = np.minimum(x[:, bounded] - low[bounded], high[bounded] - x[:, bounded])
            wall[k] = max(0.0, float(radius - np.min(clearance))) / radius
    return pair, wall


def outside_box(centres, low, high, periodic):
    """Per output, how many centres are outside the box along a side that is not periodic."""
    bounded = ~periodic
    out = (centres[..., bounded] < low[bounded]) | (centres[..., bounded] > high[bounded])
    return np.count_nonzero(np.any(out, axis=-1), axis=-1)


def measure(run_dir):
    """Everything the checks read, as a dict."""
    case = io.read_case(run_dir)
    summary = io.read_summary(run_dir)
    radius = _radius(case)
    low, high, periodic = box(case)
    times, ids, centres, speeds = frames(run_dir)
    pair, wall = largest_overlaps(centres, radius, low, high, periodic)
    rest_speed = case.get("time", {}).get("rest_speed")
    rest_duration = case.get("time", {}).get("rest_duration", 0.1)
    gravity = np.asarray(case.get("fluid", {}).get("gravity", [0.0] * len(low)), dtype=float)
    up = -gravity / np.linalg.norm(gravity) if np.any(gravity) else None
    height = float(np.max(centres[-1] @ up) - low @ up + radius) if up is not None else None
    return {
        "radius": radius,
        "bodies": len(ids),
        "outputs": len(times),
        "times": times,
        "status": summary.get("status"),
        "end_time": summary.get("time"),
        "max_relative_overlap": summary.get("max_relative_overlap"),
        "max_overlap_time": summary.get("max_overlap_time"),
        "pair_overlap": pair,
        "wall_overlap": wall,
        "outside": outside_box(centres, low, high, periodic),
        "max_speed": np.max(speeds, axis=1),
        "rest_speed": rest_speed,
        "at_rest_since": summary.get("at_rest_since"),
        "rest_duration": rest_duration,
        "pile_height": height,
        "centres": centres,
    }


def checks(run_dir, overlap_bound=0.01):
    """The soak's checks: (quantity, measured, reference, tolerance, source) per line, as
    tools/validate.py takes them (a line passes when |measured − reference| ≤ tolerance)."""
    m = measure(run_dir)
    issue = "issues 14 and 16: the soak's bound"
    lines = [
        ("run completed (1) or not (0)", 1.0 if m["status"] == "completed" else 0.0, 1.0, 0.0,
         "no blow-up"),
        ("largest contact overlap / r, every DEM sub-step", m["max_relative_overlap"] or 0.0, 0.0,
         overlap_bound, issue),
        ("largest overlap / r at the outputs, from the positions",
         float(max(np.max(m["pair_overlap"]), np.max(m["wall_overlap"]))), 0.0, overlap_bound,
         f"{issue}; a cross-check of the line above from particles.csv alone"),
        ("centres outside the box, any output", float(np.max(m["outside"])), 0.0, 0.0,
         "no escape"),
    ]
    if m["rest_speed"] is not None:
        lines.append(("fastest body at the end / time.rest_speed", float(m["max_speed"][-1]) /
                      m["rest_speed"], 0.0, 1.0, "at rest: every body below time.rest_speed"))
        ended_at_rest = (m["status"] == "completed" and m["at_rest_since"] is not None and
                         m["end_time"] - m["at_rest_since"] >= m["rest_duration"] * (1 - 1e-9))
        lines.append(("ended at rest (1) or not (0)", 1.0 if ended_at_rest else 0.0, 1.0, 0.0,
                      "the run completed and stopped on time.rest_speed: every body below it "
                      "for time.rest_duration"))
    return lines


def plot_side(axes, run_dir):
    """The final pile seen from the side: the first horizontal axis against the vertical, the
    balls drawn at their radius, the nearest last."""
    import matplotlib.patches

    m = measure(run_dir)
    low, high, _ = box(io.read_case(run_dir))
    x = m["centres"][-1]
    vertical = len(low) - 1
    depth = x[:, 1] if len(low) == 3 else x[:, 0]
    for centre in x[np.argsort(-depth)]:
        axes.add_patch(matplotlib.patches.Circle((centre[0], centre[vertical]), m["radius"],
                                                 facecolor="tab:blue", edgecolor="k", lw=0.3, alpha=0.6))
    axes.set_xlim(low[0], high[0])
    axes.set_ylim(low[vertical], high[vertical])
    axes.set_aspect("equal")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("z [m]" if len(low) == 3 else "y [m]")
    axes.set_title(f"{m['bodies']} bodies at t = {m['times'][-1]:.3g} s", fontsize=8)


def plot_history(axes, run_dir, overlap_bound=0.01):
    """The fastest body's |U| + |ω|R and the largest overlap / r at the outputs against time,
    with time.rest_speed and the overlap bound."""
    m = measure(run_dir)
    axes.semilogy(m["times"], np.maximum(m["max_speed"], 1e-12), label="fastest |U| + |ω|R [m/s]")
    if m["rest_speed"] is not None:
        axes.axhline(m["rest_speed"], color="tab:blue", ls=":", label="time.rest_speed")
    overlap = np.maximum(m["pair_overlap"], m["wall_overlap"])
    touching = overlap > 0
    axes.semilogy(m["times"][touching], overlap[touching], ".", ms=2, color="tab:red",
                  label="largest overlap / r (outputs)")
    axes.axhline(overlap_bound, color="tab:red", ls=":", label=f"bound {overlap_bound:g} r")
    axes.set_xlabel("t [s]")
    axes.legend(fontsize=6)
