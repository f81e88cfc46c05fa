#!/usr/bin/python3
"""fddem's DKT run (cases/validation/dkt_uhlmann2005) against Uhlmann (2005), Figs. 6-8.

    python3 tools/compare_uhlmann_dkt.py RUN_DIR -o dkt_uhlmann.png [--reference DIR] [--mirror]

Prints, per particle and quantity, the RMS and the largest deviation from the reference over
the reference's time points (fddem interpolated in time), for the drafting phase (t <= 0.15 s,
before the disks kiss) and for the whole run, and writes the five panels (streamwise and
lateral position and velocity, angular velocity). The comparison is python/fddem/uhlmann.py
(where the reference comes from and why --mirror); `fddem plot RUN_DIR` draws the same figure
as uhlmann.png, mirrored when that matches the reference better.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from fddem import Run, references, uhlmann  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--reference", default=references.uhlmann_directory())
    parser.add_argument("--mirror", action="store_true", help="mirror the lateral quantities")
    options = parser.parse_args()
    if not options.reference or not os.path.isdir(options.reference):
        print(f"compare_uhlmann_dkt: reference directory {options.reference} not found",
              file=sys.stderr)
        return 2
    fig, rows = uhlmann.comparison_figure(Run(options.run), options.reference, options.mirror)
    uhlmann.print_table(rows)
    fig.savefig(options.output)
    print(f"wrote {options.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
