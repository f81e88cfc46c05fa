#!/usr/bin/python3
"""Readers for fddem's run-directory files (docs/output-files.md), for the plotting tools.

Only numpy is needed. Every reader takes a run directory and returns plain numpy arrays.
"""
import csv
import json
import os

import numpy as np


def read_csv_columns(path):
    """A CSV file with a header line as a dict: column name -> numpy array."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(x) for x in row] for row in reader if row]
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    return {name: data[:, k] for k, name in enumerate(header)}


def read_solver(run_dir):
    """solver.csv: one row per time step."""
    return read_csv_columns(os.path.join(run_dir, "solver.csv"))


def read_particles(run_dir):
    """particles.csv as a dict: particle id -> dict of column arrays (sorted by time)."""
    columns = read_csv_columns(os.path.join(run_dir, "particles.csv"))
    ids = columns["id"].astype(int)
    particles = {}
    for pid in np.unique(ids):
        mask = ids == pid
        order = np.argsort(columns["time"][mask])
        particles[int(pid)] = {name: values[mask][order] for name, values in columns.items()}
    return particles


def read_summary(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def read_case_title(run_dir):
    """The [case] title of the case as run, or the directory name."""
    path = os.path.join(run_dir, "case.toml")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                stripped = line.strip()
                if stripped.startswith("title"):
                    return stripped.split("=", 1)[1].strip().strip("'\"")
    return os.path.basename(os.path.normpath(run_dir))


def read_case(run_dir):
    """The case as run (case.toml) as a dict (Python ≥ 3.11 tomllib)."""
    import tomllib

    with open(os.path.join(run_dir, "case.toml"), "rb") as f:
        return tomllib.load(f)


def read_pvd(run_dir, name="fields.pvd"):
    """A .pvd collection as a list of (time, absolute file path), in time order."""
    import xml.etree.ElementTree as ET

    root = ET.parse(os.path.join(run_dir, name)).getroot()
    frames = [(float(d.get("timestep")), os.path.join(run_dir, d.get("file"))) for d in root.iter("DataSet")]
    return sorted(frames)


def read_vtr(path):
    """A fddem .vtr file (appended raw, UInt64 headers, Float64 data) as a dict with the node
    coordinates "x", "y", "z" and the cell arrays by name, each shaped (nz, ny, nx[, 3])."""
    import re

    with open(path, "rb") as f:
        data = f.read()
    start = data.index(b"<AppendedData")
    base = data.index(b"_", start) + 1
    header = data[:start].decode()

    def array(offset):
        n_bytes = int(np.frombuffer(data, dtype="<u8", count=1, offset=base + offset)[0])
        return np.frombuffer(data, dtype="<f8", count=n_bytes // 8, offset=base + offset + 8)

    out = {}
    for m in re.finditer(r'<DataArray type="Float64" Name="(\w+)"( NumberOfComponents="(\d)")?'
                         r' format="appended" offset="(\d+)"/>', header):
        out[m.group(1)] = (array(int(m.group(4))), int(m.group(3) or 1))
    x, y, z = (out.pop(k)[0] for k in ("x", "y", "z"))
    shape = (max(len(z) - 1, 1), len(y) - 1, len(x) - 1)
    result = {"x": x, "y": y, "z": z}
    for name, (values, components) in out.items():
        result[name] = values.reshape(shape + ((components,) if components > 1 else ()))
    return result
