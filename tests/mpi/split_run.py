#!/usr/bin/env python3
"""`mpirun -n N fddem run CASE` against `fddem run CASE` on one process (issue 15).

    split_run.py FDDEM MPIEXEC N WORK_DIR

For a 2D cavity, a 3D channel (the fluid alone) and four colliding disks across the rank faces
(tests/mpi/cases), the run on N processes must write what the one-process run writes:
particles.csv to 1e-10 of each column's largest value, solver.csv step by step (the same steps, step sizes and outer
iterations; the residuals, which sit near the tolerance, to 1e-8 relative), the line samples to
1e-10 of their largest value, the same field and particle frames (on N > 1 processes written in
pieces, one per rank, whose extents tile the grid: assembled by the fddem Python readers, each
array to 1e-10 of its largest value), with no frame files left over that the .pvd collections do
not list (a restart removes the later frames and their pieces); and checkpoints that continue on another
number of processes (one process's on N, N processes' on one, and for N > 2 two processes' on N)
as the one-process run continues.
Then the bad input of a split run: a body of negative diameter, a run into a directory that is not
empty (which rank 0 alone checks), a restart of a directory that does not exist and one from a
damaged checkpoint, each end with exit status 2 and one message, without MPI_Abort; and a
damaged piece of the newest checkpoint is named, set aside, and the run continues from the one before. The pressure is solved by FFT transforms in both: FFTW's serial ones on one
process, FFTW-MPI's slabs on N (hypre's split solve is checked by many_ranks.py and the unit tests). Exit status 0 if all holds, 1 with the first difference otherwise.
"""

import csv
import pathlib
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
from fddem import io as frames_io  # noqa: E402

COMMON = ["--set", "simple.pressure_solver=fft"]

CASES = pathlib.Path(__file__).resolve().parent / "cases"
CAVITY = (CASES / "cavity.toml").read_text()
CHANNEL = (CASES / "channel.toml").read_text()

DISKS = (CASES / "disks.toml").read_text()
# The same disks swept together: each body's eqs. (13)-(15) evaluated by its owner alone, whose
# marker arrays a checkpoint must gather (coupling/marker_routes.hpp). Its checkpoint is taken at
# t = 0.01 s, while disk 2 is still above the rank face y = 1.5 on 2 ranks: by t = 0.06 s every
# disk has fallen below it, rank 0 owns them all and holds their arrays anyway, and a checkpoint
# without the gathering of the marker arrays continued as well (measured: 6.6e-13); at 0.01 s
# it differs by 3.9 of contact_fy's largest value.
DISKS_SWEPT = DISKS.replace('markers = "paper"', 'markers = "paper"\nbody_sweep = "simultaneous"')
DISKS_SWEPT = DISKS_SWEPT.replace("end = 0.06", "end = 0.01")
assert DISKS_SWEPT.count("simultaneous") == 1 and "end = 0.01" in DISKS_SWEPT

BAD_DISK = CAVITY + """
[[bodies]]
shape = "disk"
diameter = -0.2
density = 2.0
position = [0.5, 0.5]
"""


def table(path):
    rows = list(csv.reader(open(path)))
    return rows[0], np.array([[float(x) for x in row] for row in rows[1:]])


def run(command, expect):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != expect:
        sys.exit(f"{' '.join(command)}: exit {result.returncode} (expected {expect})\n"
                 f"{result.stderr}")
    return result


def compare(one, split, name, n_ranks, solver_tolerance=1e-12):
    head, a = table(one / "solver.csv")
    head_split, b = table(split / "solver.csv")
    if head != head_split or a.shape != b.shape:
        sys.exit(f"{name}: solver.csv has {a.shape} rows/columns, the split run {b.shape}")
    for k, column in enumerate(head):
        tolerance = {"wall_seconds": None, "mass_residual": 1e-8,
                     "momentum_residual": 1e-8}.get(column, solver_tolerance)
        if tolerance is None:
            continue
        scale = max(np.abs(a[:, k]).max(), 1e-300)
        worst = np.abs(a[:, k] - b[:, k]).max() / scale
        if worst > tolerance:
            sys.exit(f"{name}: solver.csv column {column} differs by {worst:.2e} (relative)")
    for sample in sorted((one / "samples").glob("*.csv")):
        head, a = table(sample)
        _, b = table(split / "samples" / sample.name)
        # A column of round-off alone (w on the cube's mid-plane, 1e-14) against 1e-6 of the
        # table's largest value, as for particles.csv below.
        floor = max(1e-6 * np.abs(a).max(), 1e-300)
        worst = max(np.abs(a[:, k] - b[:, k]).max() / max(np.abs(a[:, k]).max(), floor)
                    for k in range(a.shape[1]))
        print(f"{name}: samples/{sample.name}: largest relative difference {worst:.2e}")
        if worst > 1e-10:
            sys.exit(f"{name}: samples/{sample.name} differs by {worst:.2e} (relative)")
    if (one / "particles.csv").exists():
        head, a = table(one / "particles.csv")
        head_split, b = table(split / "particles.csv")
        if head != head_split or a.shape != b.shape:
            sys.exit(f"{name}: particles.csv has {a.shape} rows/columns, the split run {b.shape}")
        # Each column against its largest value; a column of round-off alone (the contact
        # torque of disks touching head-on, 1e-17) against 1e-6 of the table's largest value.
        floor = 1e-6 * np.abs(a).max()
        worst, column = max((np.abs(a[:, k] - b[:, k]).max() / max(np.abs(a[:, k]).max(), floor),
                             head[k]) for k in range(a.shape[1]))
        print(f"{name}: particles.csv ({a.shape[0]} rows): largest relative difference "
              f"{worst:.2e} ({column})")
        if worst > 1e-10:
            sys.exit(f"{name}: particles.csv column {column} differs by {worst:.2e} (relative)")
    compare_frames(one, split, name, n_ranks, "fields.pvd", frames_io.read_vtr)
    if (one / "particles.pvd").exists():
        compare_frames(one, split, name, n_ranks, "particles.pvd", frames_io.read_vtp)


def listed_files(run, collection):
    """The files a .pvd lists, and for a master file (.pvtr, .pvtp) its pieces: relative paths."""
    files = set()
    for _, path in frames_io.read_pvd(run, collection):
        files.add(str(pathlib.Path(path).relative_to(run)))
        if path.endswith((".pvtr", ".pvtp")):
            text = pathlib.Path(path).read_text()
            folder = pathlib.Path(path).parent.relative_to(run)
            for source in re.findall(r'Source="([^"]+)"', text):
                files.add(str(folder / source))
    return files


def check_pieces(path, n_pieces):
    """A master file lists `n_pieces` pieces; a .pvtr's extents tile its whole extent (every cell
    of the grid in exactly one piece, neighbours sharing their node planes)."""
    root = ElementTree.parse(path).getroot()
    pieces = list(root.iter("Piece"))
    allowed = (n_pieces,) if isinstance(n_pieces, int) else tuple(n_pieces)
    if len(pieces) not in allowed:
        sys.exit(f"{path}: {len(pieces)} pieces on {n_pieces} processes")
    if not path.endswith(".pvtr"):
        return
    whole = [int(v) for v in root.find("PRectilinearGrid").get("WholeExtent").split()]
    cells = [max(whole[2 * d + 1] - whole[2 * d], 1) for d in range(3)]
    covered = np.zeros(cells[::-1], dtype=int)
    for piece in pieces:
        e = [int(v) for v in piece.get("Extent").split()]
        if any(e[2 * d] < whole[2 * d] or e[2 * d + 1] > whole[2 * d + 1] or
               e[2 * d] > e[2 * d + 1] for d in range(3)):
            sys.exit(f"{path}: a piece's extent {e} is not inside the whole extent {whole}")
        covered[tuple(slice(e[2 * d] - whole[2 * d], max(e[2 * d + 1], e[2 * d] + 1) -
                            whole[2 * d]) for d in (2, 1, 0))] += 1
    if np.any(covered != 1):
        sys.exit(f"{path}: the pieces' extents do not tile the whole extent {whole}")


def compare_frames(one, split, name, n_ranks, collection, read):
    """The frames `collection` lists in `split` (in `n_ranks` pieces where written on several
    processes) against the one-process run's, array by array; no frame file left that it does not list."""
    a_frames = frames_io.read_pvd(one, collection)
    b_frames = frames_io.read_pvd(split, collection)
    if [t for t, _ in a_frames] != [t for t, _ in b_frames] or len(a_frames) < 2:
        sys.exit(f"{name}: {collection} lists frames at {[t for t, _ in b_frames]}, "
                 f"the one-process run at {[t for t, _ in a_frames]}")
    folder = "fields" if collection == "fields.pvd" else "particles"
    on_disk = {str(p.relative_to(split)) for p in (split / folder).rglob("*") if p.is_file()}
    if on_disk != listed_files(split, collection):
        sys.exit(f"{name}: {folder}/ holds {sorted(on_disk - listed_files(split, collection))} "
                 f"that {collection} does not list, and lacks "
                 f"{sorted(listed_files(split, collection) - on_disk)}")
    worst, where = 0.0, ""
    for (_, a_path), (_, b_path) in zip(a_frames, b_frames):
        if b_path.endswith((".pvtr", ".pvtp")):
            check_pieces(b_path, int(n_ranks) if isinstance(n_ranks, str) else n_ranks)
        a, b = read(a_path), read(b_path)
        if sorted(a) != sorted(b):
            sys.exit(f"{name}: {b_path} holds {sorted(b)}, {a_path} {sorted(a)}")
        if "id" in a:  # bodies: in id order in both
            order = np.argsort(a["id"], kind="stable")
            a = {key: values[order] for key, values in a.items()}
        # Each array against its largest value; an array of round-off alone (the contact torque
        # of disks touching head-on) against 1e-6 of the frame's largest value.
        floor = 1e-6 * max(np.abs(values).max() for values in a.values())
        for key in a:
            if a[key].shape != b[key].shape:
                sys.exit(f"{name}: {b_path}: {key} is {b[key].shape}, one process {a[key].shape}")
            difference = np.abs(a[key] - b[key]).max() / max(np.abs(a[key]).max(), floor)
            if difference > worst:
                worst, where = difference, f"{pathlib.Path(b_path).name} {key}"
    print(f"{name}: {collection} ({len(a_frames)} frames): largest relative difference "
          f"{worst:.2e} ({where})")
    if worst > 1e-10:
        sys.exit(f"{name}: {where} differs by {worst:.2e} (relative)")


def main():
    fddem, mpiexec, n, work = sys.argv[1], sys.argv[2], sys.argv[3], pathlib.Path(sys.argv[4])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    split = [mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", n, fddem]
    for name, text, end in (("cavity", CAVITY, "0.5"), ("channel", CHANNEL, "0.4"),
                            ("disks", DISKS, "0.08"), ("disks_swept", DISKS_SWEPT, "0.08")):
        case = work / f"{name}.toml"
        case.write_text(text)
        one, many = work / f"{name}_one", work / f"{name}_split"
        run([fddem, "run", str(case), "-o", str(one), "--quiet"] + COMMON, 0)
        run(split + ["run", str(case), "-o", str(many), "--quiet"] + COMMON, 0)
        compare(one, many, f"{name} on {n} processes", n)
        # Checkpoints across process counts: the one-process run continued on N processes and
        # the N-process run continued on one must both continue as the one-process run does.
        crossed = work / f"{name}_one_then_split"
        shutil.copytree(one, crossed)
        extend = ["--quiet", "--set", f"time.end={end}"]
        run([fddem, "run", "--restart", str(one)] + extend, 0)
        run(split + ["run", "--restart", str(crossed)] + extend, 0)
        run([fddem, "run", "--restart", str(many)] + extend, 0)
        compare(one, crossed, f"{name}: one process, continued on {n}", n)
        compare(one, many, f"{name}: {n} processes, continued on one", n)
        if int(n) > 2:
            # A checkpoint written on 2 processes, continued on N (neither count is one): its
            # frames are in 2 pieces up to the restart and in N after it.
            two = work / f"{name}_two_then_split"
            run(split[:4] + ["2"] + split[5:] + ["run", str(case), "-o", str(two), "--quiet"]
                + COMMON, 0)
            run(split + ["run", "--restart", str(two)] + extend, 0)
            compare(one, two, f"{name}: 2 processes, continued on {n}", (2, int(n)))
    # Bad input on several processes: exit 2, said once, nothing written.
    if int(n) > 1:
        disk = work / "disk.toml"
        disk.write_text(BAD_DISK)
        result = run(split + ["run", str(disk), "-o", str(work / "disk_run")], 2)
        said = [line for line in result.stderr.splitlines() if line.startswith("fddem:")]
        if len(said) != 1 or "diameter" not in said[0] or (work / "disk_run").exists() or "MPI_ABORT" in result.stderr:
            sys.exit(f"a body of negative diameter on {n} processes: {result.stderr}")
        # Rank 0 alone checks the run directory; every rank must still end without MPI_Abort
        # (app/error_agreement.hpp: an abort could kill rank 0 before its message is forwarded).
        taken = work / "taken"
        (taken / "notes").mkdir(parents=True)
        result = run(split + ["run", str(work / "cavity.toml"), "-o", str(taken)], 2)
        said = [line for line in result.stderr.splitlines() if line.startswith("fddem:")]
        if (len(said) != 1 or "exists and is not empty" not in said[0]
                or "MPI_ABORT" in result.stderr or sorted(p.name for p in taken.iterdir()) != ["notes"]):
            sys.exit(f"a run into a directory that is not empty on {n} processes: {result.stderr}")
        result = run(split + ["run", "--restart", str(work / "nowhere")], 2)
        said = [line for line in result.stderr.splitlines() if line.startswith("fddem:")]
        if len(said) != 1 or "no such run directory" not in said[0] or "MPI_ABORT" in result.stderr:
            sys.exit(f"a restart of a missing directory on {n} processes: {result.stderr}")
        damaged = work / "damaged"
        (damaged / "checkpoints").mkdir(parents=True)
        (damaged / "case.toml").write_text(CAVITY)
        (damaged / "checkpoints" / "checkpoint_0000000010.ckpt").write_text("garbage\n")
        result = run(split + ["run", "--restart", str(damaged)], 2)
        said = [line for line in result.stderr.splitlines() if line.startswith("fddem:")]
        if len(said) != 1 or "no usable checkpoint" not in said[0] or "MPI_ABORT" in result.stderr:
            sys.exit(f"a restart from a damaged checkpoint on {n} processes: {result.stderr}")
        # A damaged piece of the newest checkpoint (written on N processes, io/checkpoint.hpp):
        # the restart names the piece and the reason, sets the checkpoint aside and continues
        # from the one before.
        pieces = work / "pieces"
        run(split + ["run", str(work / "cavity.toml"), "-o", str(pieces), "--quiet",
                     "--set", "checkpoint.step_interval=10", "--set", "checkpoint.keep=2"]
            + COMMON, 0)
        kept = sorted((pieces / "checkpoints").glob("checkpoint_*.ckpt"))
        piece = sorted((pieces / "checkpoints").glob(kept[-1].name + ".*.piece1"))
        if len(kept) != 2 or len(piece) != 1:
            sys.exit(f"checkpoints of a run on {n} processes: {sorted(p.name for p in kept)}, "
                     f"pieces {[p.name for p in piece]}")
        data = bytearray(piece[0].read_bytes())
        data[100] ^= 0x5A
        piece[0].write_bytes(bytes(data))
        result = run(split + ["run", "--restart", str(pieces), "--set", "time.end=0.6"]
                     + COMMON, 0)
        said = "\n".join(line for line in result.stderr.splitlines() if line.startswith("fddem:"))
        for expected in (piece[0].name, "is damaged (CRC-32", "set aside",
                         f"from step {int(kept[0].name[11:21])}"):
            if expected not in said:
                sys.exit(f"a restart past a damaged piece on {n} processes does not say "
                         f"'{expected}':\n{said}")
        aside = kept[-1].parent / (kept[-1].name + ".damaged" + piece[0].name[len(kept[-1].name):])
        if not aside.exists():
            sys.exit(f"the damaged checkpoint's piece was not set aside with it as {aside.name}")
    print(f"split runs on {n} processes match the one-process runs")


if __name__ == "__main__":
    main()
