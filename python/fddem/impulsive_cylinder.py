"""The impulsively started cylinder: C_D(t) of a fixed disk in a stream switched on at t = 0,
against Koumoutsakos & Leonard (1995), J. Fluid Mech. 296, 1-38 (vortex method, unbounded).

The reference curves (Re = U D/ν = 550 and 3000) are cuIBM's digitisation of the paper's drag
histories, kept with the case: cases/validation/impulsive_cylinder_re550/reference/ (SOURCE.md
there: the source, the units, and the time scale, which is the paper's tU/R, R the radius).

A run gives C_D = 2 F_x / (ρ U² D) from particles.csv (fx of the first body, per unit depth)
with ρ = fluid.density, U = inflow.velocity and D = the first body's diameter of its case.toml.
"""

import os

import numpy as np

from . import io
from .references import SOURCE_ROOT

REFERENCE_DIRECTORY = os.path.join(SOURCE_ROOT, "cases", "validation", "impulsive_cylinder_re550",
                                   "reference")
REYNOLDS_NUMBERS = (550, 3000)
# tU/R: from after the start-up singularity (C_D ~ t^(-1/2), which a time step of the run cannot
# follow within its first steps) to the end of the Re 550 curve's shared range with Re 3000.
WINDOW = (0.5, 6.0)
LABEL = "Koumoutsakos & Leonard (1995)"


def load_reference(reynolds, directory=REFERENCE_DIRECTORY):
    """(tU/R, C_D) of the digitised curve for Re 550 or 3000, in time order."""
    if reynolds not in REYNOLDS_NUMBERS:
        raise ValueError(f"no Koumoutsakos & Leonard curve for Re = {reynolds} "
                         f"(there are {', '.join(map(str, REYNOLDS_NUMBERS))})")
    path = os.path.join(directory, f"koumoutsakos_leonard_1995_re{reynolds}.csv")
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    table = table[np.argsort(table[:, 0], kind="stable")]
    return table[:, 0], table[:, 1]


def run_parameters(run_dir):
    """(ρ, U, D, Re) of a run: fluid density, inflow speed, the first body's diameter, ρUD/μ."""
    case = io.read_case(run_dir)
    density = float(case["fluid"]["density"])
    speed = float(case["inflow"]["velocity"])
    diameter = float(case["bodies"][0]["diameter"])
    viscosity = case["fluid"].get("viscosity") or case.get("derived", {}).get("viscosity")
    return density, speed, diameter, density * speed * diameter / float(viscosity)


def nearest_reference_reynolds(reynolds, tolerance=0.01):
    """The reference Re within `tolerance` (relative) of the run's, or None."""
    for candidate in REYNOLDS_NUMBERS:
        if abs(reynolds / candidate - 1.0) <= tolerance:
            return candidate
    return None


def drag_history(run_dir):
    """(tU/R, C_D) of the run's first body; C_D = 2 F_x/(ρ U² D)."""
    density, speed, diameter, _ = run_parameters(run_dir)
    particles = io.read_particles(run_dir)
    body = particles[min(particles)]
    tau = body["time"] * speed / (0.5 * diameter)
    return tau, 2.0 * body["fx"] / (density * speed**2 * diameter)


def deviation(tau, drag, ref_tau, ref_drag, window=WINDOW):
    """fddem's C_D interpolated (linearly) onto the reference points in `window` (tU/R) that the
    run covers; the relative deviation (C_D − C_D,ref)/C_D,ref there, as a dict:
    rms, max (largest |·|, signed), mean (the bias), the window compared and the point count."""
    low = max(window[0], tau[0])
    high = min(window[1], tau[-1])
    inside = (ref_tau >= low) & (ref_tau <= high)
    if not np.any(inside):
        raise ValueError(f"the run (tU/R {tau[0]:g} to {tau[-1]:g}) covers no reference point "
                         f"in [{window[0]:g}, {window[1]:g}]")
    relative = np.interp(ref_tau[inside], tau, drag) / ref_drag[inside] - 1.0
    worst = int(np.argmax(np.abs(relative)))
    return {"rms": float(np.sqrt(np.mean(relative**2))), "max": float(relative[worst]),
            "max_at": float(ref_tau[inside][worst]), "mean": float(np.mean(relative)),
            "window": (float(ref_tau[inside][0]), float(ref_tau[inside][-1])),
            "points": int(np.count_nonzero(inside))}


def compare(run_dir, window=WINDOW, reynolds=None, directory=REFERENCE_DIRECTORY):
    """deviation() of a run against the curve of its Reynolds number (or `reynolds`)."""
    if reynolds is None:
        reynolds = nearest_reference_reynolds(run_parameters(run_dir)[3])
        if reynolds is None:
            raise ValueError(f"{run_dir}: Re = {run_parameters(run_dir)[3]:.4g} is not one of "
                             f"the reference curves' {REYNOLDS_NUMBERS}")
    tau, drag = drag_history(run_dir)
    result = deviation(tau, drag, *load_reference(reynolds, directory), window)
    result["reynolds"] = reynolds
    return result


def plot(axes, run_dirs, labels=None, reynolds=None, window=WINDOW, directory=REFERENCE_DIRECTORY):
    """C_D against tU/R of every run and the reference curve, the compared window shaded."""
    labels = labels or [os.path.basename(os.path.normpath(r)) for r in run_dirs]
    for run, label in zip(run_dirs, labels):
        tau, drag = drag_history(run)
        axes.plot(tau, drag, label=f"fddem {label}")
        if reynolds is None:
            reynolds = nearest_reference_reynolds(run_parameters(run)[3])
    if reynolds is not None:
        ref_tau, ref_drag = load_reference(reynolds, directory)
        axes.plot(ref_tau, ref_drag, "ko", markersize=3, label=f"{LABEL}, Re {reynolds}")
    axes.axvspan(*window, color="0.9", zorder=0)
    axes.set_xlabel("tU/R")
    axes.set_ylabel("C_D = 2 F_x / (ρ U² D)")
    axes.set_ylim(0.0, 2.0)
    axes.set_xlim(0.0, max(window[1] + 1.0, 7.0))
