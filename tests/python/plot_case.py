#!/usr/bin/python3
"""`fddem plot` on a small run of a case in cases/ (run by CTest, one test per case):

    plot_case.py FDDEM CASE.toml WORK_DIR

runs the case on a coarse grid (h = the smaller of a sixteenth of the box's shortest side and a
quarter of the smallest body's diameter) for three steps with a field frame at each, plots it,
and checks that the figures the case's kind calls for exist and are not blank (pixel variance),
that the run directory has its ParaView script, and that a directory that is not a run ends
with exit status 2 and one line.
"""

import csv
import math
import os
import shutil
import subprocess
import sys
import tomllib

import numpy as np

MIN_PIXEL_VARIANCE = 1e-3
STEPS = 3


def body_diameters(case, case_file):
    """Every body's diameter: an entry's own, or each row's of its bodies.file (a CSV)."""
    for body in case.get("bodies", []):
        if "file" in body:
            path = os.path.join(os.path.dirname(case_file), body["file"])
            with open(path, newline="") as f:
                lines = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
            yield from (float(row["diameter"]) for row in csv.DictReader(lines, skipinitialspace=True))
        else:
            yield body["diameter"]


def coarse_overrides(case, case_file):
    size = case["domain"]["size"]
    h = min(size) / 16
    for diameter in body_diameters(case, case_file):
        h = min(h, diameter / 4)
    cells = [max(4, math.ceil(s / h)) for s in size]
    dt = case["time"]["dt"]
    return [f"domain.cells=[{','.join(map(str, cells))}]", f"time.max_steps={STEPS}",
            f"output.field_interval={dt}", "output.particle_interval=0"]


def expected_figures(case):
    names = ["overview", "solver"]
    bodies = case.get("bodies", [])
    if not case.get("time", {}).get("steady", False):
        names.append("snapshots")
    if any(b.get("motion", "free") != "fixed" for b in bodies):
        names += ["positions", "velocities", "energy", "trajectories"]
    if bodies:
        names.append("forces")
    if "reynolds" in case.get("nondimensional", {}):
        names.append("settling")
    return names


def pixel_variance(path):
    import matplotlib.image

    return float(np.var(matplotlib.image.imread(path)[..., :3]))


def main():
    fddem, case_file, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(case_file, "rb") as f:
        case = tomllib.load(f)
    run_dir = os.path.join(work, "run")
    command = [fddem, "run", case_file, "-o", run_dir, "-q"]
    for override in coarse_overrides(case, case_file):
        command += ["--set", override]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"fddem run failed ({result.returncode}): {' '.join(command)}\n{result.stderr}")
    out = os.path.join(work, "plots")
    result = subprocess.run([fddem, "plot", run_dir, "-o", out], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"fddem plot failed ({result.returncode}):\n{result.stderr}")
    failures = []
    for name in expected_figures(case):
        path = os.path.join(out, name + ".png")
        if not os.path.exists(path):
            failures.append(f"{name}.png missing")
        elif pixel_variance(path) <= MIN_PIXEL_VARIANCE:
            failures.append(f"{name}.png is blank (pixel variance {pixel_variance(path):.2g})")
    for path in (p for p in result.stdout.split() if p.endswith(".png")):
        if pixel_variance(path) <= MIN_PIXEL_VARIANCE:
            failures.append(f"{path} is blank")
    if not os.path.exists(os.path.join(run_dir, "open_in_paraview.py")):
        failures.append("no open_in_paraview.py in the run directory")
    result = subprocess.run([fddem, "plot", work], capture_output=True, text=True)
    if result.returncode != 2 or len(result.stderr.strip().splitlines()) != 1:
        failures.append(f"not a run: exit {result.returncode}, stderr {result.stderr!r}")
    if failures:
        sys.exit("\n".join(failures))
    print(f"{case_file}: {len(result.stdout.split())} figures checked in {out}")
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
