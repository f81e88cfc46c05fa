#!/usr/bin/python3
"""Compare sphere-approaching-a-wall runs with Brenner's (1961) exact Stokes-flow force.

    python3 tools/compare_sphere_wall.py RUN_DIR [RUN_DIR ...] [-o fig.png] [--label NAME ...]

For each run (cases/validation/sphere_wall_approach): κ = F/(6πμrU) at the gaps δ/r = 2, 1, 0.5,
0.3, 0.2, 0.1, 0.05 (interpolated in ln δ), the resolved part alone (f*), the lubrication
correction (lubrication_f*), their sum, Brenner's series, the ratios to it, and κ_Brenner − κ_lub:
what the correction assumes the grid resolves (its c(h_Δ) subtraction), to set beside κ_hydro; the
largest deviation of the total over 0.1 ≤ δ/r ≤ 2. With -o, κ/κ_Brenner against δ/r of every run.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import sphere_wall  # noqa: E402
from fddem.figures import comparison_parser, run_labels  # noqa: E402


def main():
    parser = comparison_parser(__doc__.splitlines()[0])
    args = parser.parse_args()
    labels = run_labels(parser, args)
    for run, label in zip(args.runs, labels):
        try:
            r = sphere_wall.kappa_at(run)
            worst = sphere_wall.deviation(r)
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_sphere_wall: {run}: {error}")
        print(f"{label}: largest deviation of the total over 0.1 <= δ/r <= 2: "
              f"{100 * worst['max']:+.1f} % at δ/r = {worst['max_at']:g}")
        print(f"  {'δ/r':>5s} {'κ_hydro':>8s} {'κ_lub':>8s} {'κ_total':>8s} {'Brenner':>8s} "
              f"{'total/B':>8s} {'hydro/B':>8s} {'B − lub':>8s}")
        for k, x in enumerate(r["delta_over_r"]):
            cells = [r[name][k] for name in ("hydro", "lubrication", "total", "brenner",
                                             "ratio", "hydro_ratio")]
            cells.append(r["brenner"][k] - r["lubrication"][k])
            print(f"  {x:5.2f} " + " ".join("     n/a" if not np.isfinite(c) else f"{c:8.4f}"
                                            for c in cells))
    if args.output:
        from fddem.figures import save_one_panel

        print(save_one_panel(args.output, lambda axes: sphere_wall.plot(axes, args.runs, labels),
                             "Sphere approaching a wall (shaded: ±10 %)", grid_which="both"))


if __name__ == "__main__":
    main()
