#!/usr/bin/python3
"""The potential-flow added mass of a circular cylinder in a closed rectangular box.

    python3 tools/added_mass.py --box 2 4 --centre 1 2 --radius 0.25 [--axis y]
    python3 tools/added_mass.py --check        (against Lamb's concentric-cylinder formula)

A body started from rest, or suddenly accelerated, first sets the fluid in potential motion:
over a step much shorter than R²/ν the impulse it takes is (ρs V + m_a) ΔU, whatever the
viscosity. m_a = C_m ρf V is the reference for fddem's early acceleration of a light or heavy
disk and for the impulse of a disk started impulsively (issue 13, docs/method.md §4, "The
inertia of the marker layouts"). In an unbounded fluid C_m = 1 for a circular cylinder; a box
raises it.

Method: the method of fundamental solutions (Kupradze & Aleksidze 1964; Fairweather & Karageorghis
1998, Adv. Comput. Math. 9). The velocity potential φ (for the body moving at unit speed along
`axis`) is a sum of 2D sources, (q_j / 2π) ln|x − y_j|, placed outside the fluid: inside the
disk and on a contour outside the box. Their strengths make ∂φ/∂n = n·e_axis on the disk and
∂φ/∂n = 0 on the walls at collocation points, in the least-squares sense, with Σ q_j = 0 (no net
source in a closed box). Then

    m_a = −ρf ∮_disk φ (n·e_axis) ds,    n the disk's outward normal,

which is twice the fluid's kinetic energy. The answer is printed with its change when every
number of points is doubled (the discretisation error). Written here rather than taken from a
library: no Debian package solves a 2D Neumann potential problem in a multiply connected domain
without a mesh generator, and the method is a page of numpy.
"""

import argparse
import math
import sys

import numpy as np


def disk_points(centre, radius, n):
    theta = 2 * math.pi * (np.arange(n) + 0.5) / n
    normal = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    return centre + radius * normal, normal


def box_points(size, n_per_unit):
    """Collocation points on the walls of [0, W] × [0, L], with the fluid's outward normals and
    the length each point stands for (for the check of the no-flux condition)."""
    points, normals = [], []
    w, length = size
    for (start, direction, normal, extent) in (
            ((0.0, 0.0), (1.0, 0.0), (0.0, -1.0), w),
            ((w, 0.0), (0.0, 1.0), (1.0, 0.0), length),
            ((w, length), (-1.0, 0.0), (0.0, 1.0), w),
            ((0.0, length), (0.0, -1.0), (-1.0, 0.0), length)):
        n = max(8, int(round(n_per_unit * extent)))
        s = (np.arange(n) + 0.5) / n * extent
        points.append(np.array(start) + np.outer(s, direction))
        normals.append(np.tile(normal, (n, 1)))
    return np.concatenate(points), np.concatenate(normals)


def outer_sources(size, offset, n_per_unit):
    """Sources on a rectangle grown by `offset`, with its corners cut: outside every wall."""
    w, length = size
    grown = (w + 2 * offset, length + 2 * offset)
    points, _ = box_points(grown, n_per_unit)
    return points - offset


def solve(size, centre, radius, axis, resolution):
    """m_a / (ρf π R²) for the disk in the box; `resolution` scales every number of points."""
    centre = np.asarray(centre, dtype=float)
    n_disk = int(16 * resolution)
    per_unit = 32 * resolution / (size[0] + size[1])  # 64 · resolution sources around the box
    collocation_disk, normal_disk = disk_points(centre, radius, 2 * n_disk)
    sources_disk, _ = disk_points(centre, 0.5 * radius, n_disk)
    collocation_box, normal_box = box_points(size, 2 * per_unit)
    sources_box = outer_sources(size, 0.25 * min(size), per_unit)
    sources = np.concatenate([sources_disk, sources_box])
    collocation = np.concatenate([collocation_disk, collocation_box])
    normals = np.concatenate([normal_disk, normal_box])
    # ∂/∂n of (1/2π) ln|x − y| = (1/2π) n·(x − y)/|x − y|².
    d = collocation[:, None, :] - sources[None, :, :]
    r2 = np.sum(d * d, axis=2)
    a = np.sum(normals[:, None, :] * d, axis=2) / r2 / (2 * math.pi)
    rhs = np.concatenate([normal_disk[:, axis], np.zeros(len(collocation_box))])
    a = np.vstack([a, np.ones(len(sources))])  # Σ q = 0
    rhs = np.append(rhs, 0.0)
    q, *_ = np.linalg.lstsq(a, rhs, rcond=None)
    residual = np.max(np.abs(a @ q - rhs))
    # φ on the disk, and m_a = −ρ ∮ φ n_axis ds (ρ = 1), by the midpoint rule on its points.
    d = collocation_disk[:, None, :] - sources[None, :, :]
    phi = np.log(np.sqrt(np.sum(d * d, axis=2))) @ q / (2 * math.pi)
    ds = 2 * math.pi * radius / len(collocation_disk)
    added = -np.sum(phi * normal_disk[:, axis]) * ds
    return added / (math.pi * radius * radius), residual


def concentric(b, radius, resolution):
    """The same method for a disk in a circular container of radius b (Lamb's case)."""
    n_disk = int(32 * resolution)
    n_outer = int(64 * resolution)
    centre = np.zeros(2)
    collocation_disk, normal_disk = disk_points(centre, radius, 2 * n_disk)
    sources_disk, _ = disk_points(centre, 0.5 * radius, n_disk)
    collocation_outer, outward = disk_points(centre, b, 2 * n_outer)
    sources_outer, _ = disk_points(centre, 1.3 * b, n_outer)
    sources = np.concatenate([sources_disk, sources_outer])
    collocation = np.concatenate([collocation_disk, collocation_outer])
    normals = np.concatenate([normal_disk, outward])
    d = collocation[:, None, :] - sources[None, :, :]
    a = np.sum(normals[:, None, :] * d, axis=2) / np.sum(d * d, axis=2) / (2 * math.pi)
    rhs = np.concatenate([normal_disk[:, 1], np.zeros(len(collocation_outer))])
    a = np.vstack([a, np.ones(len(sources))])
    rhs = np.append(rhs, 0.0)
    q, *_ = np.linalg.lstsq(a, rhs, rcond=None)
    d = collocation_disk[:, None, :] - sources[None, :, :]
    phi = np.log(np.sqrt(np.sum(d * d, axis=2))) @ q / (2 * math.pi)
    ds = 2 * math.pi * radius / len(collocation_disk)
    return -np.sum(phi * normal_disk[:, 1]) * ds / (math.pi * radius * radius)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--box", nargs=2, type=float, metavar=("W", "L"))
    parser.add_argument("--centre", nargs=2, type=float, metavar=("X", "Y"))
    parser.add_argument("--radius", type=float)
    parser.add_argument("--axis", choices=["x", "y"], default="y")
    parser.add_argument("--check", action="store_true",
                        help="compare with Lamb's C_m = (b² + R²)/(b² − R²) and exit")
    options = parser.parse_args()
    if options.check:
        worst = 0.0
        for ratio in (2.0, 4.0, 16.0):
            exact = (ratio ** 2 + 1) / (ratio ** 2 - 1)
            got = concentric(ratio, 1.0, 2)
            worst = max(worst, abs(got - exact))
            print(f"b/R = {ratio:>4}: C_m {got:.6f}, Lamb {exact:.6f}")
        return 0 if worst < 1e-4 else 1
    if options.box is None or options.centre is None or options.radius is None:
        parser.error("give --box, --centre and --radius, or --check")
    cx, cy = options.centre
    w, length = options.box
    if not (options.radius < cx < w - options.radius and options.radius < cy < length - options.radius):
        print(f"added_mass.py: the disk (centre {options.centre}, radius {options.radius}) is not "
              f"inside the box {options.box}", file=sys.stderr)
        return 2
    axis = 0 if options.axis == "x" else 1
    coarse, _ = solve(options.box, options.centre, options.radius, axis, 2)
    fine, residual = solve(options.box, options.centre, options.radius, axis, 4)
    print(f"C_m = m_a / (rho_f pi R^2) = {fine:.5f} (with half the points {coarse:.5f}; largest "
          f"boundary-condition residual {residual:.1e})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
