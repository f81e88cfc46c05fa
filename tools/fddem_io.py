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
                    return stripped.split("=", 1)[1].strip().strip('"')
    return os.path.basename(os.path.normpath(run_dir))
