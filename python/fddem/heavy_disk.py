"""Heavy disks falling in the closed 2 × 6 cm box (d = 0.25 cm, ρs/ρf = 1.5, ν = 0.01 cm²/s):
the particle Reynolds number Re(t) = |U| d / ν of each body and its largest value during the
fall, for the drafting–kissing–tumbling pair (cases/validation/dkt_uhlmann2005) and for one
disk alone (cases/validation/glowinski_disk_b).

Re_max is read while a disk's centre is above `floor_clearance` (0.4 cm, a diameter and a half
above the floor): when a disk meets the floor the contact, not the fall, makes a short spike in
its speed. With `before_contact` it is read only before the run's first contact of any kind (the
drafting phase of a pair).

Published Re_max (as quoted by Wang, Fan & Luo 2008 and later papers; the originals were not
available here): Glowinski et al. (2001) 438.6 and 466, Uhlmann (2005) 495, Wang, Fan & Luo
(2008) 484.75–503.38. The band is their spread. Uhlmann's 495 is the peak of his two-disk
(DKT) case: in his Fig. 6b (digitised, shared/reference/digitized/uhlmann_2005) the trailing
disk, drafting in the leader's wake, peaks at 19.3 cm/s (Re 483) at t = 0.165 s, before the
pair touches, while the leading disk, falling ahead as a single disk would, is at 13.05 cm/s
(Re 326) at t = 0.15 s. That the other quoted values are the same pair's peak is inferred from
their being quoted together, not read from their papers (docs/method.md §4, "The heavy disk").
So the band is compared with the pair's Re_max before its first contact, not with one disk.
"""

import numpy as np

from . import io

BAND = (438.6, 503.38)
LABEL = "published Re_max (Glowinski 2001, Uhlmann 2005, Wang 2008)"
FLOOR_CLEARANCE = 0.4  # cm: the centre height below which the floor's contact takes over


def _histories(run_dir):
    """{id: (t, y, Re, in contact)}: Re = |U| d/ν with ν = μ/ρf and each body's own diameter
    from the run's case.toml (body ids count the [[bodies]] entries from 0)."""
    case = io.read_case(run_dir)
    fluid = case["fluid"]
    nu = float(fluid["viscosity"]) / float(fluid["density"])
    entries = case["bodies"]
    histories = {}
    for body, record in io.read_particles(run_dir).items():
        diameter = float(entries[min(body, len(entries) - 1)]["diameter"])
        speed = np.hypot(record["u"], record["v"])
        touching = np.zeros(len(speed), dtype=bool)
        for name in ("contact_fx", "contact_fy"):
            if name in record:
                touching |= record[name] != 0.0
        histories[body] = (record["time"], record["y"], speed * diameter / nu, touching)
    return histories


def reynolds_history(run_dir, body=None):
    """(t, y, Re) of one body (the first if `body` is None)."""
    histories = _histories(run_dir)
    t, y, re, _ = histories[min(histories) if body is None else body]
    return t, y, re


def first_contact_time(histories):
    """The earliest time at which any body feels a contact force (inf if none does)."""
    times = [t[touching][0] for t, _, _, touching in histories.values() if touching.any()]
    return min(times) if times else np.inf


def fall_maximum(run_dir, floor_clearance=FLOOR_CLEARANCE, before_contact=False):
    """{'Re_max', 't_max', 'body', 'y_end', 'reached_floor', 'first_contact'}: the largest Re of
    any body while that body's centre is above floor_clearance (from the start to its first
    sample below it) and, with `before_contact`, before the run's first contact. y_end and
    reached_floor are those of the body with the maximum. Raises ValueError when no sample
    qualifies."""
    histories = _histories(run_dir)
    contact = first_contact_time(histories)
    best = None
    for body in sorted(histories):
        t, y, re, _ = histories[body]
        below = np.nonzero(y < floor_clearance)[0]
        end = below[0] if len(below) else len(t)
        window = np.arange(end)
        if before_contact:
            window = window[t[:end] < contact]
        if len(window) == 0:
            continue
        i = int(window[np.argmax(re[window])])
        if best is None or re[i] > best["Re_max"]:
            best = {"Re_max": float(re[i]), "t_max": float(t[i]), "body": body,
                    "y_end": float(y[end - 1]) if end > 0 else float(y[0]),
                    "reached_floor": bool(len(below)), "first_contact": float(contact)}
    if best is None:
        raise ValueError(f"{run_dir}: no sample above y = {floor_clearance}"
                         + (" before the first contact" if before_contact else ""))
    return best


def plot(ax, run_dir, before_contact=False):
    """Re(t) of every body with the published band shaded, and the maximum of the fall."""
    histories = _histories(run_dir)
    ax.axhspan(*BAND, color="k", alpha=0.2, label=LABEL)
    for k, body in enumerate(sorted(histories)):
        t, y, re, _ = histories[body]
        ax.plot(t, re, color=f"C{k}", label=f"fddem, body {body}")
        below = np.nonzero(y < FLOOR_CLEARANCE)[0]
        if len(below):
            ax.axvspan(t[below[0]], t[-1], color=f"C{k}", alpha=0.08,
                       label=f"body {body} below y = {FLOOR_CLEARANCE} (not compared)")
    contact = first_contact_time(histories)
    if before_contact and np.isfinite(contact):
        ax.axvline(contact, color="k", linestyle=":", label=f"first contact, t = {contact:.3f} s")
    result = fall_maximum(run_dir, before_contact=before_contact)
    ax.plot([result["t_max"]], [result["Re_max"]], "o", color="k",
            label=f"Re_max compared: {result['Re_max']:.0f} (body {result['body']})")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("Re = |U| d / ν")
    ax.legend(loc="lower right", fontsize=7)
