"""Periodic vortex shedding behind a fixed cylinder: C_D,max, C_L,max and the Strouhal number
from the force history of a run, as Schäfer & Turek (1996) define them for their 2D-2 benchmark
(Re 100; cases/validation/schafer_turek_2d2).

    C_D = 2 F_x / (ρ Ū² D),  C_L = 2 F_y / (ρ Ū² D)   (particles.csv: fx, fy of the first body)
    St  = D / (Ū T),  T the period of C_L

The maxima are taken over the last `periods` full periods of C_L (between its upward zero
crossings, linearly interpolated), so they describe the saturated shedding, not the start-up.
The band of the benchmark (its Table 4, the spread of the groups' best values):
C_D,max 3.22–3.24, C_L,max 0.99–1.01, St 0.295–0.305.
"""

import numpy as np

from . import io

# Schäfer & Turek (1996), "Benchmark computations of laminar flow around a cylinder", Table 4
# ("lower bound" – "upper bound" of test case 2D-2); reference/SOURCE.md of the case.
BAND = {"C_D,max": (3.22, 3.24), "C_L,max": (0.99, 1.01), "St": (0.295, 0.305)}
LABEL = "Schäfer & Turek (1996) 2D-2 band"


def coefficients(run_dir, mean_velocity, diameter, density=1.0):
    """(t, C_D, C_L) of the run's first body."""
    particles = io.read_particles(run_dir)
    body = particles[min(particles)]
    scale = 0.5 * density * mean_velocity**2 * diameter
    return body["time"], body["fx"] / scale, body["fy"] / scale


def upward_crossings(t, values):
    """Times where `values` crosses zero from below (linear interpolation between samples)."""
    below = values[:-1] < 0.0
    above = values[1:] >= 0.0
    i = np.nonzero(below & above)[0]
    return t[i] - values[i] * (t[i + 1] - t[i]) / (values[i + 1] - values[i])


def shedding_numbers(run_dir, mean_velocity, diameter, density=1.0, periods=5):
    """{'C_D,max', 'C_L,max', 'C_L,min', 'St', 'window', 'periods'} over the last `periods` full
    lift periods. Raises ValueError when the lift has fewer than `periods` + 1 upward crossings
    (no periodic shedding yet)."""
    t, drag, lift = coefficients(run_dir, mean_velocity, diameter, density)
    crossings = upward_crossings(t, lift - np.mean(lift[len(lift) // 2:]))
    if len(crossings) < periods + 1:
        raise ValueError(f"{run_dir}: {len(crossings)} upward zero crossings of C_L, "
                         f"{periods + 1} needed for {periods} periods of shedding")
    window = (float(crossings[-periods - 1]), float(crossings[-1]))
    inside = (t >= window[0]) & (t <= window[1])
    period = (window[1] - window[0]) / periods
    return {"C_D,max": float(np.max(drag[inside])), "C_L,max": float(np.max(lift[inside])),
            "C_L,min": float(np.min(lift[inside])), "St": diameter / (mean_velocity * period),
            "window": window, "periods": periods}


def plot(ax_drag, ax_lift, run_dir, mean_velocity, diameter, label="fddem", density=1.0):
    """C_D(t) and C_L(t) of the run on two axes, with the benchmark's C_D,max and ±C_L,max bands
    shaded and the window the maxima were taken from marked."""
    t, drag, lift = coefficients(run_dir, mean_velocity, diameter, density)
    ax_drag.plot(t, drag, label=label)
    ax_drag.axhspan(*BAND["C_D,max"], color="k", alpha=0.25, label="C_D,max, " + LABEL)
    ax_lift.plot(t, lift, label=label)
    ax_lift.axhspan(*BAND["C_L,max"], color="k", alpha=0.25, label="C_L,max, " + LABEL)
    ax_lift.axhspan(-BAND["C_L,max"][1], -BAND["C_L,max"][0], color="k", alpha=0.25)
    try:
        window = shedding_numbers(run_dir, mean_velocity, diameter, density)["window"]
        for ax in (ax_drag, ax_lift):
            ax.axvspan(*window, color="C1", alpha=0.12, label="window of the maxima")
    except ValueError:
        pass
    # The start-up (an impulsive start: C_D reaches ±100 in the first steps) is off the scale.
    settled = t >= t[-1] / 4.0
    low = min(np.min(drag[settled]), BAND["C_D,max"][0]) - 0.1
    high = max(np.max(drag[settled]), BAND["C_D,max"][1]) + 0.1
    ax_drag.set_ylim(low, high)
    ax_drag.set_ylabel("C_D")
    ax_lift.set_ylabel("C_L")
    ax_lift.set_xlabel("t [s]")
    ax_drag.legend(loc="center left", fontsize=7)
    ax_lift.set_ylim(-1.25, 1.6)
    ax_lift.legend(loc="upper left", fontsize=7, ncol=2)
