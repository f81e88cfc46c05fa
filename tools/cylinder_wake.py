#!/usr/bin/python3
"""Drag, lift, recirculation length and pressure difference of a fixed cylinder's run.

    /usr/bin/python3 tools/cylinder_wake.py RUN_DIR [--mean-velocity 0.2] [--diameter 0.1]
                                           [--rear 0.25] [--density 1.0]

Reads particles.csv (the body's fx, fy at the last row), samples/wake_axis.csv (u along the
axis behind the cylinder, starting at its rear point) and, if present, samples/front_back.csv
(p at the front and rear points); the definitions are in python/fddem/wake.py. Defaults are the
Schäfer & Turek (1996) 2D-1 benchmark (cases/verification/cylinder_re20). `fddem plot RUN_DIR`
draws the wake axis and the force coefficients against the references.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from fddem.wake import wake_numbers  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--mean-velocity", type=float, default=0.2, help="Ū [m/s]")
    parser.add_argument("--diameter", type=float, default=0.1, help="D [m]")
    parser.add_argument("--rear", type=float, default=0.25, help="x of the cylinder's rear point [m]")
    parser.add_argument("--density", type=float, default=1.0, help="ρ [kg/m³]")
    options = parser.parse_args()
    numbers = wake_numbers(options.run_dir, options.mean_velocity, options.diameter, options.rear,
                           options.density)
    for name, value in numbers.items():
        print(f"{name:6s} {'n/a' if value is None else f'{value:.5g}'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
