#!/usr/bin/python3
"""Prints fddem's benchmark tables from run directories (see bench/run.sh)."""
import argparse
import csv
import json
import math
import os
import statistics
import sys
import tomllib


def read_solver_csv(run_dir):
    with open(os.path.join(run_dir, "solver.csv"), newline="") as f:
        return list(csv.DictReader(f))


def read_summary(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def run_costs(run_dir):
    """(steps, seconds stepping, seconds by phase, outer iterations, summary) of one run."""
    rows = read_solver_csv(run_dir)
    summary = read_summary(run_dir)
    outer = sum(int(r["outer_iterations"]) for r in rows)
    return len(rows), summary["wall_seconds_stepping"], summary["wall_seconds_by_phase"], outer, summary


def cavity_table(entries):
    print(
        f"{'grid':>6} {'steps':>6} {'ms/step':>8} {'ns/cell/step':>13} {'outer/step':>10} "
        f"{'pressure %':>10} {'momentum %':>10} {'peak MiB':>9}"
    )
    for entry in entries:
        n, run_dir = entry.split(":", 1)
        n = int(n)
        steps, stepping, phases, outer, summary = run_costs(run_dir)
        print(
            f"{n:>5}² {steps:>6} {1e3 * stepping / steps:>8.3f} "
            f"{1e9 * stepping / steps / n / n:>13.1f} {outer / steps:>10.2f} "
            f"{100 * phases.get('pressure', 0) / stepping:>10.1f} "
            f"{100 * phases.get('momentum', 0) / stepping:>10.1f} "
            f"{summary['peak_memory_mib']:>9.1f}"
        )


def paper_table(entries):
    """End-to-end timing of particle cases: wall time, per step, outer iterations, phase shares."""
    print(
        f"{'case':<24} {'steps':>6} {'wall s':>8} {'ms/step':>8} {'outer/step':>10} "
        f"{'fluid %':>8} {'coupling %':>10} {'contact %':>9} {'max overlap/r':>13}"
    )
    for entry in entries:
        name, run_dir = entry.split(":", 1)
        steps, stepping, phases, outer, summary = run_costs(run_dir)
        fluid = phases.get("momentum", 0) + phases.get("pressure", 0)
        print(
            f"{name:<24} {steps:>6} {stepping:>8.2f} {1e3 * stepping / steps:>8.2f} "
            f"{outer / steps:>10.2f} {100 * fluid / stepping:>8.1f} "
            f"{100 * phases.get('coupling', 0) / stepping:>10.1f} "
            f"{100 * phases.get('contact', 0) / stepping:>9.1f} "
            f"{100 * summary.get('max_relative_overlap', 0):>12.2f}%"
        )


def three_d_table(entries):
    """3D sphere cases: cost per step and per cell and outer iteration, phase shares, memory."""
    print(
        f"{'case':<14} {'cells':>11} {'steps':>6} {'s/step':>7} {'outer/step':>10} "
        f"{'ns/cell/outer':>13} {'momentum %':>10} {'pressure %':>10} {'coupling %':>10} "
        f"{'contact %':>9} {'peak MiB':>9} {'B/cell':>7}"
    )
    for entry in entries:
        name, run_dir = entry.split(":", 1)
        steps, stepping, phases, outer, summary = run_costs(run_dir)
        cells = summary["cells"]
        print(
            f"{name:<14} {cells:>9} {steps:>6} {stepping / steps:>7.3f} {outer / steps:>10.2f} "
            f"{1e9 * stepping / outer / cells:>13.1f} "
            f"{100 * phases.get('momentum', 0) / stepping:>10.1f} "
            f"{100 * phases.get('pressure', 0) / stepping:>10.1f} "
            f"{100 * phases.get('coupling', 0) / stepping:>10.1f} "
            f"{100 * phases.get('contact', 0) / stepping:>9.1f} "
            f"{summary['peak_memory_mib']:>9.1f} {summary['peak_memory_mib'] * 2**20 / cells:>7.0f}"
        )


def read_icofoam_u(case_dir, n):
    """u along the cube's vertical centre line x = z = 0.5 from icoFoam's ascii U at the last time
    written: the mean of the four cells around the line, at the cell centres y = (j + 1/2)/n."""
    times = [d for d in os.listdir(case_dir) if d != "0" and d.replace(".", "", 1).isdigit()]
    with open(os.path.join(case_dir, max(times, key=float), "U")) as f:
        text = f.read()
    body = text[text.index("internalField"):]
    count_at = body.index("List<vector>") + len("List<vector>")
    opening = body.index("(", count_at)
    count = int(body[count_at:opening])
    values = body[opening + 1:].split(")", count)[:count]
    u = [float(v.replace("(", " ").split()[0]) for v in values]
    a, b = n // 2 - 1, n // 2
    at = lambda i, j, k: u[i + n * j + n * n * k]
    return [0.25 * (at(a, j, a) + at(b, j, a) + at(a, j, b) + at(b, j, b)) for j in range(n)]


def read_fddem_u(run_dir, n):
    """u along the same line from fddem's line sample (257 points), at the cell centres."""
    with open(os.path.join(run_dir, "samples", "vertical_centerline.csv"), newline="") as f:
        u = [float(r["u"]) for r in csv.DictReader(f)]
    m = (len(u) - 1) // n
    return [u[m * j + m // 2] for j in range(n)]


def cube3d_table(cube_dir):
    """The 3D cube side by side with icoFoam (bench/run.sh --cube3d): wall seconds (medians over
    the rounds), the ratio within each round (median), outer iterations, and at 64³ each code's
    time error; then the pressure solve, FFTW against hypre."""
    walls = {}
    with open(os.path.join(cube_dir, "walls.csv"), newline="") as f:
        for r in csv.DictReader(f):
            walls.setdefault((int(r["n"]), r["row"]), {})[int(r["round"])] = float(r["wall_s"])
    print(f"{'cube':>5} {'code, setting':<26} {'wall s':>8} {'icoFoam/this':>12} {'outer/step':>10} "
          f"{'time error at 64³':>17}")
    for n in (64, 128):
        foam = walls.get((n, "icofoam"), {})
        error = {}
        if n == 64 and (64, "icofoam_ref") in walls:
            reference = read_icofoam_u(os.path.join(cube_dir, "icofoam_n64_ref"), 64)
            error["icofoam"] = max_abs_difference(
                read_icofoam_u(os.path.join(cube_dir, "icofoam_n64"), 64), reference)
            reference = read_fddem_u(os.path.join(cube_dir, "n64_ref"), 64)
            for row in ("tol1e-4", "tol1e-5", "projection"):
                error[row] = max_abs_difference(
                    read_fddem_u(os.path.join(cube_dir, f"n64_{row}"), 64), reference)
        for row, label in (("icofoam", "icoFoam, PISO 2 correctors"),
                           ("tol1e-4", "fddem, tolerance 1e-4"),
                           ("tol1e-5", "fddem, tolerance 1e-5"),
                           ("projection", "fddem, projection step")):
            times = walls.get((n, row), {})
            if not times:
                continue
            ratios = [foam[k] / times[k] for k in times if k in foam]
            outer = "–"
            if row != "icofoam":
                steps, _, _, total, _ = run_costs(os.path.join(cube_dir, f"n{n}_{row}"))
                outer = f"{total / steps:.2f}"
            err = f"{error[row]:.2e}" if row in error else "–"
            print(f"{n:>4}³ {label:<26} {statistics.median(times.values()):>8.2f} "
                  f"{statistics.median(ratios):>12.2f} {outer:>10} {err:>17}")
    print()
    print(f"{'cube':>5} {'pressure solver':<16} {'outer its':>9} {'pressure s':>10} "
          f"{'ms per outer':>12} {'hypre/fft':>9}")
    for n in (64, 128):
        per = {}
        for solver in ("fft", "hypre"):
            run_dir = os.path.join(cube_dir, f"pressure_n{n}_{solver}")
            if not os.path.isdir(run_dir):
                continue
            steps, _, phases, outer, _ = run_costs(run_dir)
            per[solver] = phases.get("pressure", 0) / outer
            ratio = f"{per[solver] / per['fft']:.2f}" if "fft" in per else "–"
            print(f"{n:>4}³ {solver:<16} {outer:>9} {phases.get('pressure', 0):>10.2f} "
                  f"{1e3 * per[solver]:>12.1f} {ratio:>9}")


def max_abs_difference(a, b):
    return max(abs(p - q) for p, q in zip(a, b))


def mpi_table(cores, entries):
    """Strong and weak scaling rows (kind:ranks:run_dir), each against its one-rank row."""
    cores = int(cores)
    print(f"{'scaling':>14} {'ranks':>5} {'cells':>11} {'ms/step':>9} {'outer/step':>10} "
          f"{'speed-up':>8} {'efficiency':>10} {'pressure %':>10} {'momentum %':>10} "
          f"{'msgs/step':>9} {'KiB/step':>8} {'coll/step':>9} {'a2a KiB/step':>12} {'comm %':>6} "
          f"{'comm in mom. %':>14} {'comm in coupl. %':>16}")
    base = {}
    for entry in entries:
        kind, ranks, run_dir = entry.split(":", 2)
        ranks = int(ranks)
        steps, stepping, phases, outer, summary = run_costs(run_dir)
        with open(os.path.join(run_dir, "case.toml"), "rb") as f:
            cells = tomllib.load(f)["domain"]["cells"]
        per_step = stepping / steps
        if ranks == 1:
            base[kind] = per_step
        # Strong: T1 / (p Tp); weak (the work grows with p): T1 / Tp.
        speed_up = base[kind] / per_step if kind in base else float("nan")
        efficiency = speed_up if kind.startswith("weak") else speed_up / ranks
        note = "  (oversubscribed)" if ranks > cores else ""
        messages = summary.get("mpi_rank0_messages", 0) / steps
        kib = summary.get("mpi_rank0_message_bytes", 0) / steps / 1024
        collectives = summary.get("mpi_rank0_collectives", 0) / steps
        a2a_kib = summary.get("mpi_rank0_all_to_all_bytes", 0) / steps / 1024
        comm = 100 * summary.get("mpi_rank0_communication_seconds", 0) / stepping

        def share(phase):
            seconds = phases.get(phase, 0)
            own = summary.get(f"mpi_rank0_communication_seconds_{phase}", 0)
            return 100 * own / seconds if seconds > 0 else 0.0

        print(f"{kind:>14} {ranks:>5} {'x'.join(str(c) for c in cells):>11} "
              f"{1e3 * per_step:>9.1f} {outer / steps:>10.2f} {speed_up:>8.2f} "
              f"{efficiency:>10.2f} {100 * phases.get('pressure', 0) / stepping:>10.1f} "
              f"{100 * phases.get('momentum', 0) / stepping:>10.1f} {messages:>9.0f} "
              f"{kib:>8.0f} {collectives:>9.0f} {a2a_kib:>12.0f} {comm:>6.1f} {share('momentum'):>14.1f} "
              f"{share('coupling'):>16.1f}{note}")
    print("  speed-up: T(1 rank) / T(p) per step; efficiency: speed-up / p (strong*), speed-up "
          "(weak, p times the cells). msgs, KiB, coll: rank 0's halo messages, their payload and "
          "its collectives per step; a2a: what left rank 0 in the all-to-alls between the grid's "
          "blocks and FFTW-MPI's slabs (*_fft rows); comm: rank 0's wall time inside fddem's own "
          "halo exchanges, collectives and all-to-alls, waiting included, of the whole step and of "
          "the momentum and coupling phases (hypre's and FFTW-MPI's own messages and time are not "
          "counted).")
    mpi_model(entries, "weak")
    mpi_model(entries, "weak_fft")


def mpi_memory_table(n, *entries):
    """Peak resident memory per process (ranks:kib,kib,…, GNU time's %M, in rank-independent
    order) on one process and on several ranks."""
    n = int(n)
    print(f"{'ranks':>5} {'cells':>11} {'largest MiB':>11} {'smallest MiB':>12} "
          f"{'largest/smallest':>16} {'sum MiB':>8} {'B/cell (sum)':>12}")
    for entry in entries:
        ranks, values = entry.split(":", 1)
        kib = [int(v) for v in values.split(",") if v]
        mib = [k / 1024 for k in kib]
        print(f"{ranks:>5} {f'{n}^3':>11} {max(mib):>11.0f} {min(mib):>12.0f} "
              f"{max(mib) / min(mib):>16.2f} {sum(mib):>8.0f} {sum(kib) * 1024 / n**3:>12.0f}")
    print("  each process's peak resident memory over the whole run (the closing checkpoint "
          "included); with no rank holding the whole grid, the ranks' peaks are alike and their "
          "sum is near the one-process run's.")


# The cluster the efficiency model assumes: one message's latency [s] and the link's bandwidth
# [B/s]. Typical of InfiniBand EDR/HDR (about 1-2 µs, 10-25 GB/s); the pessimistic pair is an
# Ethernet-like cluster.
CLUSTERS = (("InfiniBand-like", 1.5e-6, 10e9), ("Ethernet-like", 20e-6, 2e9))


def mpi_model(entries, kind, target_ranks=64):
    """The expected weak-scaling efficiency on a cluster, from the measured counts of the `kind`
    rows (weak: hypre's pressure; weak_fft: FFTW-MPI's).

    Rank 0 is a corner block: with the weak layout (the box doubled along x, then y, then z) it
    has log2(p) neighbours up to 3, while a block inside a 4 x 4 x 4 layout has 6. Its messages
    and bytes per step, scaled by 6 / neighbours, are an inside block's; its collectives are
    every rank's. The time per step on a cluster is then the one-rank compute time T1 plus
    messages * latency + bytes / bandwidth + collectives * (2 log2(p) latency + p * payload /
    bandwidth) (the sums are all-gathers of each rank's values, added in rank order).
    hypre's own messages, inside the pressure solve, are not counted by fddem and not in the
    model. FFTW-MPI's are modelled: per pressure solve (one per outer iteration) fddem's two
    all-to-alls between blocks and slabs and FFTW's two transposes (one each way with the
    transposed output and input), each a pairwise exchange of (p - 1) messages carrying
    (p - 1)/p of the rank's cells, 8 B each; the blocks' all-to-alls are taken at that bound
    (where a block is already a slab they move nothing)."""
    weak = []
    for entry in entries:
        row_kind, ranks, run_dir = entry.split(":", 2)
        if row_kind == kind:
            weak.append((int(ranks), run_cost_row(run_dir)))
    t1 = next((row["per_step"] for ranks, row in weak if ranks == 1), None)
    split = [(ranks, row) for ranks, row in weak if ranks > 1]
    if t1 is None or not split:
        return
    ranks, row = max(split, key=lambda item: item[0])
    neighbours = min(int(math.log2(ranks)), 3)
    scale = 6 / neighbours
    messages, message_bytes = row["messages"] * scale, row["bytes"] * scale
    collectives = row["collectives"]
    payload = row["collective_bytes"] / collectives if collectives else 0.0
    is_fft = kind == "weak_fft"
    transposes = 4 * row["outer"] if is_fft else 0.0
    transpose_bytes = 8 * row["cells"] / ranks * (target_ranks - 1) / target_ranks
    print(f"  model of the {kind} scaling to {target_ranks} ranks on a cluster, from the {ranks}-rank "
          f"row (rank 0 has {neighbours} neighbour(s); an inside block has 6): per step "
          f"{messages:.0f} messages, {message_bytes / 1024:.0f} KiB, {collectives:.0f} "
          f"collectives of {payload:.0f} B"
          + (f", {transposes:.0f} all-to-alls of {transpose_bytes / 1024:.0f} KiB" if is_fft else "")
          + f", against T1 = {1e3 * t1:.1f} ms of compute")
    for name, latency, bandwidth in CLUSTERS:
        halo = messages * latency + message_bytes / bandwidth
        reduce = collectives * (2 * math.log2(target_ranks) * latency +
                                target_ranks * payload / bandwidth)
        exchange = transposes * ((target_ranks - 1) * latency + transpose_bytes / bandwidth)
        efficiency = t1 / (t1 + halo + reduce + exchange)
        pressure = (f" + all-to-alls {1e3 * exchange:.1f} ms" if is_fft else "")
        left_out = "" if is_fft else " (hypre's messages not included)"
        print(f"    {name} ({1e6 * latency:.1f} µs, {bandwidth / 1e9:.0f} GB/s): halo "
              f"{1e3 * halo:.1f} ms + collectives {1e3 * reduce:.1f} ms{pressure} per step -> "
              f"efficiency {efficiency:.2f}{left_out}")


def run_cost_row(run_dir):
    """Per-step time and rank 0's per-step counts of a run."""
    steps, stepping, _, outer, summary = run_costs(run_dir)
    with open(os.path.join(run_dir, "case.toml"), "rb") as f:
        cells = math.prod(tomllib.load(f)["domain"]["cells"])
    return {"per_step": stepping / steps, "outer": outer / steps, "cells": cells,
            "messages": summary.get("mpi_rank0_messages", 0) / steps,
            "bytes": summary.get("mpi_rank0_message_bytes", 0) / steps,
            "collectives": summary.get("mpi_rank0_collectives", 0) / steps,
            "collective_bytes": summary.get("mpi_rank0_collective_bytes", 0) / steps}


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


# High-resolution extrema for Re = 100 (u_min on x = 0.5, v_max and v_min on y = 0.5), as quoted
# in shared/peers/openfoam-cavity/RESULTS.md (Marchi, Suero & Araki 2009), trusted to ~1e-6.
HIGH_RESOLUTION_RE100 = (-0.2140424, 0.1795728, -0.2538030)


def extremum(xs, fs, sign):
    """Extremum by a parabola through the three samples around the discrete one."""
    b = max(range(1, len(fs) - 1), key=lambda k: sign * fs[k])
    a, d, c = fs[b - 1], fs[b], fs[b + 1]
    den = a - 2 * d + c
    t = 0.5 * (a - c) / den if den != 0 else 0.0
    return d - 0.25 * (a - c) * t


def extrema_errors(y, u, x, v):
    found = (extremum(y, u, -1), extremum(x, v, 1), extremum(x, v, -1))
    return [abs(f - r) for f, r in zip(found, HIGH_RESOLUTION_RE100)]


def fddem_centrelines(run_dir):
    """(y, u on x = 0.5, x, v on y = 0.5) from a cavity run's samples/*.csv."""
    with open(os.path.join(run_dir, "samples", "vertical_centerline.csv"), newline="") as f:
        vertical = list(csv.DictReader(f))
    with open(os.path.join(run_dir, "samples", "horizontal_centerline.csv"), newline="") as f:
        horizontal = list(csv.DictReader(f))
    return (
        [float(r["y"]) for r in vertical],
        [float(r["u"]) for r in vertical],
        [float(r["x"]) for r in horizontal],
        [float(r["v"]) for r in horizontal],
    )


def openfoam_centrelines(peer_results, name):
    """(y, u on x = 0.5, x, v on y = 0.5) of one peer run, results/<name>_{u,v}.csv."""
    u_rows = read_xy(os.path.join(peer_results, f"{name}_u.csv"))
    v_rows = read_xy(os.path.join(peer_results, f"{name}_v.csv"))
    return [r[0] for r in u_rows], [r[1] for r in u_rows], [r[0] for r in v_rows], [r[1] for r in v_rows]


def ghia_deviations(centrelines, reference_dir):
    """max |u - Ghia| on x = 0.5 and max |v - Ghia| on y = 0.5 (linear interpolation)."""
    y, u, x, v = centrelines
    ghia_u = read_xy(os.path.join(reference_dir, "ghia1982_u_vertical_centerline.csv"))
    ghia_v = read_xy(os.path.join(reference_dir, "ghia1982_v_horizontal_centerline.csv"))
    return max_deviation(y, u, ghia_u), max_deviation(x, v, ghia_v)


def read_peer_runs(peer_results):
    """The peer's results/runs.csv, in the order the runs were made."""
    with open(os.path.join(peer_results, "runs.csv"), newline="") as f:
        return list(csv.DictReader(f))


def openfoam_table(fddem_dir, fddem_wall, peer_results, n, reference_dir):
    fddem_lines = fddem_centrelines(fddem_dir)
    fddem_u, fddem_v = ghia_deviations(fddem_lines, reference_dir)
    name = f"icoFoam_N{n}_Re100_T20"
    of_lines = openfoam_centrelines(peer_results, name)
    of_u, of_v = ghia_deviations(of_lines, reference_dir)
    of_wall = None
    for row in read_peer_runs(peer_results):
        if row["name"] == name:
            of_wall = float(row["wall_s"])
    steps = len(read_solver_csv(fddem_dir))
    fddem_ext = extrema_errors(*fddem_lines)
    of_ext = extrema_errors(*of_lines)
    print(
        f"{'code':>8} {'wall s':>8} {'steps':>6} {'max|u-Ghia|':>12} {'max|v-Ghia|':>12} "
        f"{'|du_min|':>9} {'|dv_max|':>9} {'|dv_min|':>9}"
    )
    for name, wall, count, du, dv, ext in (
        ("fddem", float(fddem_wall), str(steps), fddem_u, fddem_v, fddem_ext),
        ("icoFoam", of_wall, "", of_u, of_v, of_ext),
    ):
        print(
            f"{name:>8} {wall:>8.1f} {count:>6} {du:>12.5f} {dv:>12.5f} "
            f"{ext[0]:>9.1e} {ext[1]:>9.1e} {ext[2]:>9.1e}"
        )
    print(f"wall-time ratio icoFoam / fddem: {of_wall / float(fddem_wall):.2f}")
    print("(Ghia et al. 1982 are themselves a 129² solution, off by ~1e-3; the |d…| columns")
    print(" compare the centreline extrema with high-resolution values, Marchi et al. 2009.)")


def ghia_table(run_dir, reference_dir):
    """Centreline deviations of one cavity run from Ghia et al. and, for Re 100, the extrema."""
    y, u, x, v = fddem_centrelines(run_dir)
    du, dv = ghia_deviations((y, u, x, v), reference_dir)
    print(f"{run_dir}: max|u - Ghia| = {du:.5f}, max|v - Ghia| = {dv:.5f}")
    print(f"  extrema: u_min {extremum(y, u, -1):.6f}, v_max {extremum(x, v, 1):.6f}, "
          f"v_min {extremum(x, v, -1):.6f}")


# The rows of the --steady table (bench/run.sh writes them): fddem's run directories
# re<Re>_<row>, simpleFoam's peer runs by name; the last of each code is its reference.
FDDEM_STEADY_ROWS = (
    ("pseudo", "pseudo-time (shipped case)"),
    ("pseudo_simple1e-6", "pseudo-time, simple.tolerance 1e-6"),
    ("marched", "time-marched, dt = h"),
    ("tight", "pseudo-time, tolerances 1e-9/1e-10 (ref)"),
)
OPENFOAM_STEADY_ROWS = (
    ("simplec", "SIMPLEC, residuals 1e-6"),
    ("simplec_tol1e-9", "SIMPLEC, residuals 1e-9 (ref)"),
)
# Ratios within a round: (numerator, denominator), each (code, row).
STEADY_RATIOS = (
    (("simpleFoam", "simplec"), ("fddem", "pseudo")),
    (("simpleFoam", "simplec"), ("fddem", "pseudo_simple1e-6")),
    (("fddem", "marched"), ("fddem", "pseudo")),
)


def max_difference(a, b):
    """Largest |a - b| over both centrelines of two runs of one code on one grid."""
    return max(max(abs(p - q) for p, q in zip(a[k], b[k])) for k in (1, 3))


def steady_rows(steady_dir, peer_results, cases_dir, re):
    """One dict per row of the --steady table for one Reynolds number."""
    reference_dir = os.path.join(cases_dir, f"cavity_re{re}", "reference")
    walls = {}
    with open(os.path.join(steady_dir, "walls.csv"), newline="") as f:
        for r in csv.DictReader(f):
            if int(r["re"]) == re:
                walls.setdefault(("fddem", r["row"]), []).append(float(r["wall_s"]))
    rows = []
    for row, mode in FDDEM_STEADY_ROWS:
        run_dir = os.path.join(steady_dir, f"re{re}_{row}")
        summary = read_summary(run_dir)
        with open(os.path.join(run_dir, "case.toml"), "rb") as f:
            tolerance = tomllib.load(f)["time"]["steady_tolerance"]
        rows.append(dict(code="fddem", row=row, mode=mode, steps=summary["steps"],
                         outer=summary["total_outer_iterations"],
                         reached=summary["last_rate_of_change"] < tolerance,
                         walls=walls[("fddem", row)], lines=fddem_centrelines(run_dir)))
    peer_runs = read_peer_runs(peer_results)
    for row, mode in OPENFOAM_STEADY_ROWS:
        name = f"simpleFoam_N128_Re{re}_{row}"
        runs = [r for r in peer_runs if r["name"] == name]
        rows.append(dict(code="simpleFoam", row=row, mode=mode, steps=int(runs[-1]["steps"]),
                         outer=int(runs[-1]["steps"]),
                         reached=all(r["converged"] == "converged" for r in runs),
                         walls=[float(r["wall_s"]) for r in runs],
                         lines=openfoam_centrelines(peer_results, name)))
    for code in ("fddem", "simpleFoam"):
        reference = [r for r in rows if r["code"] == code][-1]["lines"]
        for r in rows:
            if r["code"] == code:
                r["iteration_error"] = max_difference(r["lines"], reference)
    for r in rows:
        r["ghia"] = ghia_deviations(r["lines"], reference_dir)
    return rows


def steady_table(steady_dir, peer_results, cases_dir):
    """Time to the steady state: fddem (pseudo-time and time-marched) against simpleFoam."""
    print(
        f"{'Re':>5} {'code':<10} {'mode':<42} {'steps':>6} {'outer it':>8} {'wall s':>7} "
        f"{'(min-max)':>13} {'max|u-Ghia|':>11} {'max|v-Ghia|':>11} {'iter. error':>11}"
    )
    ratios = []
    for re in (100, 1000):
        rows = steady_rows(steady_dir, peer_results, cases_dir, re)
        for r in rows:
            walls = r["walls"]
            spread = f"({min(walls):.2f}-{max(walls):.2f})" if len(walls) > 1 else "(1 run)"
            flag = "" if r["reached"] else " NOT STEADY"
            error = "ref" if r["iteration_error"] == 0.0 else f"{r['iteration_error']:.1e}"
            print(
                f"{re:>5} {r['code']:<10} {r['mode']:<42} {r['steps']:>6} {r['outer']:>8} "
                f"{statistics.median(walls):>7.2f} {spread:>13} {r['ghia'][0]:>11.5f} "
                f"{r['ghia'][1]:>11.5f} {error:>11}{flag}"
            )
        by_key = {(r["code"], r["row"]): r for r in rows}
        for numerator, denominator in STEADY_RATIOS:
            a, b = by_key[numerator]["walls"], by_key[denominator]["walls"]
            paired = [x / y for x, y in zip(a, b)]
            ratios.append(
                f"Re {re:>4}: {numerator[0]} {by_key[numerator]['mode']} / {denominator[0]} "
                f"{by_key[denominator]['mode']}: {statistics.median(paired):.2f} "
                f"(rounds: {', '.join(f'{p:.2f}' for p in paired)})"
            )
    print("wall s: median over the rounds (fddem: the whole process; simpleFoam: the solver command,")
    print("  as the peer times it). iter. error: max |Δu|, |Δv| on the centrelines from the same code's")
    print("  reference row (ref) on the same grid. Ratios: median of the ratios within each round.")
    for line in ratios:
        print(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mode", choices=["cavity", "openfoam", "ghia", "paper", "steady", "three_d",
                                         "mpi", "mpi_memory", "cube3d"])
    parser.add_argument("args", nargs="+")
    options = parser.parse_args()
    if options.mode == "cavity":
        cavity_table(options.args)
    elif options.mode == "ghia":
        ghia_table(*options.args)
    elif options.mode == "paper":
        paper_table(options.args)
    elif options.mode == "three_d":
        three_d_table(options.args)
    elif options.mode == "mpi":
        mpi_table(options.args[0], options.args[1:])
    elif options.mode == "mpi_memory":
        mpi_memory_table(*options.args)
    elif options.mode == "steady":
        steady_table(*options.args)
    elif options.mode == "cube3d":
        cube3d_table(options.args[0])
    else:
        openfoam_table(*options.args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
