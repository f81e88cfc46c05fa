"""ten Cate et al. (2002), Phys. Fluids 14:4012: a sphere settling in a closed box (E1-E4).

The reference numbers are those of ../shared/reference/ten_cate.md (ρf, μ, u∞ from the paper's
Table 1, u_max from its Table 2, as quoted by waLBerla, Lethe and Basilisk), and the curves the
third-party digitisation of its Fig. 5 (gap/d and w against t, ±1-2 % in w, ±0.02 s in t):
../shared/reference/digitized/ten_cate_2002, or $FDDEM_TEN_CATE_REFERENCE.
"""

import os

import numpy as np

from . import io
from .references import SOURCE_ROOT

DIAMETER = 0.015  # m
PARTICLE_DENSITY = 1120.0  # kg/m³
GRAVITY = 9.81  # m/s²
# case: (u_max [m/s], digitised-file tag)
CASES = {"E1": (0.035986, "Re1p5"), "E2": (0.05718, "Re4p1"),
         "E3": (0.087269, "Re11p6"), "E4": (0.12224, "Re31p9")}
# case: ρf [kg/m³] (Table 1)
FLUID_DENSITY = {"E1": 970.0, "E2": 965.0, "E3": 962.0, "E4": 960.0}


def release_acceleration_bound(case):
    """The largest acceleration a sphere released from rest can have [m/s²]:
    (ρs − ρf) g / (ρs + ρf/2). Drag and the history force oppose a sphere accelerating from
    rest, and the added mass is at least the unbounded fluid's half displaced mass (walls only
    add to it), so |w(t)| ≤ a_max t for every t."""
    rho_f = FLUID_DENSITY[case]
    return (PARTICLE_DENSITY - rho_f) * GRAVITY / (PARTICLE_DENSITY + 0.5 * rho_f)


def reference_points_above_release_bound(directory, case):
    """The digitised Fig. 5b points (t, w) faster than release_acceleration_bound(case) · t:
    speeds no sphere released from rest at t = 0 reaches by then (the digitisation's ±0.02 s in
    t, or another time origin)."""
    _, ref_w = load_curves(directory, case)
    above = np.abs(ref_w[:, 1]) > release_acceleration_bound(case) * ref_w[:, 0]
    return ref_w[above]


def reference_directory():
    """The digitised Fig. 5 curves, or None when they are not on this machine."""
    directory = os.environ.get("FDDEM_TEN_CATE_REFERENCE") or os.path.join(
        SOURCE_ROOT, "..", "shared", "reference", "digitized", "ten_cate_2002")
    return directory if os.path.isdir(directory) else None


def load_curves(directory, case):
    """(t, gap/d) of Fig. 5a and (t, w [m/s]) of Fig. 5b for `case` ("E1".."E4")."""
    tag = CASES[case][1]
    def read(name):
        # The digitised points are not all in time order: sorted, stably, for interpolation.
        table = np.loadtxt(os.path.join(directory, name))
        return table[np.argsort(table[:, 0], kind="stable")]

    return read(f"tenCate2002-fig5a-{tag}.csv"), read(f"tenCate2002-fig5b-{tag}.csv")


def sphere_history(run_dir, floor=0.0):
    """(t, gap/d, w) of the run's first body: gap = the distance from its bottom to the floor."""
    p = io.read_particles(run_dir)[0]
    gap = (p["z"] - floor - 0.5 * DIAMETER) / DIAMETER
    return p["time"], gap, p["w"]


def compare(run_dir, directory, case):
    """The numbers fddem is judged by, as a dict:
    - u_max_error: (max |w| − u_max)/u_max against Table 2;
    - w_rms: RMS of w − w_ref over the digitised points while the gap exceeds 1 d (before the
      floor decelerates the sphere, where the digitisation's ±0.02 s in t is a large error in
      w), relative to u_max;
    - w_rms_within_bound: the same without the points of reference_points_above_release_bound
      (a diagnostic beside w_rms, which the validation checks), and points_above_bound their
      number;
    - travel_rms: RMS of the distance travelled, (gap(0) − gap(t)) of fddem against that of the
      digitised curve (whose first point is its start; the curve sits about 0.16 d above the
      nominal 8 d release height, which waLBerla corrects by a 0.25 d shift), in d;
    - deceleration_gaps: the gaps [d] at which |w| falls to 0.9, 0.7 and 0.5 of its largest value
      (deceleration_gaps), and reference_deceleration_gaps the experiment's (nan where its
      digitised curves end before).
    """
    u_max = CASES[case][0]
    t, gap, w = sphere_history(run_dir)
    ref_gap, ref_w = load_curves(directory, case)
    result = {"u_max": float(np.max(-w)), "u_max_error": float(np.max(-w) / u_max - 1.0)}
    def last_time_above(g):
        above = gap > g
        return min(t[above][-1] if np.any(above) else t[0], t[-1])

    t_end = last_time_above(0.1)
    in_w = (ref_w[:, 0] <= last_time_above(1.0)) & (ref_w[:, 0] >= t[0])
    mine_w = np.interp(ref_w[in_w, 0], t, w)
    result["w_rms"] = float(np.sqrt(np.mean((mine_w - ref_w[in_w, 1]) ** 2)) / u_max)
    reachable = np.abs(ref_w[in_w, 1]) <= release_acceleration_bound(case) * ref_w[in_w, 0]
    result["w_rms_within_bound"] = float(
        np.sqrt(np.mean((mine_w[reachable] - ref_w[in_w, 1][reachable]) ** 2)) / u_max)
    result["points_above_bound"] = int(np.count_nonzero(~reachable))
    in_gap = (ref_gap[:, 0] <= t_end) & (ref_gap[:, 0] >= t[0])
    mine_travel = gap[0] - np.interp(ref_gap[in_gap, 0], t, gap)
    ref_travel = ref_gap[0, 1] - ref_gap[in_gap, 1]
    result["travel_rms"] = float(np.sqrt(np.mean((mine_travel - ref_travel) ** 2)))
    result["compared_until"] = float(t_end)
    result["deceleration_gaps"] = deceleration_gaps(gap, w)
    result["reference_deceleration_gaps"] = reference_deceleration_gaps(directory, case)
    return result


def plot(run_dir, directory, case, axes_w, axes_gap, label="fddem"):
    """w(t) and gap/d(t) of the run against the digitised Fig. 5b and 5a."""
    t, gap, w = sphere_history(run_dir)
    ref_gap, ref_w = load_curves(directory, case)
    axes_w.plot(t, w, label=label)
    axes_w.plot(ref_w[:, 0], ref_w[:, 1], "k.", markersize=3, label="ten Cate et al. 2002")
    axes_w.set_xlabel("t [s]")
    axes_w.set_ylabel("w [m/s]")
    axes_gap.plot(t, gap, label=label)
    axes_gap.plot(ref_gap[:, 0], ref_gap[:, 1], "k.", markersize=3, label="ten Cate et al. 2002")
    axes_gap.set_xlabel("t [s]")
    axes_gap.set_ylabel("gap / d")


def deceleration_gaps(gap, w, fractions=(0.9, 0.7, 0.5)):
    """The gaps (in d) at which |w| first falls below each fraction of its largest value, after
    that largest value: where the floor begins to slow the sphere, in the floor's own coordinate.
    A history compared in time mixes this with the start height and the plateau speed; compared
    in the gap it does not. (gap, w) in time order; w of either sign. nan where |w| never falls
    that low."""
    speed = np.abs(np.asarray(w, dtype=float))
    gap = np.asarray(gap, dtype=float)
    top = int(np.argmax(speed))
    speed, gap = speed[top:] / speed[top], gap[top:]
    result = []
    for fraction in fractions:
        below = np.nonzero(speed < fraction)[0]
        if below.size == 0:
            result.append(float("nan"))
            continue
        j = below[0]  # j ≥ 1: speed[0] = 1
        share = (speed[j - 1] - fraction) / (speed[j - 1] - speed[j])
        result.append(float(gap[j - 1] + share * (gap[j] - gap[j - 1])))
    return result


def reference_deceleration_gaps(directory, case, fractions=(0.9, 0.7, 0.5), gap_from="5a"):
    """deceleration_gaps of the experiment: Fig. 5b's w at the gap of the same instant, read
    from Fig. 5a (gap_from="5a": 5a interpolated in time; only 5b points within 5a's time span)
    or from Fig. 5b itself (gap_from="5b": the nominal 8 d release height less the integral of
    5b from w = 0 at t = 0). The two figures do not agree (reference_consistency), so the two
    readings bracket the experiment."""
    ref_gap, ref_w = load_curves(directory, case)
    if gap_from == "5b":
        t = np.concatenate([[0.0], ref_w[:, 0]])
        w = np.concatenate([[0.0], ref_w[:, 1]])
        fall = np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t)) / DIAMETER
        return deceleration_gaps(8.0 + fall, ref_w[:, 1], fractions)
    inside = (ref_w[:, 0] >= ref_gap[0, 0]) & (ref_w[:, 0] <= ref_gap[-1, 0])
    gap = np.interp(ref_w[inside, 0], ref_gap[:, 0], ref_gap[:, 1])
    return deceleration_gaps(gap, ref_w[inside, 1], fractions)


def reference_consistency(directory, case):
    """How far the digitised Fig. 5a and 5b and Table 2 agree with each other, as a dict:
    - peak_w: Fig. 5b's largest |w| [m/s], and peak_w_error against Table 2's u_max;
    - gap_speed: the mean speed of Fig. 5a over its plateau [m/s] (least-squares slope of gap(t)
      while 2 d < gap < 6 d, times d), and gap_speed_error against Table 2's u_max;
    - travel_mismatch: the largest |travel by 5a − travel by ∫ 5b dt| while the gap exceeds 1 d
      [d], the travels counted from 5a's first time (5b integrated from w = 0 at t = 0).
    None of this uses a run: it is the reference's own spread, beside which a run is judged."""
    u_max = CASES[case][0]
    ref_gap, ref_w = load_curves(directory, case)
    plateau = (ref_gap[:, 1] > 2.0) & (ref_gap[:, 1] < 6.0)
    slope = np.polyfit(ref_gap[plateau, 0], ref_gap[plateau, 1], 1)[0]
    t = np.concatenate([[0.0], ref_w[:, 0]])
    w = np.concatenate([[0.0], ref_w[:, 1]])
    fall = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))]) / DIAMETER
    above = ref_gap[:, 1] > 1.0
    travel_5a = ref_gap[0, 1] - ref_gap[above, 1]
    travel_5b = np.interp(ref_gap[0, 0], t, fall) - np.interp(ref_gap[above, 0], t, fall)
    peak = float(np.max(np.abs(ref_w[:, 1])))
    return {"peak_w": peak, "peak_w_error": peak / u_max - 1.0,
            "gap_speed": float(-slope * DIAMETER), "gap_speed_error": float(-slope * DIAMETER / u_max - 1.0),
            "travel_mismatch": float(np.max(np.abs(travel_5a - travel_5b)))}
