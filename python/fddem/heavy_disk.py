"""The heavy disk falling in a closed box (cases/validation/glowinski_disk_b): the particle
Reynolds number Re(t) = |U| d / ν of the first body and its largest value during the fall.

Re_max is read while the disk's centre is above `floor_clearance` (0.4 cm, a diameter and a half
above the floor for d = 0.25): when the disk meets the floor the contact, not the fall, makes a
short spike in the speed (the case header), and the references report the fall.

Published Re_max (as quoted by Wang, Fan & Luo 2008 and later papers; the case header and
docs/method.md §4 say what could and could not be traced): Glowinski et al. (2001) 438.6 and
466, Uhlmann (2005) 495, Wang, Fan & Luo (2008) 484.75–503.38. The band is their spread.
"""

import numpy as np

from . import io

BAND = (438.6, 503.38)
LABEL = "published Re_max (Glowinski 2001, Uhlmann 2005, Wang 2008)"
FLOOR_CLEARANCE = 0.4  # cm: the centre height below which the floor's contact takes over


def reynolds_history(run_dir):
    """(t, y, Re) of the run's first body; ν = μ/ρf and d from the run's case.toml."""
    case = io.read_case(run_dir)
    fluid = case["fluid"]
    nu = float(fluid["viscosity"]) / float(fluid["density"])
    diameter = float(case["bodies"][0]["diameter"])
    particles = io.read_particles(run_dir)
    body = particles[min(particles)]
    return body["time"], body["y"], np.hypot(body["u"], body["v"]) * diameter / nu


def fall_maximum(run_dir, floor_clearance=FLOOR_CLEARANCE):
    """{'Re_max', 't_max', 'y_end'}: the largest Re while the centre is above floor_clearance
    (from the start to the first sample below it). Raises ValueError before any such sample."""
    t, y, re = reynolds_history(run_dir)
    below = np.nonzero(y < floor_clearance)[0]
    end = below[0] if len(below) else len(t)
    if end == 0:
        raise ValueError(f"{run_dir}: the disk starts below y = {floor_clearance}")
    i = int(np.argmax(re[:end]))
    return {"Re_max": float(re[i]), "t_max": float(t[i]), "y_end": float(y[end - 1]),
            "reached_floor": bool(len(below))}


def plot(ax, run_dir, label="fddem"):
    """Re(t) with the published band shaded and the part of the fall Re_max is read from."""
    t, y, re = reynolds_history(run_dir)
    ax.plot(t, re, label=label)
    ax.axhspan(*BAND, color="k", alpha=0.2, label=LABEL)
    below = np.nonzero(y < FLOOR_CLEARANCE)[0]
    if len(below):
        ax.axvspan(t[below[0]], t[-1], color="C3", alpha=0.1,
                   label=f"centre below y = {FLOOR_CLEARANCE} (contact, not compared)")
    result = fall_maximum(run_dir)
    ax.plot([result["t_max"]], [result["Re_max"]], "o", color="C1",
            label=f"Re_max of the fall {result['Re_max']:.0f}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("Re = |U| d / ν")
    ax.legend(loc="lower right")
