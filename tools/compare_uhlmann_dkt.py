#!/usr/bin/python3
"""fddem's DKT run (cases/validation/dkt_uhlmann2005) against Uhlmann (2005), Figs. 6-8.

    python3 tools/compare_uhlmann_dkt.py RUN_DIR -o dkt_uhlmann.png [--reference DIR]

The reference curves are third-party digitisations of Uhlmann's figures kept outside the
repository (../shared/reference/digitized/uhlmann_2005, see its README: about 1-2 % in value and
0.005-0.02 s in time); they are read from there, never copied. Uhlmann measures the streamwise
position downwards from the top wall and the lateral one from the centre line; fddem's run has
gravity along −y in a (0,2) × (0,6) box, so streamwise = 6 − y, lateral = x − 1.

Prints, per particle and quantity, the RMS and the largest deviation from the reference over
the reference's time points (fddem interpolated in time), for the drafting phase (t <= 0.15 s,
before the disks kiss) and for the whole run, and writes a figure with the five panels
(streamwise and lateral position and velocity, angular velocity).

--mirror flips the sign of the lateral position, lateral velocity and angular velocity: the side
to which the pair tumbles is set by a ±d/250 seed through a chaotic kiss and may come out
mirrored (it does at h = d/16); the mirrored run is an equally valid solution.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fddem_io  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_REFERENCE = os.path.join(HERE, "..", "..", "shared", "reference", "digitized", "uhlmann_2005")
TOP = 6.0
CENTRE = 1.0

# (figure file stem, label, unit, function of (t, x, y, u, v, omega) giving Uhlmann's quantity)
QUANTITIES = [
    ("fig6a", "streamwise position", "cm", lambda r: TOP - r["y"]),
    ("fig6b", "streamwise velocity", "cm/s", lambda r: -r["v"]),
    ("fig7a", "lateral position", "cm", lambda r: r["x"] - CENTRE),
    ("fig7b", "lateral velocity", "cm/s", lambda r: r["u"]),
    ("fig8", "angular velocity", "1/s", lambda r: r["omega"]),
]
PARTICLES = [(0, "trailing"), (1, "leading")]


def load_reference(directory, stem, particle):
    path = os.path.join(directory, f"Uhlmann2005-{stem}-{particle}-particle.csv")
    data = np.loadtxt(path)
    return data[np.argsort(data[:, 0])]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--reference", default=DEFAULT_REFERENCE)
    parser.add_argument("--mirror", action="store_true", help="mirror the lateral quantities")
    options = parser.parse_args()
    if not os.path.isdir(options.reference):
        print(f"compare_uhlmann_dkt: reference directory {options.reference} not found", file=sys.stderr)
        return 2

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = fddem_io.read_particles(options.run)
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(4.2 * len(QUANTITIES), 3.8))
    print(f"{'quantity':<22} {'particle':<9} {'rms t<=0.15':>11} {'rms all':>9} {'max all':>9} "
          f"{'ref range':>10}  unit")
    for ax, (stem, label, unit, quantity) in zip(axes, QUANTITIES):
        for body, name in PARTICLES:
            mine = rows[body]
            t = mine["time"]
            value = quantity(mine)
            if options.mirror and stem in ("fig7a", "fig7b", "fig8"):
                value = -value
            ref = load_reference(options.reference, stem, name)
            inside = ref[:, 0] <= t[-1]
            ref_t, ref_v = ref[inside, 0], ref[inside, 1]
            deviation = np.interp(ref_t, t, value) - ref_v
            span = ref_v.max() - ref_v.min()
            drafting = ref_t <= 0.15
            print(f"{label:<22} {name:<9} {np.sqrt(np.mean(deviation[drafting] ** 2)):>11.3f} "
                  f"{np.sqrt(np.mean(deviation ** 2)):>9.3f} {np.abs(deviation).max():>9.3f} "
                  f"{span:>10.3f}  {unit}")
            colour = "C0" if body == 0 else "C3"
            mirrored = " (mirrored)" if options.mirror and stem in ("fig7a", "fig7b", "fig8") else ""
            ax.plot(t, value, color=colour, label=f"fddem, {name}{mirrored}")
            ax.plot(ref_t, ref_v, "o", ms=3, mfc="none", color=colour, label=f"Uhlmann 2005, {name}")
        ax.set_xlabel("t [s]")
        ax.set_ylabel(f"{label} [{unit}]")
        ax.set_title(f"{stem} ({label})", fontsize=10)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(fddem_io.read_case_title(options.run), fontsize=11)
    fig.tight_layout()
    fig.savefig(options.output, dpi=110)
    print(f"wrote {options.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
