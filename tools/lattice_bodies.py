#!/usr/bin/python3
"""Prints [[bodies]] tables for disks on a rectangular lattice, to append to a case file.

    python3 tools/lattice_bodies.py --columns 10 --rows 10 --x0 0.145 --dx 0.19 \\
        --y0 5.85 --dy -0.19 --diameter 0.15 --density 1.25 [--jitter 0.01 --seed 1]

Rows go from y0 in steps of dy, columns from x0 in steps of dx. --jitter moves each centre by
a uniform random amount in [-jitter, jitter] per axis (seeded, so the output is reproducible),
which breaks the lattice's symmetry the way a real suspension is never symmetric.
"""
import argparse
import random
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--columns", type=int, required=True)
    parser.add_argument("--rows", type=int, required=True)
    parser.add_argument("--x0", type=float, required=True)
    parser.add_argument("--dx", type=float, required=True)
    parser.add_argument("--y0", type=float, required=True)
    parser.add_argument("--dy", type=float, required=True)
    parser.add_argument("--diameter", type=float, required=True)
    parser.add_argument("--density", type=float, required=True)
    parser.add_argument("--jitter", type=float, default=0.0)
    parser.add_argument("--seed", type=int, default=1)
    options = parser.parse_args()
    if options.jitter * 2 >= min(abs(options.dx), abs(options.dy)) - options.diameter:
        print("lattice_bodies: --jitter would let neighbouring disks overlap", file=sys.stderr)
        return 2
    rng = random.Random(options.seed)
    for row in range(options.rows):
        for column in range(options.columns):
            x = options.x0 + column * options.dx + rng.uniform(-options.jitter, options.jitter)
            y = options.y0 + row * options.dy + rng.uniform(-options.jitter, options.jitter)
            print("[[bodies]]")
            print('shape = "disk"')
            print(f"diameter = {options.diameter:g}")
            print(f"density = {options.density:g}")
            print(f"position = [{x:.6f}, {y:.6f}]")
            print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
