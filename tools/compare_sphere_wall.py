#!/usr/bin/python3
"""Compare sphere-approaching-a-wall runs with Brenner's (1961) exact Stokes-flow force, or
two-spheres-approaching-head-on runs with the exact two-sphere force.

    python3 tools/compare_sphere_wall.py RUN_DIR [RUN_DIR ...] [-o fig.png] [--label NAME ...]

A run with one sphere (cases/validation/sphere_wall_approach): κ = F/(6πμrU) at the gaps δ/r =
2, 1, 0.5, 0.3, 0.2, 0.1, 0.05 (interpolated in ln δ), the resolved part alone (f*), the
lubrication correction (lubrication_f*), their sum, Brenner's series, the ratios to it, and
κ_Brenner − κ_lub: what the correction assumes the grid resolves (its c(h_Δ) subtraction), to
set beside κ_hydro; the largest deviation of the total over 0.1 ≤ δ/r ≤ 2. With -o, κ/κ_Brenner
against δ/r of every run.

A run with two spheres (cases/validation/two_sphere_approach): the same per sphere at the
surface-to-surface gaps g/r = 4, 2, 1, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.07 against the exact κ
(Brenner's free-plane series at δ = g/2, python/fddem/two_spheres.py), the largest deviation
over 0.1 ≤ g/r ≤ 2, and the largest difference between the two spheres' forces (by symmetry
they are equal and opposite). With -o, κ and κ/κ_exact against g/r of both spheres (two
panels; give the runs of one kind to one figure).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import io, sphere_wall, two_spheres  # noqa: E402
from fddem.figures import comparison_parser, pyplot, run_labels, save_one_panel  # noqa: E402


def is_pair(run):
    """A run of two spheres (else one sphere and a wall)."""
    return len(io.read_case(run).get("bodies", [])) == 2


def table(run, label):
    """The text lines of one run."""
    if not is_pair(run):
        return sphere_wall.table_lines(sphere_wall.kappa_at(run), label)
    lines = []
    for sphere, result in enumerate(two_spheres.kappa_at(run)):
        lines += sphere_wall.table_lines(result, f"{label}, sphere {sphere}", gap_name="g/r",
                                         exact_name="exact")
    a = two_spheres.asymmetry(run)
    lines.append(f"{label}: the two spheres' κ differ by at most {100 * a['hydro']:.3f} % "
                 f"(resolved) and {100 * a['lubrication']:.3f} % (lubrication), g/r >= 0.05")
    return lines


def pair_figure(path, runs, labels):
    plt = pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(7, 8), sharex=True)
    two_spheres.plot(axes, runs, labels)
    axes[0].set_title("Two spheres approaching head-on (shaded: ±10 %)", fontsize=10)
    for a in axes:
        a.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main():
    parser = comparison_parser(__doc__.splitlines()[0])
    args = parser.parse_args()
    labels = run_labels(parser, args)
    for run, label in zip(args.runs, labels):
        try:
            print("\n".join(table(run, label)))
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_sphere_wall: {run}: {error}")
    if args.output and is_pair(args.runs[0]):
        print(pair_figure(args.output, args.runs, labels))
    elif args.output:
        print(save_one_panel(args.output, lambda axes: sphere_wall.plot(axes, args.runs, labels),
                             "Sphere approaching a wall (shaded: ±10 %)", grid_which="both"))


if __name__ == "__main__":
    main()
