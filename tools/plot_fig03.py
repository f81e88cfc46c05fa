#!/usr/bin/python3
"""Paper Figs. 3 and 4: settling velocity of a disk in a vertical channel vs time (left) and the
cumulative number of SIMPLE outer iterations vs time (right), one curve per run directory.

    python3 tools/plot_fig03.py RUN_DIR [RUN_DIR ...] -o fig03.png [--labels a b ...]

The velocity is shown made dimensionless by the case's characteristic velocity U_c (eq. 21),
read from summary.json ("characteristic_velocity") when the run derived it, else 1; the
analytic terminal value is 1 (Happel & Brenner 1965 wall-corrected Stokes drag, eqs. 19–21).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fddem_io  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run directories")
    parser.add_argument("-o", "--output", default="fig03.png", help="PNG file to write")
    parser.add_argument("--labels", nargs="*", help="legend labels, one per run")
    options = parser.parse_args()
    labels = options.labels or [fddem_io.read_case_title(r) for r in options.runs]
    if len(labels) != len(options.runs):
        parser.error("give one label per run directory")

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for run, label in zip(options.runs, labels):
        summary = fddem_io.read_summary(run)
        scale = float(summary.get("characteristic_velocity", 1.0))
        time_scale = float(summary.get("characteristic_time", 1.0))
        particles = fddem_io.read_particles(run)
        first = particles[min(particles)]
        left.plot(first["time"] / time_scale, -first["v"] / scale, label=label)
        solver = fddem_io.read_solver(run)
        right.plot(solver["time"] / time_scale, solver["total_outer_iterations"], label=label)
    left.axhline(1.0, color="k", lw=0.8, ls="--", label="analytic (Happel & Brenner 1965)")
    left.set_xlabel("t U_c / D")
    left.set_ylabel("settling velocity / U_c")
    left.set_title("settling velocity (paper Fig. 3/4, left)")
    left.legend(fontsize=8)
    right.set_xlabel("t U_c / D")
    right.set_ylabel("cumulative SIMPLE outer iterations")
    right.set_title("SIMPLE iterations (paper Fig. 3/4, right)")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(options.output, dpi=120)
    print(f"wrote {options.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
