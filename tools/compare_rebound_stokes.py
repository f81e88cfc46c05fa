#!/usr/bin/python3
"""Effective restitution against the Stokes number: fddem's rebound runs against Legendre et al.

    python3 tools/compare_rebound_stokes.py RUN_DIR [RUN_DIR ...] [-o fig.png]

Each RUN_DIR is a two-stage rebound run (cases/validation/gondret_rebound_st152, as its header
says, possibly with fluid.viscosity changed). For each run: the impact speed v_in and the
rebound speed v_out, measured from the trajectory as on Gondret's data (python/fddem/rebound.py:
slopes at the first contact of fits to 0.02 d ≤ gap ≤ 1 d), e_eff = −v_out/v_in, the contact's
own ratio of speeds (touch to separation), and St = ρp v_in d / (9 μ) with the run's ρp, d and
μ. Printed as a table; with -o, e_eff/e_dry against St over the fit of Legendre, Zenit, Daniel &
Guiraud (2006), e/e_dry = exp(−35/St) (cases/validation/rebound_stokes/legendre2006_fit.md), and
Gondret et al.'s (2002) two trajectories measured the same way (St 27 and 152 at their
published impact speeds; the St 27 file starts at the contact, so there v_out over the published
impact speed).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import io, rebound  # noqa: E402
from fddem.figures import pyplot  # noqa: E402

LEGENDRE_BETA = 35.0  # e/e_dry = exp(−β/St), legendre2006_fit.md


def measure_run(run_dir):
    """St, v_in, v_out, e_eff/e_dry and the contact's speed ratio of one run, as a dict."""
    case = io.read_case(run_dir)
    body = case["bodies"][0]
    density = float(body["density"])
    viscosity = float(case["fluid"]["viscosity"])
    e_dry = float(case.get("contact", {}).get("restitution", 1.0))
    t, gap, w, diameter = rebound.run_trajectory(run_dir)
    result = rebound.measure(t, gap, diameter=diameter)
    result.update(rebound.touch_speeds(t, gap, w, result["t_contact"]))
    v_in = -result["v_in"] if result["v_in"] is not None else result["touch"]
    result["stokes"] = density * v_in * diameter / (9.0 * viscosity)
    result["e_dry"] = e_dry
    result["ratio"] = None if result["e_eff"] is None else result["e_eff"] / e_dry
    return result


def reference_points():
    """(St, e_eff/e_dry) of Gondret's two digitised trajectories, measured as the runs are, St at
    the published impact speed (Biegert et al. 2017 Table 1 via rebound.CASES), e_dry = 0.97."""
    points = []
    for name, spec in sorted(rebound.CASES.items()):
        t, gap = rebound.load_reference(name)
        r = rebound.measure(t, gap, t_c=None if spec["has_approach"] else 0.0,
                            diameter=spec["diameter"])
        if r["e_eff"] is not None:
            points.append((spec["stokes"], r["e_eff"] / 0.97))
        elif r["v_out"] is not None:  # no approach in the file (St 27): the published impact
            points.append((spec["stokes"], r["v_out"] / spec["impact"] / 0.97))
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="rebound run directories")
    parser.add_argument("-o", "--output", help="write the figure (PNG)")
    args = parser.parse_args()
    rows = []
    print(f"{'run':40s} {'St':>7s} {'v_in':>7s} {'v_out':>7s} {'e_eff':>6s} {'e/e_dry':>7s} "
          f"{'exp(-35/St)':>11s} {'contact':>7s}")
    for run in args.runs:
        try:
            r = measure_run(run)
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_rebound_stokes: {run}: {error}")
        fit = math.exp(-LEGENDRE_BETA / r["stokes"])

        def number(x, fmt):
            return "n/a" if x is None else format(x, fmt)

        print(f"{os.path.basename(os.path.normpath(run)):40s} {r['stokes']:7.1f} "
              f"{number(r['v_in'], '7.4f')} {number(r['v_out'], '7.4f')} "
              f"{number(r['e_eff'], '6.3f')} {number(r['ratio'], '7.3f')} {fit:11.3f} "
              f"{number(r['e_contact'], '7.3f')}")
        rows.append(r)
    if not args.output:
        return
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    st = np.logspace(0, 3.2, 200)
    ax.plot(st, np.exp(-LEGENDRE_BETA / st), "k-", label="Legendre et al. (2006): exp(−35/St)")
    ref = reference_points()
    if ref:
        ax.plot([p[0] for p in ref], [p[1] for p in ref], "ks", mfc="none",
                label="Gondret et al. (2002), trajectories measured as the runs")
    measured = [(r["stokes"], r["ratio"] if r["ratio"] is not None else 0.0) for r in rows]
    ax.plot([m[0] for m in measured], [m[1] for m in measured], "ro",
            label="fddem, d/h = 8 (no rebound plotted as 0)")
    for (x, y), run in zip(measured, args.runs):
        ax.annotate(os.path.basename(os.path.normpath(run)), (x, y), textcoords="offset points",
                    xytext=(5, -12), fontsize=7)
    ax.set_xscale("log")
    ax.set_xlabel("St = ρp v_in d / (9 μ)")
    ax.set_ylabel("e_eff / e_dry")
    ax.set_ylim(-0.05, 1.12)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Sphere–wall rebound in a viscous fluid: effective restitution against St")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
