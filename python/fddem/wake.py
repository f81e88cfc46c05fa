"""Drag, lift, recirculation length and pressure difference of a fixed cylinder's run.

    C_D = 2 F_x / (ρ Ū² D),  C_L = 2 F_y / (ρ Ū² D),
    L_a = x_r − x_rear, x_r the first point behind the rear where u changes from negative to
          positive on samples/wake_axis.csv (linear interpolation between samples),
    Δp = p(front) − p(rear) from samples/front_back.csv.
"""

import os

import numpy as np

from . import io


def recirculation_end(x, u):
    """First x where u crosses from negative to non-negative; None if it never does."""
    for i in range(1, len(x)):
        if u[i - 1] < 0.0 <= u[i]:
            return x[i - 1] + (x[i] - x[i - 1]) * (-u[i - 1]) / (u[i] - u[i - 1])
    return None


def wake_numbers(run_dir, mean_velocity, diameter, rear, density=1.0):
    """{'C_D', 'C_L', 'L_a', 'L_a/D', 'dp'} of the run's last state (None where not measured)."""
    body = io.read_particles(run_dir)[0]
    scale = 0.5 * density * mean_velocity**2 * diameter
    axis = io.read_csv_columns(os.path.join(run_dir, "samples", "wake_axis.csv"))
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
        p = io.read_csv_columns(front_back)["p"]
        result["dp"] = p[0] - p[-1]
    return result
