#!/usr/bin/python3
"""Paper Figs. 3 and 4 with several runs on one figure: settling velocity / U_c and cumulative
SIMPLE outer iterations against t U_c / D, one curve per run directory.

    python3 tools/plot_fig03.py RUN_DIR [RUN_DIR ...] -o fig03.png [--labels a b ...]

(`fddem plot RUN_DIR` draws the same figure for one run, as settling.png.) The analytic terminal
value is 1 (Happel & Brenner 1965 wall-corrected Stokes drag, eqs. 19-21).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from fddem import Run  # noqa: E402
from fddem.figures import settling_figure  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run directories")
    parser.add_argument("-o", "--output", default="fig03.png", help="figure file to write")
    parser.add_argument("--labels", nargs="*", help="legend labels, one per run")
    options = parser.parse_args()
    if options.labels and len(options.labels) != len(options.runs):
        parser.error("give one label per run directory")
    fig = settling_figure([Run(r) for r in options.runs], options.labels)
    if fig is None:
        parser.error("no run derived U_c (a settling case with [nondimensional])")
    fig.savefig(options.output)
    print(f"wrote {options.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
