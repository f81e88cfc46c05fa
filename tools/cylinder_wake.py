#!/usr/bin/python3
"""Drag, lift, recirculation length and pressure difference of a fixed cylinder's run.

    /usr/bin/python3 tools/cylinder_wake.py RUN_DIR [--mean-velocity 0.2] [--diameter 0.1]
                                           [--rear 0.25] [--density 1.0]

Reads particles.csv (the body's fx, fy at the last row), samples/wake_axis.csv (u along the
axis behind the cylinder, starting at its rear point) and, if present, samples/front_back.csv
(p at the front and rear points). Prints

    C_D = 2 F_x / (ρ Ū² D),  C_L = 2 F_y / (ρ Ū² D),
    L_a = x_r − x_rear, x_r the first point behind the rear where u changes from negative to
          positive (linear interpolation between samples), and L_a / D,
    Δp = p(front) − p(rear).

Defaults are the Schäfer & Turek (1996) 2D-1 benchmark (cases/verification/cylinder_re20).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fddem_io  # noqa: E402


def recirculation_end(x, u):
    """First x where u crosses from negative to non-negative; None if it never does."""
    for i in range(1, len(x)):
        if u[i - 1] < 0.0 <= u[i]:
            return x[i - 1] + (x[i] - x[i - 1]) * (-u[i - 1]) / (u[i] - u[i - 1])
    return None


def wake_numbers(run_dir, mean_velocity, diameter, rear, density=1.0):
    """{'C_D', 'C_L', 'L_a', 'L_a/D', 'dp'} of the run's last state (dp None without the sample)."""
    body = fddem_io.read_particles(run_dir)[0]
    scale = 0.5 * density * mean_velocity**2 * diameter
    axis = fddem_io.read_csv_columns(os.path.join(run_dir, "samples", "wake_axis.csv"))
    x_r = recirculation_end(np.asarray(axis["x"]), np.asarray(axis["u"]))
    length = None if x_r is None else x_r - rear
    result = {
        "C_D": body["fx"][-1] / scale,
        "C_L": body["fy"][-1] / scale,
        "L_a": length,
        "L_a/D": None if length is None else length / diameter,
        "dp": None,
    }
    front_back = os.path.join(run_dir, "samples", "front_back.csv")
    if os.path.exists(front_back):
        p = fddem_io.read_csv_columns(front_back)["p"]
        result["dp"] = p[0] - p[-1]
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
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
