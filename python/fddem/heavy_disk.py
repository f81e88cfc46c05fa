"""Heavy disks falling in the closed 2 × 6 cm box (d = 0.25 cm, ρs/ρf = 1.5, ν = 0.01 cm²/s):
the particle Reynolds number Re(t) = |U| d / ν of each body and its largest value during the
fall, for the drafting–kissing–tumbling pair (cases/validation/dkt_uhlmann2005) and for one
disk alone (cases/validation/glowinski_disk_b).

Re_max is read while a disk's centre is above `floor_clearance` (0.4 cm, a diameter and a half
above the floor): when a disk meets the floor the contact, not the fall, makes a short spike in
its speed.

Published Re_max (as quoted by Wang, Fan & Luo 2008 and later papers): Glowinski et al. (2001)
438.6 and 466, Uhlmann (2005) 495, Wang, Fan & Luo (2008) 484.75–503.38. The band is their
spread. **They are the peak of the two-disk (DKT) case, not of one disk falling alone**
(twenty-second session; docs/method.md §4, "The heavy disk"): in Uhlmann's own Fig. 6b
(digitised, shared/reference/digitized/uhlmann_2005) the trailing disk peaks at 19.3 cm/s,
Re 483, during the kiss (t = 0.165 s), while the leading disk, ahead of it and falling as a
single disk would, has not passed 13.3 cm/s (Re 333) before then. So the band is compared with
the pair's Re_max; one disk alone reaches its terminal Re ≈ 330 and is not compared with it.
"""

import numpy as np

from . import io

BAND = (438.6, 503.38)
LABEL = "published Re_max of the DKT pair (Glowinski 2001, Uhlmann 2005, Wang 2008)"
FLOOR_CLEARANCE = 0.4  # cm: the centre height below which the floor's contact takes over


def _viscosity_and_diameter(run_dir):
    case = io.read_case(run_dir)
    fluid = case["fluid"]
    nu = float(fluid["viscosity"]) / float(fluid["density"])
    return nu, float(case["bodies"][0]["diameter"])


def reynolds_history(run_dir, body=None):
    """(t, y, Re) of one body (the first if `body` is None); ν = μ/ρf and d from the run's
    case.toml (the first [[bodies]] entry's diameter: the disks of these cases are alike)."""
    nu, diameter = _viscosity_and_diameter(run_dir)
    particles = io.read_particles(run_dir)
    record = particles[min(particles) if body is None else body]
    return record["time"], record["y"], np.hypot(record["u"], record["v"]) * diameter / nu


def fall_maximum(run_dir, floor_clearance=FLOOR_CLEARANCE):
    """{'Re_max', 't_max', 'body', 'y_end', 'reached_floor'}: the largest Re of any body while
    that body's centre is above floor_clearance (from the start to its first sample below it);
    y_end and reached_floor are those of the body with the maximum. Raises ValueError when every
    body starts below it."""
    best = None
    for body in sorted(io.read_particles(run_dir)):
        t, y, re = reynolds_history(run_dir, body)
        below = np.nonzero(y < floor_clearance)[0]
        end = below[0] if len(below) else len(t)
        if end == 0:
            continue
        i = int(np.argmax(re[:end]))
        if best is None or re[i] > best["Re_max"]:
            best = {"Re_max": float(re[i]), "t_max": float(t[i]), "body": body,
                    "y_end": float(y[end - 1]), "reached_floor": bool(len(below))}
    if best is None:
        raise ValueError(f"{run_dir}: every disk starts below y = {floor_clearance}")
    return best


def plot(ax, run_dir):
    """Re(t) of every body with the published band shaded, and the maximum of the fall."""
    ax.axhspan(*BAND, color="k", alpha=0.2, label=LABEL)
    for body in sorted(io.read_particles(run_dir)):
        t, y, re = reynolds_history(run_dir, body)
        ax.plot(t, re, label=f"fddem, body {body}")
        below = np.nonzero(y < FLOOR_CLEARANCE)[0]
        if len(below):
            ax.axvspan(t[below[0]], t[-1], color="C3", alpha=0.1,
                       label=f"body {body} below y = {FLOOR_CLEARANCE} (contact, not compared)")
    result = fall_maximum(run_dir)
    ax.plot([result["t_max"]], [result["Re_max"]], "o", color="k",
            label=f"Re_max of the fall {result['Re_max']:.0f} (body {result['body']})")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("Re = |U| d / ν")
    ax.legend(loc="lower right", fontsize=7)
