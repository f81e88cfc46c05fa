#!/usr/bin/python3
"""The marker retraction that gives a body its exact Stokes drag, for a kernel and a resolution.

    python3 tools/stokes_retraction.py --dim 3 --kernel roma3_smoothed --retractions 0.4 0.5 0.6
    python3 tools/stokes_retraction.py --dim 2 --kernel hat --cells-per-diameter 20

A diffuse body is hydrodynamically larger or smaller than its nominal diameter by a fraction of
a cell that depends on the kernel and the marker layout. `coupling.marker_retraction` (the
outermost marker shell's depth below the surface, in cells) sets it. This tool measures it on a
flow with an exact answer: creeping flow through a periodic array of fixed bodies, driven by a
uniform force f on the fluid (cases/verification/sphere_array_stokes, cylinder_array_stokes). At
steady state the body holds the whole drive, F = f L^dim, and the mean velocity U over the cell
(the fluid inside the body held at rest, as in the exact problem) is fixed by the drag law of
the array:

- simple cubic array of spheres (Sangani & Acrivos 1982, Int. J. Multiphase Flow 8, 343, after
  Hasimoto 1959): F = 6π μ a U K(φ), K = 1 / (1 − 1.7601 φ^{1/3} + φ − 1.5593 φ² + 3.9799 φ^{8/3}
  − 3.0734 φ^{10/3}), accurate to 0.1 % for φ < 0.03;
- square array of cylinders (Sangani & Acrivos 1982, Int. J. Multiphase Flow 8, 193, their
  dilute series): F = 4π μ U / (−½ ln φ − 0.738 + φ − 0.887 φ² + 2.039 φ³), per unit length.

Each retraction is one `fddem run` of the case; the table gives U / U_exact (above 1: the body
is hydrodynamically too small, its drag low) and the retraction where it crosses 1, by linear
interpolation between the two bracketing runs (exit status 1 if no pair brackets it). The
answer belongs to the kernel, layout and forcing at this resolution and in this array: it moves
by a few hundredths of a cell with the volume fraction (--box) and more with d/h, so run it at
the resolution it is meant for. It uses an exact solution only, no validation reference;
docs/method.md §4, "The retraction from the Stokes drag", has fddem's values.

Bad arguments exit with status 2 and one message, before any run. Each run uses one OpenMP
thread unless OMP_NUM_THREADS is set.
"""

import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

from fddem import io  # noqa: E402

KERNELS = ("hat", "roma3", "peskin4", "roma3_smoothed")

CASES = {2: "cases/verification/cylinder_array_stokes/case.toml",
         3: "cases/verification/sphere_array_stokes/case.toml"}


def sphere_array_k(phi):
    """K = F / (6π μ a U) of a simple cubic array of spheres (Sangani & Acrivos 1982)."""
    c = phi ** (1.0 / 3.0)
    return 1.0 / (1.0 - 1.7601 * c + phi - 1.5593 * phi**2 + 3.9799 * c**8 - 3.0734 * c**10)


def cylinder_array_resistance(phi):
    """F / (μ U) per unit length of a square array of cylinders (Sangani & Acrivos 1982)."""
    return 4.0 * math.pi / (-0.5 * math.log(phi) - 0.738 + phi - 0.887 * phi**2 + 2.039 * phi**3)


def exact_mean_velocity(dim, box, diameter, viscosity, drive):
    """U of the exact array for the drive f [force per volume] on a cubic (square) cell of side
    box, and φ."""
    force = drive * box**dim
    if dim == 3:
        phi = math.pi / 6.0 * diameter**3 / box**3
        return force / (6.0 * math.pi * viscosity * 0.5 * diameter * sphere_array_k(phi)), phi
    phi = math.pi / 4.0 * diameter**2 / box**2
    return force / (viscosity * cylinder_array_resistance(phi)), phi


def exact_for_run(run_dir, dim):
    """U_exact and φ for the case as run (its drive, viscosity, diameter and box, so that --set
    overrides of any of them are honoured)."""
    case = io.read_case(run_dir)
    box = case["domain"]["size"]
    if any(abs(b - box[0]) > 1e-12 * box[0] for b in box):
        raise SystemExit(f"error: {run_dir}: the exact solution is for a cubic/square cell, "
                         f"domain.size is {box}")
    drive = case["fluid"]["body_force"][0]
    return exact_mean_velocity(dim, box[0], case["bodies"][0]["diameter"],
                               case["fluid"]["viscosity"], drive)


def mean_velocity(run_dir):
    """The mean of u_x over the last field frame (cell-centred values: on a periodic grid the
    same as the mean over the faces)."""
    frames = io.read_pvd(run_dir)
    if not frames:
        raise SystemExit(f"error: {run_dir} has no field frame (fields.pvd)")
    field = io.read_vtr(frames[-1][1])
    u = field["velocity"]
    return float(u[..., 0].mean())


def crossing(rows):
    """The retraction where U / U_exact crosses 1, interpolated linearly between the first
    bracketing pair of runs (in retraction order), or None."""
    rows = sorted(rows)
    for (r0, q0), (r1, q1) in zip(rows, rows[1:]):
        if (q0 - 1.0) * (q1 - 1.0) <= 0.0 and q1 != q0:
            return r0 + (1.0 - q0) * (r1 - r0) / (q1 - q0)
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dim", type=int, choices=(2, 3), default=3)
    parser.add_argument("--kernel", default="hat", choices=KERNELS, help="coupling.kernel")
    parser.add_argument("--cells-per-diameter", type=int, default=None,
                        help="d/h (default: 8 in 3D, 16 in 2D)")
    parser.add_argument("--box", type=float, default=3.0,
                        help="the periodic cell's side in diameters (default 3: φ = 0.019 in 3D)")
    parser.add_argument("--retractions", type=float, nargs="+", default=[0.1, 0.3, 0.5, 0.7],
                        help="coupling.marker_retraction values to run, in h (0 to 2)")
    parser.add_argument("--fddem",
                        default=os.path.join(HERE, "..", "build", "release", "app", "fddem"))
    parser.add_argument("--keep", default=None,
                        help="a new directory to keep the runs in (else they are removed, "
                             "unless a run fails)")
    parser.add_argument("--set", action="append", default=[], dest="extra",
                        help="passed on to every fddem run (e.g. coupling.markers=surface)")
    args = parser.parse_args()

    dim = args.dim
    n = args.cells_per_diameter if args.cells_per_diameter is not None else (8 if dim == 3 else 16)
    if n < 2:
        parser.error(f"--cells-per-diameter {n}: at least 2")
    if args.box <= 1.0:
        parser.error(f"--box {args.box}: the cell must be wider than the body (above 1)")
    bad = [r for r in args.retractions if not 0.0 <= r <= 2.0]
    if bad:
        parser.error(f"--retractions {bad}: coupling.marker_retraction lies in [0, 2]")
    if not os.access(args.fddem, os.X_OK):
        parser.error(f"--fddem {args.fddem}: no executable there (build fddem first)")
    if args.keep and os.path.exists(args.keep):
        parser.error(f"--keep {args.keep}: exists; give a new directory")
    case = os.path.join(HERE, "..", CASES[dim])
    cells = int(round(args.box * n))
    box = cells / n  # the box holds whole cells
    centre = [0.5 * box] * dim
    if args.keep:
        os.makedirs(args.keep)
    work = args.keep or tempfile.mkdtemp(prefix="stokes_retraction_")
    env = dict(os.environ)
    env.setdefault("OMP_NUM_THREADS", "1")

    print(f"{dim}D array, kernel {args.kernel}, d/h {n}, cell {box:g} d ({cells} cells a side)")
    print("| retraction [h] | U / U_exact | drag error | outer iterations | wall s |")
    print("| ---: | ---: | ---: | ---: | ---: |")
    rows = []
    for r in args.retractions:
        run_dir = os.path.join(work, f"r{r:g}")
        command = [args.fddem, "run", case, "-o", run_dir, "--quiet",
                   "--set", f"domain.size={[box] * dim}",
                   "--set", f"domain.cells={[cells] * dim}",
                   "--set", f"bodies.1.position={centre}",
                   "--set", f'coupling.kernel="{args.kernel}"',
                   "--set", f"coupling.marker_retraction={r}"]
        for extra in args.extra:
            command += ["--set", extra]
        done = subprocess.run(command, capture_output=True, text=True, env=env)
        if done.returncode != 0:
            print(f"error: fddem failed at retraction {r} (runs in {work}):\n"
                  f"{done.stderr.strip()}", file=sys.stderr)
            sys.exit(done.returncode)
        exact, phi = exact_for_run(run_dir, dim)
        q = mean_velocity(run_dir) / exact
        summary = io.read_summary(run_dir)
        seconds = summary.get("wall_seconds_stepping")
        rows.append((r, q))
        print(f"| {r:g} | {q:.4f} | {1.0 / q - 1.0:+.2%} | "
              f"{summary.get('total_outer_iterations')} | "
              f"{'–' if seconds is None else round(seconds, 1)} |", flush=True)
    print(f"φ = {phi:.4f}, U_exact = {exact:.6g} (Sangani & Acrivos 1982)")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    root = crossing(rows)
    if root is None:
        print("U / U_exact does not cross 1 between these retractions: widen --retractions")
        sys.exit(1)
    print(f"the exact Stokes drag at retraction {root:.3f} h (linear between the bracketing runs)")


if __name__ == "__main__":
    main()
