#!/usr/bin/env python3
"""The lid-driven cube on many processes against one (issue 15: 64 ranks, oversubscribed).

    many_ranks.py FDDEM MPIEXEC N WORK_DIR [CELLS_PER_RANK_AXIS]

docs/examples/cavity3d.toml with N = 2^(3k) processes laid out k·k·k ... (4 × 4 × 4 for 64),
each block CELLS_PER_RANK_AXIS (default 6) cells a side, for 4 steps, hypre to 1e-13. The run
on N processes must write what the one-process run writes (split_run.compare: solver.csv step
by step, the case's line sample and every field frame, assembled from its N pieces, to 1e-10).
Then it prints rank 0's halo messages, their bytes and its collectives per step
(summary.json; rank 0 is a corner block, with 3 neighbours). Exit status 0 if all holds, 1
otherwise.
"""

import json
import pathlib
import shutil
import sys

import split_run

CUBE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "cavity3d.toml"


def layout(n):
    side = round(n ** (1.0 / 3.0))
    if side ** 3 != n:
        sys.exit(f"many_ranks.py: {n} is not a cube number of processes")
    return side


def main():
    fddem, mpiexec, n, work = sys.argv[1], sys.argv[2], sys.argv[3], pathlib.Path(sys.argv[4])
    per_axis = int(sys.argv[5]) if len(sys.argv) > 5 else 6
    side = layout(int(n))
    cells = side * per_axis
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    settings = split_run.COMMON + [
        "--set", f"domain.cells=[{cells},{cells},{cells}]", "--set", "time.max_steps=4",
        "--set", "time.dt=0.02", "--set", "output.field_interval=0.04",
        "--set", f"parallel.ranks=[{side},{side},{side}]", "--quiet"]
    one, many = work / "one", work / "split"
    split_run.run([fddem, "run", str(CUBE), "-o", str(one)] + settings, 0)
    split_run.run([mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", n, fddem, "run",
                   str(CUBE), "-o", str(many)] + settings, 0)
    split_run.compare(one, many, f"the cube ({cells}³) on {n} processes", n)
    summary = json.loads((many / "summary.json").read_text())
    steps = summary["steps"]
    outer = summary["total_outer_iterations"]
    print(f"rank 0 of {n} ({side}×{side}×{side}, {per_axis}³ cells each), per step: "
          f"{summary['mpi_rank0_messages'] / steps:.0f} halo messages "
          f"({summary['mpi_rank0_message_bytes'] / steps / 1024:.0f} KiB), "
          f"{summary['mpi_rank0_collectives'] / steps:.0f} collectives; "
          f"{outer / steps:.1f} outer iterations per step")


if __name__ == "__main__":
    main()
