"""A sphere approaching a plane wall at low Reynolds number: the force against the gap,
κ(δ/r) = F / (6πμ r U), against Brenner's (1961) exact Stokes-flow series.

Brenner, H. (1961), "The slow motion of a sphere through a viscous fluid towards a plane
surface", Chem. Eng. Sci. 16, 242-251. The series (r the radius, δ the gap between the sphere's
surface and the wall, α = arccosh(1 + δ/r)):

    κ = (4/3) sinh α Σ_{n≥1} n(n+1)/((2n−1)(2n+3))
          · [ (2 sinh((2n+1)α) + (2n+1) sinh 2α) / (4 sinh²((n+½)α) − (2n+1)² sinh²α) − 1 ]

as written in ../shared/reference/sphere_wall.md of the project (read there from A. Ghigo's
Basilisk test sandbox/ghigo/src/test-stokes/sphere-towards-wall.c, with a table of κ that the
unit test checks this sum against). Lubrication limit (Cooley & O'Neill 1969):
κ ≈ r/δ − (1/5) ln(δ/r) + 0.97128.

A run (cases/validation/sphere_wall_approach) moves one prescribed sphere at a constant U toward
a no-slip wall. From particles.csv and case.toml:
- κ_hydro = −f·Û / (6πμrU), the resolved flow's force against the motion (the f* columns);
- κ_lub = −lubrication_f·Û / (6πμrU), the lubrication correction (zero when it is off).
The two are not taken at the same gap. A step's fluid solve sees the markers where the step
began (fddem moves the bodies, eq. (17), after the outer iterations). So the f* of the row at
t^{n+1} belongs to δ^n = δ^{n+1} + |U|Δt. The lubrication is the mean over the DEM sub-steps
from δ^n to δ^{n+1}, which is close to the mid-step gap δ^{n+1} + |U|Δt/2. Each part is
interpolated (linearly in ln δ) onto the compared gaps at its own positions; the total is
their sum.
"""

import math
import os

import numpy as np

from . import io

LABEL = "Brenner (1961), exact"
# The gaps of the comparison table (δ/r), from the far field into the lubrication range.
TABLE_RATIOS = (2.0, 1.0, 0.5, 0.3, 0.2, 0.1, 0.05)


def brenner_kappa(delta_over_r, tolerance=1e-15, max_terms=1_000_000):
    """Brenner's (1961) κ = F/(6πμrU) at gap δ/r (a number or an array), summed until a term
    changes the sum by less than `tolerance` (relative). The terms decay as exp(−(2n+1)α), so
    δ/r = 0.01 (α = 0.14) needs about 130 terms. Written with e^{−x}, x = (2n+1)α, so that no
    sinh overflows."""
    ratios = np.atleast_1d(np.asarray(delta_over_r, dtype=float))
    if np.any(ratios <= 0.0):
        raise ValueError("Brenner's series needs a gap δ/r > 0")
    out = np.array([_brenner_one(x, tolerance, max_terms) for x in ratios])
    return out if np.ndim(delta_over_r) else float(out[0])


def _brenner_one(ratio, tolerance, max_terms):
    alpha = math.acosh(1.0 + ratio)
    sinh_2a = math.sinh(2.0 * alpha)
    sinh_a2 = math.sinh(alpha) ** 2
    total = 0.0
    for n in range(1, max_terms + 1):
        m = 2 * n + 1
        e1 = math.exp(-m * alpha)  # e^{−x}
        # bracket = (2 sinh x + m sinh 2α) / (2 cosh x − 2 − m² sinh²α) − 1, times e^x above
        # and below: (1 − e^{−2x} + m sinh2α e^{−x}) / (1 + e^{−2x} − 2e^{−x} − m² sinh²α e^{−x}).
        numerator = 2.0 * e1 - 2.0 * e1 * e1 + e1 * (m * sinh_2a + m * m * sinh_a2)
        denominator = 1.0 + e1 * e1 - 2.0 * e1 - m * m * sinh_a2 * e1
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * numerator / denominator
        total += term
        if abs(term) < tolerance * abs(total) and m * alpha > 10.0:
            return 4.0 / 3.0 * math.sinh(alpha) * total
    raise ValueError(f"Brenner's series did not converge in {max_terms} terms at δ/r = {ratio}")


def cooley_oneill_kappa(delta_over_r):
    """The lubrication limit κ ≈ r/δ − (1/5) ln(δ/r) + 0.97128 (Cooley & O'Neill 1969)."""
    x = np.asarray(delta_over_r, dtype=float)
    return 1.0 / x - 0.2 * np.log(x) + 0.97128


def run_parameters(run_dir):
    """μ, r, the speed |U|, the axis of the motion, the wall's coordinate on it, Δt and
    the lubrication range in grid spacings (None when off), from the run's case.toml."""
    case = io.read_case(run_dir)
    body = case["bodies"][0]
    velocity = np.asarray(body["velocity"], dtype=float)
    axis = int(np.argmax(np.abs(velocity)))
    speed = float(abs(velocity[axis]))
    if speed == 0.0 or not np.allclose(np.delete(velocity, axis), 0.0):
        raise ValueError(f"{run_dir}: the sphere must move along one axis toward a wall")
    origin = np.asarray(case["domain"].get("origin", [0.0] * len(velocity)), dtype=float)
    size = np.asarray(case["domain"]["size"], dtype=float)
    wall = origin[axis] if velocity[axis] < 0.0 else origin[axis] + size[axis]
    lubrication = case.get("lubrication", {})
    return {"viscosity": float(case["fluid"]["viscosity"]), "radius": 0.5 * float(body["diameter"]),
            "speed": speed, "axis": axis, "direction": math.copysign(1.0, velocity[axis]),
            "wall": float(wall), "dt": float(case["time"]["dt"]),
            "range": float(lubrication.get("range", 2.0)) if lubrication.get("enabled") else None}


def approach_history(run_dir):
    """Per row after t = 0: the gap of the row (δ/r, the end of the step), κ_hydro and the gap
    it belongs to (the start of the step), κ_lub and its gap (mid-step), as arrays."""
    p = run_parameters(run_dir)
    body = io.read_particles(run_dir)
    body = body[min(body)]
    names = "xyz"[: 3 if "z" in body else 2]
    name = names[p["axis"]]
    keep = body["time"] > 0.0
    centre = body[name][keep]
    gap = (centre - p["wall"]) * -p["direction"] - p["radius"]  # δ, positive while apart
    drag = 6.0 * math.pi * p["viscosity"] * p["radius"] * p["speed"]
    step = p["speed"] * p["dt"]
    against = -p["direction"]  # the force resisting the motion is along −Û
    lubrication = body.get(f"lubrication_f{name}", np.zeros_like(body[f"f{name}"]))
    return {"gap": gap / p["radius"],
            "hydro_gap": (gap + step) / p["radius"],
            "kappa_hydro": against * body[f"f{name}"][keep] / drag,
            "lub_gap": (gap + 0.5 * step) / p["radius"],
            "kappa_lub": against * lubrication[keep] / drag,
            "parameters": p}


def _interpolate_log(x, xs, ys):
    """ys(xs) at x, linear in ln δ; NaN outside the covered gaps."""
    order = np.argsort(xs)
    lx = np.log(np.asarray(xs)[order])
    out = np.interp(np.log(x), lx, np.asarray(ys)[order], left=np.nan, right=np.nan)
    return out


def kappa_at(run_dir, ratios=TABLE_RATIOS):
    """κ_hydro, κ_lub, their sum and Brenner's at the gaps `ratios` (δ/r) the run covered (NaN
    where it did not), and the ratios total/Brenner and hydro/Brenner, as a dict of arrays."""
    h = approach_history(run_dir)
    x = np.asarray(ratios, dtype=float)
    hydro = _interpolate_log(x, h["hydro_gap"], h["kappa_hydro"])
    lub = _interpolate_log(x, h["lub_gap"], h["kappa_lub"])
    brenner = brenner_kappa(x)
    total = hydro + lub
    return {"delta_over_r": x, "hydro": hydro, "lubrication": lub, "total": total,
            "brenner": brenner, "ratio": total / brenner, "hydro_ratio": hydro / brenner}


def deviation(result, window=(0.1, 2.0)):
    """The largest |κ/κ_Brenner − 1| (signed) of kappa_at()'s result over the gaps in `window`
    that the run covered, and where."""
    x = result["delta_over_r"]
    inside = (x >= window[0]) & (x <= window[1]) & np.isfinite(result["ratio"])
    if not np.any(inside):
        raise ValueError(f"the run covers no compared gap in δ/r {window}")
    relative = result["ratio"][inside] - 1.0
    worst = int(np.argmax(np.abs(relative)))
    return {"max": float(relative[worst]), "max_at": float(x[inside][worst]),
            "points": int(np.count_nonzero(inside))}


def plot(axes, run_dirs, labels=None):
    """κ/κ_Brenner against δ/r of every run: the total (solid) and the resolved part alone
    (dashed, where the lubrication is on), the range h_Δ of each run marked."""
    labels = labels or [os.path.basename(os.path.normpath(r)) for r in run_dirs]
    for run, label in zip(run_dirs, labels):
        h = approach_history(run)
        hydro_ratio = h["kappa_hydro"] / brenner_kappa(h["hydro_gap"])
        lub = _interpolate_log(h["hydro_gap"], h["lub_gap"], h["kappa_lub"])
        lub = np.where(np.isfinite(lub), lub, 0.0)
        total_ratio = (h["kappa_hydro"] + lub) / brenner_kappa(h["hydro_gap"])
        (line,) = axes.plot(h["hydro_gap"], total_ratio, label=f"fddem {label}")
        p = h["parameters"]
        if p["range"] is not None:
            axes.plot(h["hydro_gap"], hydro_ratio, "--", color=line.get_color(), lw=1,
                      label=f"{label}: resolved part")
    axes.axhline(1.0, color="k", lw=1, label=LABEL)
    axes.axhspan(0.9, 1.1, color="0.92", zorder=0)
    axes.set_xscale("log")
    axes.set_xlabel("δ/r (gap / radius)")
    axes.set_ylabel("κ / κ_Brenner,  κ = F / (6πμrU)")
