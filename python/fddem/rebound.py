"""A sphere bouncing on a wall in a liquid: its trajectory, gap against time, against Gondret,
Lance & Petit (2002), Phys. Fluids 14, 643 (cases/validation/rebound_stokes/, SOURCE.md there).

Everything is measured the same way on the run and on the digitised data, from the gap alone
(the distance from the sphere's lowest point to the wall, in units of its diameter d):

- **first contact** t_c: where the gap first reaches 0, interpolated linearly between the two
  samples around it; a sampled trajectory that never reaches 0 (the digitised data: samples
  every 2 ms, the contact lasts ≪ 1 ms) is extended to 0 along the line through the two
  samples before its first local minimum. The time axis of every comparison is t − t_c.
- **peaks**: the maxima of the gap between successive bounces (a hysteresis of `prominence` d
  keeps noise from counting as a bounce), each refined by the parabola through the highest
  sample and its two neighbours (a 2 ms sampling would otherwise clip a peak).
- **impact and rebound velocities** v_in, v_out: the slope of a polynomial (degree 2, or 1 with
  two samples) fitted to the samples of the approach, respectively of the first rebound, whose
  gap lies in `FIT_WINDOW` (0.02 d to 1 d): the trajectory just outside the film, as an
  experiment measures it, extended to the contact. v_in is the slope at the touch t_c, v_out at
  the separation t_s, when the gap opens again (separation_time). In the experiments the contact
  lasts microseconds and t_s = t_c; a run's collision lasts several fluid steps (the adaptive
  model stretches it to contact.collision_steps Δt, 0.5-4 ms in the rebound cases), and the rebound
  extended back to t_c across it would add the deceleration of the free flight times that
  duration to v_out (thirty-third session: +0.023 m/s, +4.5 %, on the sweep's St 467 point;
  docs/method.md §5, "The rebound measured at the separation"). Until then v_out was taken at
  t_c; that value is kept as v_out_at_touch.
- **rise deceleration** a_rise = v_out / (t_peak − t_s), the mean deceleration of the free rise
  from the separation to the first peak (m/s²; g for a ball in vacuum): the buoyant weight, the
  drag and the wake's push, with the added mass, over the flight after the contact. It separates
  a peak that is off because the sphere leaves the wall at the wrong speed from one that is off
  because its rise is braked wrongly (thirty-fourth session, docs/method.md §5, "The rise after
  the rebound against the resolution").
- **e_eff = −v_out / v_in**, the effective restitution of the first bounce: what Gondret et al.
  and Joseph et al. (2001) call e, the ratio of the velocities just after and just before the
  contact, read from the trajectory (and what Legendre et al. 2006 fit as e_dry exp(−35/St)).

A run (cases/validation/gondret_rebound_st*) also gives the sphere's own velocity w; from it
the speed at the touch (interpolated at t_c) and at the separation (the first time the gap is
positive again): their ratio, e_contact, is the contact model's restitution with the
lubrication correction during the overlap, without the fluid around the contact.
"""

import math
import os

import numpy as np

from . import io
from .references import SOURCE_ROOT

REFERENCE_DIRECTORY = os.path.join(SOURCE_ROOT, "cases", "validation", "rebound_stokes")
LABEL = "Gondret et al. (2002), measured"
FIT_WINDOW = (0.02, 1.0)  # gap / d of the samples the velocity fits use
# Legendre, Zenit, Daniel & Guiraud (2006): e/e_dry = exp(−β/St), β = 35
# (cases/validation/rebound_stokes/legendre2006_fit.md).
LEGENDRE_BETA = 35.0
# case: diameter [m], impact speed [m/s] and St of Biegert, Vowinckel & Meiburg (2017) Table 1,
# the published peak heights (gap/d) of SOURCE.md, and whether the file holds the approach.
CASES = {
    "st152": {"file": "gondret2002_trajectory_st152.csv", "diameter": 0.003, "impact": 0.585,
              "stokes": 152.0, "peaks": (2.49, 0.74, 0.17), "has_approach": True},
    "st27": {"file": "gondret2002_trajectory_st27.csv", "diameter": 0.006, "impact": 0.518,
             "stokes": 27.0, "peaks": (0.33,), "has_approach": False},
}


def load_reference(case, directory=REFERENCE_DIRECTORY):
    """(t [s], gap/d) of the digitised trajectory of `case` ("st152" or "st27")."""
    table = np.loadtxt(os.path.join(directory, CASES[case]["file"]), delimiter=",", skiprows=5)
    return table[:, 0], table[:, 3]


def contact_time(t, gap):
    """The first contact (module docstring): the interpolated first zero of the gap, or the
    zero of the line through the two samples before the first local minimum; None when neither
    exists (a trajectory that starts after the contact)."""
    t, gap = np.asarray(t, dtype=float), np.asarray(gap, dtype=float)
    touching = np.flatnonzero(gap <= 0.0)
    if touching.size:
        k = touching[0]
        if k == 0:
            return float(t[0])
        return float(t[k - 1] + (t[k] - t[k - 1]) * gap[k - 1] / (gap[k - 1] - gap[k]))
    falling = np.flatnonzero(np.diff(gap) < 0.0)
    rising = np.flatnonzero(np.diff(gap) > 0.0)
    if not falling.size:
        return None
    after = rising[rising > falling[0]]
    if not after.size:
        return None
    k = after[0]  # the first local minimum
    if k < 2:
        return None
    slope = (gap[k - 1] - gap[k - 2]) / (t[k - 1] - t[k - 2])
    return float(t[k - 1] - gap[k - 1] / slope) if slope < 0.0 else None


def _refined_maximum(t, gap, k):
    """The vertex of the parabola through samples k−1, k, k+1 (the sample itself at an end or
    when the three are collinear)."""
    if k == 0 or k == len(gap) - 1:
        return float(t[k]), float(gap[k])
    coeffs = np.polyfit(t[k - 1:k + 2] - t[k], gap[k - 1:k + 2], 2)
    if coeffs[0] >= 0.0:
        return float(t[k]), float(gap[k])
    tv = -coeffs[1] / (2.0 * coeffs[0])
    if abs(tv) > max(t[k + 1] - t[k], t[k] - t[k - 1]):
        return float(t[k]), float(gap[k])
    return float(t[k] + tv), float(np.polyval(coeffs, tv))


def peaks(t, gap, t_start, prominence=0.02):
    """The maxima of the gap after t_start, each a rise and a fall of at least `prominence`
    (same unit as gap), as a list of (t, gap), refined by a parabola."""
    t, gap = np.asarray(t, dtype=float), np.asarray(gap, dtype=float)
    found = []
    low, high, high_at, rising = math.inf, -math.inf, None, False
    for k in np.flatnonzero(t >= t_start):
        g = gap[k]
        if not rising:
            low = min(low, g)
            if g > low + prominence:
                rising, high, high_at = True, g, k
        else:
            if g > high:
                high, high_at = g, k
            if g < high - prominence:
                found.append(_refined_maximum(t, gap, high_at))
                rising, low = False, g
    return found


def separation_time(t, gap, t_c):
    """When the gap opens again after the touch t_c: its zero, interpolated linearly between the
    last sample at or below 0 and the next one above. t_c itself when no sample after t_c is at
    or below 0 (a contact shorter than the sampling, as in the digitised data); None when the gap
    never opens again."""
    t, gap = np.asarray(t, dtype=float), np.asarray(gap, dtype=float)
    after = np.flatnonzero(t > t_c)
    if not after.size or gap[after[0]] > 0.0:
        return float(t_c)
    open_again = after[gap[after] > 0.0]
    if not open_again.size:
        return None
    k = open_again[0]
    return float(t[k - 1] + (t[k] - t[k - 1]) * -gap[k - 1] / (gap[k] - gap[k - 1]))


def fitted_velocity(t, gap, t_c, side, window=FIT_WINDOW, until=None, at=None):
    """d(gap)/dt at t_c (or at `at`) from the samples on `side` ("before" or "after" t_c) with gap
    within `window`, back to the previous maximum (before) or up to `until` (after): polynomial
    of degree 2 (1 with two samples) in t − t_c. Gap in the unit of the result's length; None
    with fewer than two samples."""
    t, gap = np.asarray(t, dtype=float), np.asarray(gap, dtype=float)
    inside = (gap >= window[0]) & (gap <= window[1])
    if side == "before":
        k = np.flatnonzero(t < t_c)
        # back to the last sample that is not in the window (the approach only)
        keep = []
        for j in k[::-1]:
            if not inside[j]:
                if keep:
                    break
                continue
            keep.append(j)
        keep = np.array(sorted(keep), dtype=int)
    else:
        k = np.flatnonzero((t > t_c) & ((t < until) if until is not None else True))
        keep = []
        for j in k:
            if not inside[j]:
                if keep:
                    break
                continue
            keep.append(j)
        keep = np.array(keep, dtype=int)
    if keep.size < 2:
        return None
    degree = min(2, keep.size - 1)
    coeffs = np.polyfit(t[keep] - t_c, gap[keep], degree)
    return float(np.polyval(np.polyder(coeffs), 0.0 if at is None else at - t_c))


def measure(t, gap, t_c=None, diameter=1.0):
    """The numbers of one trajectory (gap in units of d, t in s): t_c, the peaks (t − t_c,
    gap/d), v_in, v_out (m/s with `diameter` in m) and e_eff = −v_out/v_in (module docstring)."""
    t, gap = np.asarray(t, dtype=float), np.asarray(gap, dtype=float)
    if t_c is None:
        t_c = contact_time(t, gap)
    if t_c is None:
        raise ValueError("no contact: the gap never reaches 0 nor turns back from the wall")
    found = peaks(t, gap, t_c)
    t_s = separation_time(t, gap, t_c)
    until = found[0][0] if found else None
    v_in = fitted_velocity(t, gap, t_c, "before")
    v_out = None if t_s is None else fitted_velocity(t, gap, t_c, "after", until=until, at=t_s)
    v_out_at_touch = fitted_velocity(t, gap, t_c, "after", until=until)
    result = {"t_contact": t_c, "t_separation": t_s, "peaks": [(tp - t_c, gp) for tp, gp in found],
              "v_in": None if v_in is None else v_in * diameter,
              "v_out": None if v_out is None else v_out * diameter,
              "v_out_at_touch": None if v_out_at_touch is None else v_out_at_touch * diameter}
    result["e_eff"] = (-v_out / v_in) if (v_in and v_out is not None) else None
    result["rise_deceleration"] = None
    if v_out is not None and found and found[0][0] > t_s:
        result["rise_deceleration"] = result["v_out"] / (found[0][0] - t_s)
    return result


def run_trajectory(run_dir):
    """(t, gap/d, w [m/s], d [m]) of the run's first body: gap from its lowest point to the
    floor (the box's low side along z, gravity along −z)."""
    case = io.read_case(run_dir)
    diameter = float(case["bodies"][0]["diameter"])
    floor = float(case["domain"].get("origin", [0.0, 0.0, 0.0])[2])
    body = io.read_particles(run_dir)
    body = body[min(body)]
    gap = (body["z"] - floor - 0.5 * diameter) / diameter
    return body["time"], gap, body["w"], diameter


def touch_speeds(t, gap, w, t_c):
    """The run's own speeds: |w| of the last sample before the touch t_c (the speed at which
    the step that touches starts), w of the first sample with the gap positive again after
    it (the separation), their ratio, and the rows of the contact (first, last + 1)."""
    before = np.flatnonzero(t < t_c)
    k0 = before[-1] if before.size else 0
    touch = float(-w[k0])
    later = np.flatnonzero((t > t_c) & (gap > 0.0))
    if not later.size:
        return {"touch": touch, "separation": None, "e_contact": None, "rows": (k0 + 1, len(t))}
    separation = float(w[later[0]])
    return {"touch": touch, "separation": separation, "e_contact": separation / touch,
            "rows": (k0 + 1, int(later[0]) + 1)}


def contact_impulses(run_dir, t_c):
    """The impulses on the sphere over the rows of its first contact (touch_speeds' rows):
    contact, lubrication and resolved fluid force (columns contact_fz, lubrication_fz, fz;
    each a step's mean, times the step), its buoyant weight, and m Δw, in N·s; and the
    lubrication's work there (Σ F_lub w Δt, J) against the kinetic energy at the touch."""
    case = io.read_case(run_dir)
    body_spec = case["bodies"][0]
    d = float(body_spec["diameter"])
    mass = float(body_spec["density"]) * math.pi / 6.0 * d**3
    g = float(case["fluid"].get("gravity", [0.0, 0.0, 0.0])[2])
    weight = (float(body_spec["density"]) - float(case["fluid"]["density"])) * math.pi / 6.0 * d**3 * g
    body = io.read_particles(run_dir)
    body = body[min(body)]
    t, w = body["time"], body["w"]
    floor = float(case["domain"].get("origin", [0.0, 0.0, 0.0])[2])
    gap = (body["z"] - floor - 0.5 * d) / d
    k0, k1 = touch_speeds(t, gap, w, t_c)["rows"]
    dt = np.diff(t)[k0 - 1:k1 - 1]
    rows = slice(k0, k1)
    zero = np.zeros_like(t)
    result = {name: float(np.sum(body.get(name, zero)[rows] * dt))
              for name in ("contact_fz", "lubrication_fz", "fz")}
    result["weight"] = float(weight * np.sum(dt))
    result["momentum_change"] = float(mass * (w[k1 - 1] - w[k0 - 1]))
    result["lubrication_work"] = float(np.sum(body.get("lubrication_fz", zero)[rows] * w[rows] * dt))
    result["kinetic_energy"] = float(0.5 * mass * w[k0 - 1] ** 2)
    result["duration"] = float(t[k1 - 1] - t[k0 - 1])
    return result


def compare(run_dir, case):
    """The run's and the reference's numbers, and the RMS of gap/d of the run at the
    reference's times (t − t_c) where both exist, as a dict."""
    t, gap, w, diameter = run_trajectory(run_dir)
    mine = measure(t, gap, diameter=diameter)
    mine.update(touch_speeds(t, gap, w, mine["t_contact"]))
    # The impulse budget needs the forces and the densities: a run of fddem's, not a table.
    run_case = io.read_case(run_dir)
    has_forces = "density" in run_case["bodies"][0] and "fluid" in run_case and np.min(gap) <= 0.0
    mine["impulses"] = contact_impulses(run_dir, mine["t_contact"]) if has_forces else None
    mine["overlap"] = float(-np.min(gap)) if np.min(gap) < 0.0 else 0.0
    ref_t, ref_gap = load_reference(case)
    spec = CASES[case]
    reference = measure(ref_t, ref_gap, t_c=None if spec["has_approach"] else 0.0,
                        diameter=spec["diameter"])
    shifted = t - mine["t_contact"]
    ref_shifted = ref_t - reference["t_contact"]
    both = (ref_shifted >= shifted[0]) & (ref_shifted <= shifted[-1])
    rms = None
    if np.any(both):
        rms = float(np.sqrt(np.mean((np.interp(ref_shifted[both], shifted, gap)
                                     - ref_gap[both]) ** 2)))
    return {"run": mine, "reference": reference, "rms": rms, "points": int(np.count_nonzero(both)),
            "case": case}


def plot(axes, run_dirs, case, labels=None):
    """gap/d against t − t_c of every run over the digitised trajectory."""
    labels = labels or [os.path.basename(os.path.normpath(r)) for r in run_dirs]
    ref_t, ref_gap = load_reference(case)
    ref_tc = contact_time(ref_t, ref_gap) if CASES[case]["has_approach"] else 0.0
    for run, label in zip(run_dirs, labels):
        t, gap, _, _ = run_trajectory(run)
        axes.plot(t - contact_time(t, gap), gap, label=f"fddem {label}")
    axes.plot(ref_t - ref_tc, ref_gap, "o", ms=3, color="k", mfc="none",
              label=f"{LABEL}, St {CASES[case]['stokes']:g}")
    axes.axhline(0.0, color="0.5", lw=0.8)
    axes.set_xlabel("t − t_contact [s]")
    axes.set_ylabel("gap / d")


def legendre_fit(stokes):
    """e/e_dry of Legendre et al.'s (2006) fit at St."""
    return math.exp(-LEGENDRE_BETA / stokes)


def film_passage_integral(range_over_a, roughness_over_a):
    """J = ∫ c_corr(h) dh / (6πμ a²) over one passage of a sphere through the film to a wall,
    h from the range h_Δ down to 0, for the correction fddem adds (src/fddem/contact/
    lubrication.hpp, lubrication.resolved = "range"): c(h) = 6πμa [a/h + ln(a/h)/5] (Cox &
    Brenner 1967), c_corr = c(max(h, h_σ)) − c(h_Δ). Because the film's force is c v and
    dh = v dt, its impulse over the passage is 6πμa² J whatever the speed: the sphere loses
    Δv = J v/St (St = ρs v d/(9μ)) on the way in, and again on the way out. In closed form, with
    x = h/a:
        J = ln(x_Δ/x_σ) + [x_Δ (1 − ln x_Δ) − x_σ (1 − ln x_σ)]/5 − x_Δ c(x_Δ) + x_σ c(x_σ),
        c(x) = 1/x + ln(1/x)/5."""
    x_range, x_rough = float(range_over_a), float(roughness_over_a)
    if not 0.0 < x_rough < x_range <= 1.0:
        raise ValueError(f"need 0 < roughness < range <= a, got {x_rough} and {x_range}")

    def resistance(x):
        return 1.0 / x + math.log(1.0 / x) / 5.0

    return (math.log(x_range / x_rough)
            + (x_range * (1.0 - math.log(x_range)) - x_rough * (1.0 - math.log(x_rough))) / 5.0
            - x_range * resistance(x_range) + x_rough * resistance(x_rough))


def film_restitution(stokes, e_dry, range_over_a, roughness_over_a):
    """e_eff/e_dry of a sphere bouncing on a wall whose only losses are the dry contact (e_dry)
    and the lubrication correction (film_passage_integral), in and out: the film's own share of
    the restitution, without the resolved flow. St at the speed with which the sphere enters the
    film. 0 if the film stops it on the way in or on the way out."""
    if not stokes > 0.0:
        raise ValueError(f"the Stokes number must be positive, got {stokes}")
    loss = film_passage_integral(range_over_a, roughness_over_a) / stokes
    touch = 1.0 - loss
    leave = e_dry * touch - loss
    return max(leave, 0.0) / e_dry if touch > 0.0 else 0.0


def film_restitution_of_run(run_dir, stokes):
    """film_restitution() with the run's own e_dry (contact.restitution of the adaptive model),
    lubrication.range (in grid spacings, the largest) and lubrication.roughness (in radii), at
    `stokes`. None where the closed form is not the run's film: no lubrication, not a sphere
    (3D), lubrication.resolved other than "range", the correction held in contact
    (in_contact "saturated"), another collision model, a range beyond the radius or a
    roughness beyond the range (where fddem adds no correction)."""
    case = io.read_case(run_dir)
    lubrication = case.get("lubrication", {})
    contact = case.get("contact", {})
    domain = case["domain"]
    if (not lubrication.get("enabled", False) or len(domain["size"]) != 3
            or lubrication.get("resolved", "range") != "range"
            or lubrication.get("in_contact", "off") != "off"
            or contact.get("model", "linear") != "adaptive" or not stokes > 0.0):
        return None
    radius = 0.5 * float(case["bodies"][0]["diameter"])
    spacing = max(float(L) / int(n) for L, n in zip(domain["size"], domain["cells"]))
    x_range = float(lubrication.get("range", 2.0)) * spacing / radius
    x_rough = float(lubrication.get("roughness", 0.001))
    if not 0.0 < x_rough < x_range <= 1.0:
        return None
    return film_restitution(stokes, float(contact.get("restitution", 1.0)), x_range, x_rough)


def restitution(run_dir):
    """St, v_in, v_out, e_eff, e_eff/e_dry ("ratio") and the contact's speed ratio of one rebound
    run, as a dict. St = ρp v_in d/(9μ) at the impact speed v_in measured from the trajectory
    (as the experiments define it); a sphere that never touches (the film stops it) has St at
    its speed where the gap is first 1 d (the far end of FIT_WINDOW, before the film slows it)
    and the ratio 0 (no rebound); one that touches and does not leave the wall again, the ratio
    0 too."""
    case = io.read_case(run_dir)
    body = case["bodies"][0]
    density = float(body["density"])
    viscosity = float(case["fluid"]["viscosity"])
    e_dry = float(case.get("contact", {}).get("restitution", 1.0))
    t, gap, w, diameter = run_trajectory(run_dir)
    body = io.read_particles(run_dir)
    body = body[min(body)]
    # measure() extends a sampled gap that never reaches 0 along the approach before its first
    # local minimum: right for the digitised data (samples every 2 ms), wrong for a sphere the
    # film stopped short of the wall, where it invents a touch (the sweep's St 4 run: at
    # t = 0.178 s in a run to 0.11 s, from a wiggle early in the fall, met moving away: St < 0).
    # A run says whether it touched: an overlap (gap ≤ 0) or a contact force in some row. Rows
    # are every step in the rebound cases; a run written more sparsely could miss both.
    touched = None
    if "contact_fz" in body:
        touched = bool(np.any(gap <= 0.0)) or bool(np.any(body["contact_fz"] != 0.0))
    try:
        if touched is False:
            raise ValueError("the sphere never touches the wall")
        result = measure(t, gap, diameter=diameter)
        if result["t_contact"] > t[-1] or result["v_in"] is None or result["v_in"] >= 0.0:
            raise ValueError("the sphere never touches the wall")
    except ValueError:  # never at the wall: no contact, no rebound
        near = np.flatnonzero(gap <= FIT_WINDOW[1])
        k = int(near[0]) if near.size else int(np.argmin(gap))
        result = {"t_contact": None, "t_separation": None, "peaks": [], "v_in": None,
                  "v_out": None, "v_out_at_touch": None, "e_eff": None,
                  "touch": float(-w[k]), "separation": None, "e_contact": None}
    else:
        result.update(touch_speeds(t, gap, w, result["t_contact"]))
    v_in = -result["v_in"] if result["v_in"] is not None else result["touch"]
    result["stokes"] = density * v_in * diameter / (9.0 * viscosity)
    result["e_dry"] = e_dry
    result["ratio"] = 0.0 if result["e_eff"] is None else result["e_eff"] / e_dry
    result["rebounds"] = result["e_eff"] is not None
    return result


def gondret_restitution_points():
    """(St, e_eff/e_dry) of Gondret's two digitised trajectories, measured as the runs are, St
    at the published impact speed (Biegert et al. 2017 Table 1, CASES), e_dry = 0.97. The St 27
    file starts at the contact: there v_out over the published impact speed."""
    points = []
    for name, spec in sorted(CASES.items()):
        t, gap = load_reference(name)
        r = measure(t, gap, t_c=None if spec["has_approach"] else 0.0, diameter=spec["diameter"])
        if r["e_eff"] is not None:
            points.append((spec["stokes"], r["e_eff"] / 0.97))
        elif r["v_out"] is not None:
            points.append((spec["stokes"], r["v_out"] / spec["impact"] / 0.97))
    return points


def plot_restitution(axes, results, label="fddem, d/h = 8", film_run=None):
    """e_eff/e_dry against St: `results` (restitution() dicts) over Legendre et al.'s fit and
    Gondret et al.'s two trajectories measured the same way; with `film_run` (a run directory)
    also what its lubrication film alone allows (film_restitution_of_run), as a dashed line."""
    st = np.logspace(0, 3.2, 200)
    axes.plot(st, np.exp(-LEGENDRE_BETA / st), "k-", label="Legendre et al. (2006): exp(−35/St)")
    if film_run is not None and film_restitution_of_run(film_run, 100.0) is not None:
        film = [film_restitution_of_run(film_run, x) for x in st]
        axes.plot(st, film, "b--", lw=1,
                  label="the lubrication film alone, exactly integrated (its range, roughness)")
    ref = gondret_restitution_points()
    axes.plot([p[0] for p in ref], [p[1] for p in ref], "ks", mfc="none",
              label="Gondret et al. (2002), trajectories measured as the runs")
    axes.plot([r["stokes"] for r in results], [r["ratio"] for r in results], "ro",
              label=f"{label} (no rebound plotted as 0)")
    axes.set_xscale("log")
    axes.set_xlabel("St = ρp v_in d / (9 μ)")
    axes.set_ylabel("e_eff / e_dry")
    axes.set_ylim(-0.05, 1.12)
    axes.grid(True, which="both", alpha=0.3)
