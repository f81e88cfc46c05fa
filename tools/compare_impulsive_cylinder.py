#!/usr/bin/python3
"""Compare impulsively started cylinder runs with Koumoutsakos & Leonard (1995).

    python3 tools/compare_impulsive_cylinder.py RUN_DIR [RUN_DIR ...] [-o fig.png]
                                                [--window 0.5 6] [--label NAME ...]

For each run: its Re (ρUD/μ from its case.toml) picks the reference curve (550 or 3000); fddem's
C_D = 2 F_x/(ρ U² D) is interpolated onto the reference points in the window of tU/R (R the
radius, the paper's time scale) and the RMS, largest and mean relative deviations are printed.
With -o, C_D(tU/R) of every run against the digitised curve.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import impulsive_cylinder  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("-o", "--output")
    parser.add_argument("--window", nargs=2, type=float, default=impulsive_cylinder.WINDOW,
                        metavar=("FROM", "TO"), help="tU/R range compared (default: %(default)s)")
    parser.add_argument("--label", nargs="+", help="legend labels, one per run")
    args = parser.parse_args()
    if args.label and len(args.label) != len(args.runs):
        parser.error("give one --label per run")
    labels = args.label or [os.path.basename(os.path.normpath(r)) for r in args.runs]
    print(f"{'run':32s} {'Re':>5s} {'RMS':>7s} {'max':>8s} {'at tU/R':>8s} {'mean':>8s} "
          f"{'tU/R compared':>14s} {'points':>6s}")
    for run, label in zip(args.runs, labels):
        try:
            r = impulsive_cylinder.compare(run, window=tuple(args.window))
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_impulsive_cylinder: {run}: {error}")
        print(f"{label:32s} {r['reynolds']:5d} {100 * r['rms']:6.2f}% {100 * r['max']:+7.2f}% "
              f"{r['max_at']:8.2f} {100 * r['mean']:+7.2f}% {r['window'][0]:6.2f}–{r['window'][1]:<6.2f} "
              f"{r['points']:6d}")
    if args.output:
        from fddem.figures import save_one_panel

        print(save_one_panel(
            args.output,
            lambda axes: impulsive_cylinder.plot(axes, args.runs, labels, window=tuple(args.window)),
            "Impulsively started cylinder (shaded: the compared window)"))


if __name__ == "__main__":
    main()
