"""fddem's DKT run (cases/validation/dkt_uhlmann2005) against Uhlmann (2005), Figs. 6-8.

The reference curves are third-party digitisations of Uhlmann's figures kept outside the
repository (references.uhlmann_directory(): about 1-2 % in value and 0.005-0.02 s in time); they
are read from there, never copied. Uhlmann measures the streamwise position downwards from the
top wall and the lateral one from the centre line; fddem's run has gravity along −y in a
(0,2) × (0,6) box, so streamwise = 6 − y, lateral = x − 1.

The side to which the pair tumbles is set by a ±d/250 seed through a chaotic kiss and may come
out mirrored (it does at h = d/16); the mirrored run is an equally valid solution, so `mirror`
flips the sign of the lateral position, lateral velocity and angular velocity (None: whichever
is closer to the reference's lateral position).
"""

import os

import numpy as np

TOP = 6.0
CENTRE = 1.0
DRAFTING_END = 0.15  # s: the disks kiss after this

# (figure file stem, label, unit, Uhlmann's quantity from one body's history, is lateral)
QUANTITIES = [
    ("fig6a", "streamwise position", "cm", lambda r: TOP - r["y"], False),
    ("fig6b", "streamwise velocity", "cm/s", lambda r: -r["v"], False),
    ("fig7a", "lateral position", "cm", lambda r: r["x"] - CENTRE, True),
    ("fig7b", "lateral velocity", "cm/s", lambda r: r["u"], True),
    ("fig8", "angular velocity", "1/s", lambda r: r["omega"], True),
]
PARTICLES = [(0, "trailing"), (1, "leading")]


def load_reference(directory, stem, particle):
    data = np.loadtxt(os.path.join(directory, f"Uhlmann2005-{stem}-{particle}-particle.csv"))
    return data[np.argsort(data[:, 0])]


def deviations(histories, directory, mirror):
    """Rows (stem, label, unit, particle, t, value, ref_t, ref_v, rms drafting, rms, max)."""
    rows = []
    for stem, label, unit, quantity, lateral in QUANTITIES:
        for body, name in PARTICLES:
            mine = histories[body]
            t = mine["time"]
            value = quantity(mine) * (-1.0 if mirror and lateral else 1.0)
            ref = load_reference(directory, stem, name)
            inside = ref[:, 0] <= t[-1]
            ref_t, ref_v = ref[inside, 0], ref[inside, 1]
            deviation = np.interp(ref_t, t, value) - ref_v
            drafting = ref_t <= DRAFTING_END
            rms_drafting = float(np.sqrt(np.mean(deviation[drafting] ** 2))) if drafting.any() else np.nan
            rows.append((stem, label, unit, name, t, value, ref_t, ref_v, rms_drafting,
                         float(np.sqrt(np.mean(deviation**2))) if len(deviation) else np.nan,
                         float(np.abs(deviation).max()) if len(deviation) else np.nan))
    return rows


def choose_mirror(histories, directory):
    """Whether the mirrored run is closer to the reference's lateral position."""
    def lateral_rms(mirror):
        return sum(r[9] for r in deviations(histories, directory, mirror) if r[0] == "fig7a")
    return lateral_rms(True) < lateral_rms(False)


def comparison_figure(run, directory, mirror=None):
    """(figure with the five panels, deviation rows)."""
    from .figures import pyplot

    histories = run.body_histories()
    if mirror is None:
        mirror = choose_mirror(histories, directory)
    rows = deviations(histories, directory, mirror)
    plt = pyplot()
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(4.0 * len(QUANTITIES), 3.7))
    for ax, (stem, label, unit, _, lateral) in zip(axes, QUANTITIES):
        for row in (r for r in rows if r[0] == stem):
            colour = "C0" if row[3] == "trailing" else "C3"
            mirrored = " (mirrored)" if mirror and lateral else ""
            ax.plot(row[4], row[5], color=colour, label=f"fddem, {row[3]}{mirrored}")
            ax.plot(row[6], row[7], "o", ms=3, mfc="none", color=colour,
                    label=f"Uhlmann (2005), {row[3]}")
        ax.set_xlabel("t [s]")
        ax.set_ylabel(f"{label} [{unit}]")
        ax.set_title(f"Uhlmann (2005) {stem.replace('fig', 'Fig. ')}: {label}")
    axes[0].legend()
    fig.suptitle(run.title)
    fig.tight_layout()
    return fig, rows


def print_table(rows, write=print):
    write(f"{'quantity':<22} {'particle':<9} {'rms t<=0.15':>11} {'rms all':>9} {'max all':>9} "
          f"{'ref range':>10}  unit")
    for stem, label, unit, name, _, _, _, ref_v, rms_drafting, rms, largest in rows:
        span = ref_v.max() - ref_v.min() if len(ref_v) else np.nan
        write(f"{label:<22} {name:<9} {rms_drafting:>11.3f} {rms:>9.3f} {largest:>9.3f} "
              f"{span:>10.3f}  {unit}")
