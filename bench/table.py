#!/usr/bin/python3
"""Prints fddem's benchmark tables from run directories (see bench/run.sh)."""
import argparse
import csv
import json
import os
import sys


def read_solver_csv(run_dir):
    with open(os.path.join(run_dir, "solver.csv"), newline="") as f:
        return list(csv.DictReader(f))


def read_summary(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def cavity_table(entries):
    print(
        f"{'grid':>6} {'steps':>6} {'ms/step':>8} {'ns/cell/step':>13} {'outer/step':>10} "
        f"{'pressure %':>10} {'momentum %':>10} {'peak MiB':>9}"
    )
    for entry in entries:
        n, run_dir = entry.split(":", 1)
        n = int(n)
        rows = read_solver_csv(run_dir)
        summary = read_summary(run_dir)
        steps = len(rows)
        phases = summary["wall_seconds_by_phase"]
        stepping = summary["wall_seconds_stepping"]
        outer = sum(int(r["outer_iterations"]) for r in rows)
        print(
            f"{n:>5}² {steps:>6} {1e3 * stepping / steps:>8.3f} "
            f"{1e9 * stepping / steps / n / n:>13.1f} {outer / steps:>10.2f} "
            f"{100 * phases.get('pressure', 0) / stepping:>10.1f} "
            f"{100 * phases.get('momentum', 0) / stepping:>10.1f} "
            f"{summary['peak_memory_mib']:>9.1f}"
        )


def read_xy(path, skip_header=True):
    rows = []
    with open(path) as f:
        lines = f.read().strip().splitlines()
    for line in lines[1 if skip_header else 0 :]:
        parts = line.split(",")
        rows.append([float(p) for p in parts])
    return rows


def interpolate(xs, ys, x):
    for k in range(1, len(xs)):
        if xs[k] >= x - 1e-14:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] != xs[k - 1] else 0.0
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]


def max_deviation(xs, ys, reference):
    return max(abs(interpolate(xs, ys, rx) - ry) for rx, ry in reference)


def openfoam_table(fddem_dir, fddem_wall, peer_results, n, reference_dir):
    ghia_u = read_xy(os.path.join(reference_dir, "ghia1982_u_vertical_centerline.csv"))
    ghia_v = read_xy(os.path.join(reference_dir, "ghia1982_v_horizontal_centerline.csv"))
    with open(os.path.join(fddem_dir, "samples", "vertical_centerline.csv"), newline="") as f:
        vertical = list(csv.DictReader(f))
    with open(os.path.join(fddem_dir, "samples", "horizontal_centerline.csv"), newline="") as f:
        horizontal = list(csv.DictReader(f))
    fddem_u = max_deviation(
        [float(r["y"]) for r in vertical], [float(r["u"]) for r in vertical], ghia_u
    )
    fddem_v = max_deviation(
        [float(r["x"]) for r in horizontal], [float(r["v"]) for r in horizontal], ghia_v
    )
    name = f"icoFoam_N{n}_Re100_T20"
    of_u_rows = read_xy(os.path.join(peer_results, f"{name}_u.csv"))
    of_v_rows = read_xy(os.path.join(peer_results, f"{name}_v.csv"))
    of_u = max_deviation([r[0] for r in of_u_rows], [r[1] for r in of_u_rows], ghia_u)
    of_v = max_deviation([r[0] for r in of_v_rows], [r[1] for r in of_v_rows], ghia_v)
    of_wall = None
    with open(os.path.join(peer_results, "runs.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["name"] == name:
                of_wall = float(row["wall_s"])
    steps = len(read_solver_csv(fddem_dir))
    print(f"{'code':>8} {'wall s':>8} {'steps':>6} {'max|u-Ghia|':>12} {'max|v-Ghia|':>12}")
    print(f"{'fddem':>8} {float(fddem_wall):>8.1f} {steps:>6} {fddem_u:>12.5f} {fddem_v:>12.5f}")
    print(f"{'icoFoam':>8} {of_wall:>8.1f} {'':>6} {of_u:>12.5f} {of_v:>12.5f}")
    print(f"wall-time ratio icoFoam / fddem: {of_wall / float(fddem_wall):.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mode", choices=["cavity", "openfoam"])
    parser.add_argument("args", nargs="+")
    options = parser.parse_args()
    if options.mode == "cavity":
        cavity_table(options.args)
    else:
        openfoam_table(*options.args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
