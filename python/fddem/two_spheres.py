"""Two equal spheres approaching head-on at low Reynolds number: the force on each against the
surface-to-surface gap g, κ(g/r) = F / (6πμrU), U the speed of each sphere (closing speed 2U),
against the exact Stokes-flow solution.

The exact force: by symmetry the mid-plane between the spheres has no normal velocity and no
shear stress, so each sphere approaches a flat free plane at the gap δ = g/2, and
κ = κ_free(δ/r), Brenner's (1961) free-surface series (sphere_wall.free_plane_kappa; derivation
of the equivalence and the limits in cases/validation/rebound_stokes/two_spheres_free_surface.md).
Its limits, in g:
- near contact (Jeffrey & Onishi 1984, X^A_11 − X^A_12 for equal spheres, the singular terms
  doubled by the squeezing): κ ≈ r/(2g) + (9/20) ln(r/g) + C, C = 1.3456 (the series' own value
  at g/r = 2e-5; Jeffrey & Onishi's tabulated A^X_11 − A^X_12 agrees, quoted from memory in the
  note above);
- far apart: the other sphere's Stokeslet, κ = 1/(1 − (3/4) r/H) ≈ 1 + (3/4) r/H + (9/16)(r/H)²,
  H = r + g/2 the distance from a centre to the mid-plane.

fddem's pair lubrication (src/fddem/contact/lubrication.cpp) for equal spheres is 6πμr
[(1/4)(r/g) + (9/40) ln(r/g)] times the closing speed 2U: the near-contact form without C.

A run (cases/validation/two_sphere_approach; tools/compare_sphere_wall.py) moves two prescribed
spheres at ±U along one axis. Each sphere's rows are compared as the wall case's are
(sphere_wall.force_parts): the resolved force (f*) at the gap where the step began, g + 2UΔt,
the lubrication (lubrication_f*, the mean over the DEM sub-steps) at mid-step, g + UΔt.
"""

import math
import os

import numpy as np

from . import io
from .sphere_wall import axis_name, force_parts, free_plane_kappa, kappa_table, per_row

LABEL = "exact (Brenner 1961 free plane at δ = g/2)"
# The gaps of the comparison table (g/r, surface to surface), from the far field into the
# lubrication range (2 h = g/r 0.5 at d/h = 8); the case's last resolved force is at 0.0625.
TABLE_RATIOS = (4.0, 2.0, 1.0, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.07)
NEAR_CONTACT_CONSTANT = 1.3456


def exact_kappa(gap_over_r):
    """κ of each of two equal spheres closing head-on at surface gap g/r: κ_free(g/(2r))."""
    return free_plane_kappa(0.5 * np.asarray(gap_over_r, dtype=float))


def near_contact_kappa(gap_over_r):
    """r/(2g) + (9/20) ln(r/g) + C, the series' near-contact form (module docstring)."""
    x = np.asarray(gap_over_r, dtype=float)
    return 0.5 / x - 0.45 * np.log(x) + NEAR_CONTACT_CONSTANT


def far_field_kappa(gap_over_r):
    """1 + (3/4) r/H + (9/16)(r/H)², H = r + g/2 (the reflection of the other sphere)."""
    x = 1.0 / (1.0 + 0.5 * np.asarray(gap_over_r, dtype=float))
    return 1.0 + 0.75 * x + 9.0 / 16.0 * x * x


def run_parameters(run_dir):
    """μ, r, |U|, the axis, Δt, the lubrication range (grid spacings; None when off) and the
    two bodies' directions (±1 along the axis, in particles.csv's id order), from case.toml.
    Checks the set-up: two spheres of one diameter moving at ±U along one axis toward each
    other."""
    case = io.read_case(run_dir)
    bodies = case.get("bodies", [])
    if len(bodies) != 2 or bodies[0]["diameter"] != bodies[1]["diameter"]:
        raise ValueError(f"{run_dir}: needs two spheres of one diameter")
    velocities = [np.asarray(b["velocity"], dtype=float) for b in bodies]
    axis = int(np.argmax(np.abs(velocities[0])))
    speed = float(abs(velocities[0][axis]))
    positions = [np.asarray(b["position"], dtype=float) for b in bodies]
    directions = [math.copysign(1.0, v[axis]) for v in velocities]
    moving_apart = directions[0] * (positions[1][axis] - positions[0][axis]) < 0.0
    if (speed == 0.0 or any(not np.allclose(np.delete(v, axis), 0.0) for v in velocities)
            or not np.allclose(velocities[0], -velocities[1]) or moving_apart):
        raise ValueError(f"{run_dir}: the spheres must approach at ±U along one axis")
    lubrication = case.get("lubrication", {})
    return {"viscosity": float(case["fluid"]["viscosity"]),
            "radius": 0.5 * float(bodies[0]["diameter"]), "speed": speed, "axis": axis,
            "directions": directions, "dt": float(case["time"]["dt"]),
            "range": float(lubrication.get("range", 2.0)) if lubrication.get("enabled") else None}


def approach_histories(run_dir):
    """Per sphere (in id order), per row after t = 0: the surface gap of the row (g/r, the end
    of the step) and force_parts() with gaps in g/r; each with the run_parameters()."""
    p = run_parameters(run_dir)
    rows = io.read_particles(run_dir)
    ids = sorted(rows)
    name = axis_name(rows[ids[0]], p["axis"])
    if not np.array_equal(rows[ids[0]]["time"], rows[ids[1]]["time"]):
        raise ValueError(f"{run_dir}: the two spheres' rows are not at the same times")
    keep = rows[ids[0]]["time"] > 0.0
    r = p["radius"]
    drag = 6.0 * math.pi * p["viscosity"] * r * p["speed"]
    histories = []
    for k, direction in zip(ids, p["directions"]):
        other = ids[1] if k == ids[0] else ids[0]
        gap = direction * (rows[other][name][keep] - rows[k][name][keep]) - 2.0 * r
        h = force_parts(rows[k], name, direction, gap / r, 2.0 * p["speed"] * p["dt"] / r, drag)
        h.update({"id": k, "gap": gap / r, "parameters": p})
        histories.append(h)
    return histories


def kappa_at(run_dir, ratios=TABLE_RATIOS):
    """sphere_wall.kappa_table() of each sphere against the exact κ at the gaps `ratios` (g/r):
    a list, in id order."""
    return [kappa_table(h, exact_kappa, ratios) for h in approach_histories(run_dir)]


def asymmetry(run_dir, smallest_gap=0.05):
    """The largest |κ_1 − κ_2| / ((κ_1 + κ_2)/2) of the resolved forces (f*) and of the
    lubrication, row by row, over the rows with g/r ≥ `smallest_gap`: by symmetry the two
    forces are equal and opposite."""
    first, second = approach_histories(run_dir)
    keep = first["gap"] >= smallest_gap

    def largest(key):
        a, b = first[key][keep], second[key][keep]
        mean = 0.5 * (a + b)
        inside = mean != 0.0
        return float(np.max(np.abs(a - b)[inside] / mean[inside])) if np.any(inside) else 0.0

    return {"hydro": largest("kappa_hydro"), "lubrication": largest("kappa_lub")}


def plot(axes, run_dirs, labels=None):
    """Two panels of every run, both spheres: κ against g/r (log-log; exact, resolved part
    dashed, total solid) and κ / κ_exact (shaded ±10 %); the lubrication range g = h_Δ dotted."""
    top, bottom = axes
    labels = labels or [os.path.basename(os.path.normpath(r)) for r in run_dirs]
    covered = []
    for run, label in zip(run_dirs, labels):
        for h, marker in zip(approach_histories(run), ("o", "x")):
            row = per_row(h, exact_kappa)
            covered += [row["gap"].min(), row["gap"].max()]
            name = f"{label}, sphere {h['id']}"
            (line,) = top.plot(row["gap"], row["total"], marker=marker, ms=4, markevery=0.08,
                               lw=1, label=f"{name}: total")
            top.plot(row["gap"], row["hydro"], "--", color=line.get_color(), lw=1,
                     label=f"{name}: resolved")
            bottom.plot(row["gap"], row["total"] / row["exact"], marker=marker, ms=4,
                        markevery=0.08, lw=1, color=line.get_color(), label=f"{name}: total")
            bottom.plot(row["gap"], row["hydro"] / row["exact"], "--", lw=1,
                        color=line.get_color(), label=f"{name}: resolved")
        p = run_parameters(run)
        if p["range"] is not None:
            domain = io.read_case(run)["domain"]
            spacing = domain["size"][p["axis"]] / domain["cells"][p["axis"]]
            for a in axes:
                a.axvline(p["range"] * spacing / p["radius"], color="0.5", ls=":", lw=1)
    gaps = np.geomspace(min(covered), max(covered), 200)
    top.plot(gaps, exact_kappa(gaps), "k", lw=1.5, label=LABEL)
    top.set_yscale("log")
    top.set_ylabel("κ = F / (6πμrU)")
    bottom.axhline(1.0, color="k", lw=1)
    bottom.axhspan(0.9, 1.1, color="0.92", zorder=0)
    bottom.set_ylabel("κ / κ_exact")
    for a in axes:
        a.set_xscale("log")
    bottom.set_xlabel("g/r (surface-to-surface gap / radius; dotted: lubrication range h_Δ)")
