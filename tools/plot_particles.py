#!/usr/bin/python3
"""The paper's particle figures (Wu & Yuan 2015, Figs. 5–13) from one fddem run directory:

    python3 tools/plot_particles.py RUN_DIR -o PREFIX [--flow-times 0.4 1.0 ...]

writes PREFIX_position.png   centre coordinates vs time (Figs. 6, 12)
       PREFIX_velocity.png   velocity components vs time (Figs. 7, 11)
       PREFIX_energy.png     translational and rotational kinetic energy vs time (Fig. 8)
       PREFIX_trajectory.png centre trajectories in the box (Fig. 13 left)
       PREFIX_iterations.png cumulative SIMPLE outer iterations vs time (Fig. 13 right)
       PREFIX_flow_T.png     vertical-velocity contours, streamlines and the particles at the
                             field output nearest each time T (Figs. 5, 9, 10)
Kinetic energies are per unit depth in 2D: m = ρs π r², J = m r²/2.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fddem_io  # noqa: E402


def label_each(ax, particles, many):
    if not many:
        ax.legend(fontsize="small")


def plot_series(particles, columns, ylabels, title, path):
    fig, axes = plt.subplots(1, len(columns), figsize=(5 * len(columns), 4))
    many = len(particles) > 6
    for ax, column, ylabel in zip(np.atleast_1d(axes), columns, ylabels):
        for pid, p in particles.items():
            ax.plot(p["time"], p[column], lw=1, label=f"particle {pid}")
        ax.set_xlabel("t")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        label_each(ax, particles, many)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_energy(particles, bodies, title, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    total_t = total_r = 0.0
    for pid, p in particles.items():
        body = bodies[pid]
        r = 0.5 * body["diameter"]
        mass = body["density"] * np.pi * r * r
        inertia = 0.5 * mass * r * r
        translational = 0.5 * mass * (p["u"] ** 2 + p["v"] ** 2)
        rotational = 0.5 * inertia * p["omega"] ** 2
        total_t = total_t + translational
        total_r = total_r + rotational
    time = next(iter(particles.values()))["time"]
    axes[0].plot(time, total_t)
    axes[0].set_ylabel("translational kinetic energy (sum over particles)")
    axes[1].plot(time, total_r)
    axes[1].set_ylabel("rotational kinetic energy (sum over particles)")
    for ax in axes:
        ax.set_xlabel("t")
        ax.grid(alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_trajectories(particles, case, title, path):
    size = case["domain"]["size"]
    origin = case["domain"].get("origin", [0.0, 0.0])
    fig, ax = plt.subplots(figsize=(3 + 2 * size[0] / size[1] * 4, 7))
    for pid, p in particles.items():
        ax.plot(p["x"], p["y"], lw=1)
        ax.plot(p["x"][0], p["y"][0], "o", ms=3, color="k")
    ax.set_xlim(origin[0], origin[0] + size[0])
    ax.set_ylim(origin[1], origin[1] + size[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title(title + "\ntrajectories (dots: start)", fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_iterations(solver, title, path):
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(solver["time"], solver["total_outer_iterations"])
    ax.set_xlabel("t")
    ax.set_ylabel("cumulative SIMPLE outer iterations")
    ax.grid(alpha=0.3)
    ax.set_title(title, fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_flow(run_dir, particles, bodies, time, title, path):
    frames = fddem_io.read_pvd(run_dir)
    t, file = min(frames, key=lambda f: abs(f[0] - time))
    field = fddem_io.read_vtr(file)
    xc = 0.5 * (field["x"][1:] + field["x"][:-1])
    yc = 0.5 * (field["y"][1:] + field["y"][:-1])
    velocity = field["velocity"][0]
    fig, ax = plt.subplots(figsize=(4, 9))
    v = velocity[:, :, 1]
    limit = np.max(np.abs(v)) or 1.0
    contour = ax.contourf(xc, yc, v, levels=np.linspace(-limit, limit, 41), cmap="RdBu_r")
    fig.colorbar(contour, ax=ax, shrink=0.6, label="v")
    ax.streamplot(xc, yc, velocity[:, :, 0], v, density=1.6, color="k", linewidth=0.4, arrowsize=0.5)
    for pid, p in particles.items():
        k = int(np.argmin(np.abs(p["time"] - t)))
        r = 0.5 * bodies[pid]["diameter"]
        ax.add_patch(Circle((p["x"][k], p["y"][k]), r, facecolor="0.6", edgecolor="k", lw=0.6))
    ax.set_aspect("equal")
    ax.set_xlim(field["x"][0], field["x"][-1])
    ax.set_ylim(field["y"][0], field["y"][-1])
    ax.set_title(f"{title}\nt = {t:.3g}", fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="run directory")
    parser.add_argument("-o", "--output", required=True, help="prefix of the PNG files")
    parser.add_argument("--flow-times", nargs="*", type=float, default=[], help="times of the flow pictures")
    options = parser.parse_args()
    run = options.run
    title = fddem_io.read_case_title(run)
    case = fddem_io.read_case(run)
    bodies = case.get("bodies", [])
    particles = fddem_io.read_particles(run)
    if not particles:
        sys.exit(f"plot_particles: {run}: particles.csv has no rows")
    prefix = options.output
    plot_series(particles, ["x", "y"], ["x of the centre", "y of the centre"], title, prefix + "_position.png")
    plot_series(particles, ["u", "v"], ["u (x-velocity)", "v (y-velocity)"], title, prefix + "_velocity.png")
    plot_energy(particles, bodies, title, prefix + "_energy.png")
    plot_trajectories(particles, case, title, prefix + "_trajectory.png")
    plot_iterations(fddem_io.read_solver(run), title, prefix + "_iterations.png")
    for t in options.flow_times:
        plot_flow(run, particles, bodies, t, title, f"{prefix}_flow_{t:g}.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
