#!/usr/bin/python3
"""Energy budget of a sphere's collision with the floor: who does the work, step by step.

    python3 tools/rebound_energy.py RUN_DIR [RUN_DIR ...] [--reach 2.0] [--speeds]

For the first body of each run (a rebound run: cases/validation/gondret_rebound_st*, gravity
along −z, the floor the box's low side) and each step of particles.csv (which must hold every
step: output.particle_interval = 0, the default), the body's momentum balance over the step is

    m (w^{n+1} − w^n)/Δt = W_b + F_c + F_l + s F_H

with W_b = (ρs − ρf) V g the buoyant weight, F_c the dry contact (contact_fz), F_l the
lubrication correction (lubrication_fz), F_H the resolved hydrodynamic force (fz: from the
fluid's momentum balance over the body, coupling/hydrodynamic_force.hpp), and s = 1 when the
fluid update, eqs. (13)–(14), moved the body, s = 0 when the DEM sub-steps did (contact.coupling
= "paper" with the body in contact or within the lubrication range: F_H is then measured, the
fluid being made to follow the body, but not applied to it). With contact.fluid_force = "held"
a DEM-moved step applies the step before's F_H instead (in the sub-steps that touch nothing).
The phase is read off the balance itself: whichever of F_H, 0 and the step before's F_H
m Δw/Δt − W_b − F_c − F_l is closest to (a step that touches in part of its sub-steps under
"held" matches none exactly: see the residual printed).

Each force's work over a step is its impulse times the step's mean velocity, F Δt (w^n +
w^{n+1})/2, so that the works of the applied forces add up to the change of ½ m w² exactly.
Printed per phase of the first collision: the approach from gap `reach` d down to the touch, the
contact (gap < 0), and the exit from the separation up to gap `reach` d or the first apex:
the kinetic energy at the ends, and the work of each force, split into the DEM-moved and the
fluid-moved steps; "F_H not applied" is the resolved force's work over the DEM-moved steps,
what the paper coupling leaves out. With --speeds, w against the gap on the approach at a few
gaps (interpolated), to compare runs.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import io  # noqa: E402

SPEED_GAPS = (2.0, 1.0, 0.5, 0.25, 0.125, 0.0625, 0.0)  # gap / d for --speeds


def load(run_dir):
    """The first body's rows and constants as a dict of arrays and numbers."""
    case = io.read_case(run_dir)
    spec = case["bodies"][0]
    d = float(spec["diameter"])
    volume = math.pi / 6.0 * d**3
    rho_s = float(spec["density"])
    rho_f = float(case["fluid"]["density"])
    g = float(case["fluid"].get("gravity", [0.0, 0.0, 0.0])[2])
    floor = float(case["domain"].get("origin", [0.0, 0.0, 0.0])[2])
    body = io.read_particles(run_dir)
    body = body[min(body)]
    zero = np.zeros_like(body["time"])
    return {"t": body["time"], "gap": (body["z"] - floor - 0.5 * d) / d, "w": body["w"],
            "fh": body["fz"], "fc": body.get("contact_fz", zero),
            "fl": body.get("lubrication_fz", zero), "mass": rho_s * volume,
            "weight": (rho_s - rho_f) * volume * g, "d": d,
            "stokes_scale": rho_s * d / (9.0 * float(case["fluid"]["viscosity"]))}


def steps(r):
    """Per step n → n+1 (arrays of length rows − 1): Δt, the mean w, the works, the phase."""
    t, w = r["t"], r["w"]
    dt = np.diff(t)
    mean_w = 0.5 * (w[1:] + w[:-1])
    fh, fc, fl = r["fh"][1:], r["fc"][1:], r["fl"][1:]  # each row: the step that ended there
    held = r["fh"][:-1]  # the step before's F_H: what contact.fluid_force = "held" applies
    accel = r["mass"] * np.diff(w) / dt
    without_fluid = accel - r["weight"] - fc - fl
    candidates = np.abs(np.vstack([without_fluid - fh, without_fluid, without_fluid - held]))
    phase = np.argmin(candidates, axis=0)  # 0 fluid-moved, 1 DEM-moved, 2 DEM-moved + held F_H
    residual = np.choose(phase, [without_fluid - fh, without_fluid, without_fluid - held])
    return {"dt": dt, "mean_w": mean_w, "dem": phase != 0, "held": phase == 2,
            "W_b": r["weight"] * mean_w * dt, "W_c": fc * mean_w * dt, "W_l": fl * mean_w * dt,
            "W_h": fh * mean_w * dt, "W_held": held * mean_w * dt,
            "kinetic": 0.5 * r["mass"] * np.diff(w**2), "residual": residual}


def first_collision(r, reach):
    """Row indices: the last row above `reach` d before the touch, the touch row (first gap <
    0), the separation row (first gap ≥ 0 after it), and the end of the exit (first row above
    `reach` d after it, or the first apex, or the last row)."""
    gap = r["gap"]
    below = np.flatnonzero(gap < 0.0)
    if not below.size:
        return None
    touch = int(below[0])
    above = np.flatnonzero(gap[:touch] >= reach)
    start = int(above[-1]) if above.size else 0
    after = np.flatnonzero(gap[touch:] >= 0.0)
    separation = touch + int(after[0]) if after.size else len(gap) - 1
    end = separation
    while end + 1 < len(gap) and gap[end + 1] > gap[end] and gap[end] < reach:
        end += 1
    return start, touch, separation, end


def budget(s, first, last, r):
    """The works of the steps ending at rows first+1 … last (step index k = row − 1)."""
    k = slice(first, last)
    dem, held = s["dem"][k], s["held"][k]
    fluid = ~dem
    out = {"rows": (first, last), "dem_steps": int(np.count_nonzero(dem)),
           "held_steps": int(np.count_nonzero(held)),
           "fluid_steps": int(np.count_nonzero(fluid)),
           "KE_start": 0.5 * r["mass"] * r["w"][first] ** 2,
           "KE_end": 0.5 * r["mass"] * r["w"][last] ** 2,
           "gap_start": r["gap"][first], "gap_end": r["gap"][last],
           "w_start": r["w"][first], "w_end": r["w"][last]}
    for name in ("W_b", "W_c", "W_l"):
        out[name] = float(np.sum(s[name][k]))
    out["W_h"] = float(np.sum(s["W_h"][k][fluid]))
    out["W_held"] = float(np.sum(s["W_held"][k][held]))
    out["W_h_not_applied"] = float(np.sum(s["W_h"][k][dem]))
    out["max_residual"] = float(np.max(np.abs(s["residual"][k]))) if last > first else 0.0
    return out


def print_budget(name, b):
    ke = max(b["KE_start"], 1e-300)
    print(f"  {name}: rows {b['rows'][0]}–{b['rows'][1]}, gap {b['gap_start']:+.4f} → "
          f"{b['gap_end']:+.4f} d, w {b['w_start']:+.4f} → {b['w_end']:+.4f} m/s, steps "
          f"{b['fluid_steps']} fluid-moved + {b['dem_steps']} DEM-moved ({b['held_steps']} with "
          "the held F_H)")
    print(f"    KE {b['KE_start']:.4e} → {b['KE_end']:.4e} J (Δ {b['KE_end'] - b['KE_start']:+.4e})")
    applied = b["W_b"] + b["W_c"] + b["W_l"] + b["W_h"] + b["W_held"]
    for label, key in (("buoyant weight", "W_b"), ("contact", "W_c"), ("lubrication", "W_l"),
                       ("F_H applied (fluid-moved steps)", "W_h"),
                       ("step-before F_H held (DEM-moved)", "W_held"),
                       ("F_H NOT applied (DEM-moved steps)", "W_h_not_applied")):
        print(f"    {label:36s} {b[key]:+.4e} J  ({b[key] / ke:+7.1%} of KE_start)")
    print(f"    sum of the applied works {applied:+.4e} J; momentum-balance residual "
          f"max {b['max_residual']:.2e} N")


def speeds(r, touch):
    """w at the SPEED_GAPS on the approach (interpolated in the gap, before the touch row)."""
    gap, w = r["gap"][:touch + 1], r["w"][:touch + 1]
    order = np.argsort(gap)
    return {g: float(np.interp(g, gap[order], w[order])) for g in SPEED_GAPS}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--reach", type=float, default=2.0, help="gap/d where the budget starts")
    parser.add_argument("--speeds", action="store_true", help="w against the gap, approach")
    args = parser.parse_args()
    for run in args.runs:
        r = load(run)
        s = steps(r)
        print(f"{run}: m = {r['mass']:.4e} kg, d = {r['d']} m")
        rows = first_collision(r, args.reach)
        if rows is None:
            print("  no contact")
            continue
        start, touch, separation, end = rows
        print_budget("approach", budget(s, start, touch - 1, r))
        print_budget("touch step + contact", budget(s, touch - 1, separation, r))
        print_budget("exit", budget(s, separation, end, r))
        print_budget("whole collision", budget(s, start, end, r))
        if args.speeds:
            v = speeds(r, touch)
            print("  approach w [m/s] at gap/d: " +
                  ", ".join(f"{g:g}: {v[g]:+.4f}" for g in SPEED_GAPS))
            print(f"  St at |w(gap 1 d)|: {r['stokes_scale'] * abs(v[1.0]):.1f}")


if __name__ == "__main__":
    main()
