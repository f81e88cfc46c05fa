#!/usr/bin/python3
"""Check a pile of balls settled from random insertion (the soak of issues 14 and 16).

    python3 tools/check_pile.py RUN_DIR [--overlap-bound 0.01] [-o pile.png]

Prints one line per check (no blow-up, no escape, the same bodies at every output, contact
overlaps below the bound relative to the radius, at rest at the end; python/fddem/pile.py) and
exits 1 if one fails, 2 if the run cannot be read. With -o, the final pile seen from the side and
the fastest body's speed and the largest overlap against time.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import io, pile  # noqa: E402
from fddem.figures import pyplot  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--overlap-bound", type=float, default=0.01,
                        help="largest overlap allowed, as a fraction of the radius (default 0.01)")
    parser.add_argument("-o", "--output", help="figure (PNG)")
    args = parser.parse_args()
    try:
        io.check_run_directory(args.run)
        lines = pile.checks(args.run, args.overlap_bound)
    except (OSError, KeyError, ValueError) as error:
        print(f"check_pile: {args.run}: {error}", file=sys.stderr)
        return 2
    failed = 0
    for quantity, measured, reference, tolerance, source in lines:
        ok = abs(measured - reference) <= tolerance
        failed += not ok
        print(f"{'pass' if ok else 'FAIL'}  {quantity}: {measured:.4g} (want {reference:g} ± {tolerance:g}; {source})")
    if args.output:
        plt = pyplot()
        fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
        pile.plot_side(axes[0], args.run)
        pile.plot_history(axes[1], args.run, args.overlap_bound)
        fig.suptitle(io.read_case_title(args.run), fontsize=9)
        fig.tight_layout()
        fig.savefig(args.output, dpi=120)
        plt.close(fig)
        print(args.output)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
