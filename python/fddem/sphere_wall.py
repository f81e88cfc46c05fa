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
    return _summed(delta_over_r, _wall_bracket, tolerance, max_terms)


def free_plane_kappa(delta_over_r, tolerance=1e-15, max_terms=1_000_000):
    """κ = F/(6πμrU) of a sphere approaching a flat shear-free plane at gap δ/r (Brenner 1961,
    the free-surface series; cases/validation/rebound_stokes/two_spheres_free_surface.md):

        κ = (4/3) sinh α Σ n(n+1)/((2n−1)(2n+3))
              · [ (4 cosh²((n+½)α) + (2n+1)² sinh²α) / (2 sinh((2n+1)α) − (2n+1) sinh 2α) − 1 ]

    It is also the force on each of two equal spheres closing head-on at ±U with surface gap
    2δ: the mid-plane is then shear-free with no normal velocity (python/fddem/two_spheres.py).
    Summed as brenner_kappa() is."""
    return _summed(delta_over_r, _free_bracket, tolerance, max_terms)


def _wall_bracket(m, e1, sinh_2a, sinh_a2):
    """The rigid wall's bracket (2 sinh x + m sinh 2α)/(2 cosh x − 2 − m² sinh²α) − 1, x = mα,
    as (numerator − denominator, denominator) after multiplying both by e^{−x} = e1:
    (1 − e^{−2x} + m sinh2α e^{−x}) / (1 + e^{−2x} − 2e^{−x} − m² sinh²α e^{−x})."""
    numerator = 2.0 * e1 - 2.0 * e1 * e1 + e1 * (m * sinh_2a + m * m * sinh_a2)
    denominator = 1.0 + e1 * e1 - 2.0 * e1 - m * m * sinh_a2 * e1
    return numerator, denominator


def _free_bracket(m, e1, sinh_2a, sinh_a2):
    """The free plane's bracket (2 cosh x + 2 + m² sinh²α)/(2 sinh x − m sinh 2α) − 1
    (4 cosh²(x/2) = 2 cosh x + 2), times e^{−x} above and below:
    (1 + e^{−2x} + (2 + m² sinh²α) e^{−x}) / (1 − e^{−2x} − m sinh2α e^{−x})."""
    numerator = 2.0 * e1 * e1 + e1 * (2.0 + m * m * sinh_a2 + m * sinh_2a)
    denominator = 1.0 - e1 * e1 - m * sinh_2a * e1
    return numerator, denominator


def _summed(delta_over_r, bracket, tolerance, max_terms):
    ratios = np.atleast_1d(np.asarray(delta_over_r, dtype=float))
    if np.any(ratios <= 0.0):
        raise ValueError("Brenner's series needs a gap δ/r > 0")
    out = np.array([_series(x, bracket, tolerance, max_terms) for x in ratios])
    return out if np.ndim(delta_over_r) else float(out[0])


def _series(ratio, bracket, tolerance, max_terms):
    """(4/3) sinh α Σ_{n≥1} n(n+1)/((2n−1)(2n+3)) · bracket_n, α = arccosh(1 + δ/r)."""
    alpha = math.acosh(1.0 + ratio)
    sinh_2a = math.sinh(2.0 * alpha)
    sinh_a2 = math.sinh(alpha) ** 2
    total = 0.0
    for n in range(1, max_terms + 1):
        m = 2 * n + 1
        numerator, denominator = bracket(m, math.exp(-m * alpha), sinh_2a, sinh_a2)
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
    name = axis_name(body, p["axis"])
    keep = body["time"] > 0.0
    gap = (body[name][keep] - p["wall"]) * -p["direction"] - p["radius"]  # δ, positive while apart
    h = force_parts(body, name, p["direction"], gap, p["speed"] * p["dt"],
                    6.0 * math.pi * p["viscosity"] * p["radius"] * p["speed"])
    h.update({"gap": gap / p["radius"], "hydro_gap": h["hydro_gap"] / p["radius"],
              "lub_gap": h["lub_gap"] / p["radius"], "parameters": p})
    return h


def axis_name(body, axis):
    """The particles.csv column of the coordinate along `axis` (x, y or z)."""
    return "xyz"[: 3 if "z" in body else 2][axis]


def force_parts(body, name, direction, gap, closure, drag):
    """κ of one body's rows after t = 0 (particles.csv columns `body`, moving along the axis
    `name` in `direction` ±1) whose gaps at the end of the steps are `gap`, closing by `closure`
    per step: κ_hydro = the resolved force against the motion (f*) / `drag` at the gap where
    the step began, gap + closure; κ_lub = the lubrication correction (lubrication_f*) /
    `drag` at mid-step, gap + closure/2 (the gaps in the units of `gap`)."""
    keep = body["time"] > 0.0
    against = -direction  # the force resisting the motion is along −Û
    lubrication = body.get(f"lubrication_f{name}", np.zeros_like(body[f"f{name}"]))
    return {"hydro_gap": gap + closure, "kappa_hydro": against * body[f"f{name}"][keep] / drag,
            "lub_gap": gap + 0.5 * closure, "kappa_lub": against * lubrication[keep] / drag}


def interpolate_log(x, xs, ys):
    """ys(xs) at x, linear in ln δ; NaN outside the covered gaps."""
    order = np.argsort(xs)
    lx = np.log(np.asarray(xs)[order])
    out = np.interp(np.log(x), lx, np.asarray(ys)[order], left=np.nan, right=np.nan)
    return out


def kappa_table(history, exact, ratios):
    """A history's (approach_history()) κ_hydro and κ_lub, each interpolated in ln gap from its
    own gaps onto `ratios`, their sum and the exact κ = exact(ratios), with the ratios
    total/exact and hydro/exact; NaN where the run did not reach. A dict of arrays."""
    x = np.asarray(ratios, dtype=float)
    hydro = interpolate_log(x, history["hydro_gap"], history["kappa_hydro"])
    lub = interpolate_log(x, history["lub_gap"], history["kappa_lub"])
    reference = exact(x)
    total = hydro + lub
    return {"gap_over_r": x, "hydro": hydro, "lubrication": lub, "total": total,
            "exact": reference, "ratio": total / reference, "hydro_ratio": hydro / reference}


def kappa_at(run_dir, ratios=TABLE_RATIOS):
    """kappa_table() of the run against Brenner at the gaps `ratios` (δ/r); also under the
    names delta_over_r and brenner."""
    r = kappa_table(approach_history(run_dir), brenner_kappa, ratios)
    r.update({"delta_over_r": r["gap_over_r"], "brenner": r["exact"]})
    return r


def deviation(result, window=(0.1, 2.0)):
    """The largest |κ/κ_exact − 1| (signed) of a kappa_table() result over the gaps in `window`
    that the run covered, and where."""
    x = result["gap_over_r"]
    inside = (x >= window[0]) & (x <= window[1]) & np.isfinite(result["ratio"])
    if not np.any(inside):
        raise ValueError(f"the run covers no compared gap in δ/r {window}")
    relative = result["ratio"][inside] - 1.0
    worst = int(np.argmax(np.abs(relative)))
    return {"max": float(relative[worst]), "max_at": float(x[inside][worst]),
            "points": int(np.count_nonzero(inside))}


def per_row(history, exact):
    """Each row's κ at the gap its resolved force belongs to (the start of the step): that gap,
    κ_hydro, the total (κ_lub interpolated onto it; 0 where the run has none yet) and the exact
    κ = exact(gap)."""
    gap = history["hydro_gap"]
    lub = interpolate_log(gap, history["lub_gap"], history["kappa_lub"])
    total = history["kappa_hydro"] + np.where(np.isfinite(lub), lub, 0.0)
    return {"gap": gap, "hydro": history["kappa_hydro"], "total": total, "exact": exact(gap)}


def table_lines(result, label, window=(0.1, 2.0), gap_name="δ/r", exact_name="Brenner"):
    """A kappa_table() result as text lines: the largest deviation of the total over `window`,
    then per gap κ_hydro, κ_lub, the total, the exact κ, total/exact, hydro/exact and
    exact − κ_lub (what the correction assumes the grid resolves, to set beside κ_hydro)."""
    worst = deviation(result, window)
    lines = [f"{label}: largest deviation of the total over {window[0]:g} <= {gap_name} <= "
             f"{window[1]:g}: {100 * worst['max']:+.1f} % at {gap_name} = {worst['max_at']:g}",
             f"  {gap_name:>5s} {'κ_hydro':>8s} {'κ_lub':>8s} {'κ_total':>8s} {exact_name:>8s} "
             f"{'total/ex':>8s} {'hydro/ex':>8s} {'ex − lub':>8s}"]
    for k, x in enumerate(result["gap_over_r"]):
        cells = [result[name][k] for name in ("hydro", "lubrication", "total", "exact", "ratio",
                                              "hydro_ratio")]
        cells.append(result["exact"][k] - result["lubrication"][k])
        lines.append(f"  {x:5.2f} " + " ".join("     n/a" if not np.isfinite(c) else f"{c:8.4f}"
                                               for c in cells))
    return lines


def plot(axes, run_dirs, labels=None):
    """κ/κ_Brenner against δ/r of every run: the total (solid) and the resolved part alone
    (dashed, where the lubrication is on)."""
    labels = labels or [os.path.basename(os.path.normpath(r)) for r in run_dirs]
    for run, label in zip(run_dirs, labels):
        h = approach_history(run)
        row = per_row(h, brenner_kappa)
        (line,) = axes.plot(row["gap"], row["total"] / row["exact"], label=f"fddem {label}")
        if h["parameters"]["range"] is not None:
            axes.plot(row["gap"], row["hydro"] / row["exact"], "--", color=line.get_color(), lw=1,
                      label=f"{label}: resolved part")
    axes.axhline(1.0, color="k", lw=1, label=LABEL)
    axes.axhspan(0.9, 1.1, color="0.92", zorder=0)
    axes.set_xscale("log")
    axes.set_xlabel("δ/r (gap / radius)")
    axes.set_ylabel("κ / κ_Brenner,  κ = F / (6πμrU)")
