"""Readers for an fddem run directory (docs/output-files.md).

Every reader returns numpy arrays; the table readers return a pandas DataFrame instead when
asked (``as_frame=True``) or, by default (``as_frame=None``), whenever pandas is installed.
Only numpy is required.
"""

import csv
import json
import os
import re
import xml.etree.ElementTree as ElementTree

import numpy as np

try:
    import pandas
except ImportError:  # pandas is optional
    pandas = None


class NotARunError(Exception):
    """A directory that is not an fddem run directory (no case.toml)."""


def has_pandas():
    return pandas is not None


def _to_frame(columns, as_frame):
    """`columns` (name -> array) as a DataFrame if asked for (or, with None, if pandas exists)."""
    if as_frame is None:
        as_frame = pandas is not None
    if not as_frame:
        return columns
    if pandas is None:
        raise ImportError("as_frame=True needs pandas (Debian: python3-pandas)")
    return pandas.DataFrame(columns)


# Columns that count things: integers in a DataFrame (numpy arrays stay float, as written).
INTEGER_COLUMNS = {"id", "step", "outer_iterations", "total_outer_iterations", "is_converged"}


def read_csv_columns(path, as_frame=False):
    """A CSV file with a header line: dict column name -> float array (or a DataFrame, whose
    counting columns, INTEGER_COLUMNS, are integers)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(x) for x in row] for row in reader if row]
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    columns = {name: data[:, k] for k, name in enumerate(header)}
    frame = _to_frame(columns, as_frame)
    if frame is not columns:
        for name in INTEGER_COLUMNS.intersection(header):
            frame[name] = frame[name].astype(int)
    return frame


def read_solver(run_dir, as_frame=False):
    """solver.csv: one row per time step (columns in docs/output-files.md)."""
    return read_csv_columns(os.path.join(run_dir, "solver.csv"), as_frame)


def read_particle_rows(run_dir, as_frame=False):
    """particles.csv as it is: one row per body per output time."""
    return read_csv_columns(os.path.join(run_dir, "particles.csv"), as_frame)


def read_particles(run_dir):
    """particles.csv as a dict: body id -> dict of column arrays, in time order."""
    columns = read_particle_rows(run_dir)
    ids = columns["id"].astype(int)
    particles = {}
    for body in np.unique(ids):
        mask = ids == body
        order = np.argsort(columns["time"][mask], kind="stable")
        particles[int(body)] = {name: values[mask][order] for name, values in columns.items()}
    return particles


def read_samples(run_dir, as_frame=False):
    """samples/<name>.csv of the run: dict name -> its columns (x, y[, z], u, v[, w], p)."""
    directory = os.path.join(run_dir, "samples")
    if not os.path.isdir(directory):
        return {}
    return {
        name[:-4]: read_csv_columns(os.path.join(directory, name), as_frame)
        for name in sorted(os.listdir(directory))
        if name.endswith(".csv")
    }


def read_summary(run_dir):
    """summary.json as a dict ({} while the run has not written one)."""
    path = os.path.join(run_dir, "summary.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return json.load(f)


def read_case(run_dir):
    """The case as run (case.toml) as a dict (tomllib, Python 3.11)."""
    import tomllib

    with open(os.path.join(run_dir, "case.toml"), "rb") as f:
        return tomllib.load(f)


def read_body_file(path):
    """The rows of a body file ([[bodies]] file, io/body_file.hpp) as dicts: "id" (int),
    "position" (list), "diameter", "density" and, if the file has u, v (w), "velocity"."""
    with open(path, newline="") as f:
        lines = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
    rows = []
    for row in csv.DictReader(lines, skipinitialspace=True):
        axes = [a for a in "xyz" if a in row]
        body = {"id": int(row["id"]), "position": [float(row[a]) for a in axes],
                "diameter": float(row["diameter"]), "density": float(row["density"])}
        if "u" in row:
            body["velocity"] = [float(row[c]) for c in "uvw"[:len(axes)]]
        rows.append(body)
    return rows


def read_case_title(run_dir):
    """The case's [case] title, or the directory's name when it has none."""
    title = read_case(run_dir).get("case", {}).get("title", "")
    return title or os.path.basename(os.path.normpath(run_dir))


def read_case_source(run_dir):
    """The case file the run was started from, as case.toml's header records it ("# Source:")."""
    with open(os.path.join(run_dir, "case.toml")) as f:
        for line in f:
            if line.startswith("# Source:"):
                return line.split(":", 1)[1].strip()
            if not line.startswith("#"):
                break
    return None


def check_run_directory(run_dir):
    """Raise NotARunError unless `run_dir` holds an fddem run (a case.toml)."""
    if not os.path.isdir(run_dir):
        raise NotARunError(f"{run_dir}: no such directory")
    if not os.path.isfile(os.path.join(run_dir, "case.toml")):
        raise NotARunError(f"{run_dir}: not an fddem run directory (no case.toml)")


def read_pvd(run_dir, name="fields.pvd"):
    """A .pvd collection as a list of (time, absolute file path) in time order ([] if absent)."""
    path = os.path.join(run_dir, name)
    if not os.path.exists(path):
        return []
    root = ElementTree.parse(path).getroot()
    frames = [
        (float(d.get("timestep")), os.path.join(run_dir, d.get("file")))
        for d in root.iter("DataSet")
    ]
    return sorted(frames)


_DATA_ARRAY = re.compile(
    r'<DataArray type="(Float64|Int64)"(?: Name="(\w+)")?( NumberOfComponents="(\d)")?'
    r' format="appended" offset="(\d+)"/>'
)


def _appended_arrays(path):
    """The appended raw arrays of an fddem VTK XML file (UInt64 block headers), in file order:
    a list of (name or None, values, components), and the XML header text."""
    with open(path, "rb") as f:
        data = f.read()
    start = data.index(b"<AppendedData")
    base = data.index(b"_", start) + 1
    header = data[:start].decode()
    arrays = []
    for m in _DATA_ARRAY.finditer(header):
        dtype = "<f8" if m.group(1) == "Float64" else "<i8"
        offset = base + int(m.group(5))
        n_bytes = int(np.frombuffer(data, dtype="<u8", count=1, offset=offset)[0])
        values = np.frombuffer(data, dtype=dtype, count=n_bytes // 8, offset=offset + 8)
        arrays.append((m.group(2), values, int(m.group(4) or 1)))
    return arrays, header


def read_vtr(path):
    """An fddem field file (.vtr): dict with the node coordinates "x", "y", "z" and each cell
    array by name, shaped (nz, ny, nx) or (nz, ny, nx, components); nz = 1 in 2D."""
    arrays, _ = _appended_arrays(path)
    named = {name: (values, components) for name, values, components in arrays}
    x, y, z = (named.pop(k)[0] for k in ("x", "y", "z"))
    shape = (max(len(z) - 1, 1), len(y) - 1, len(x) - 1)
    result = {"x": x, "y": y, "z": z}
    for name, (values, components) in named.items():
        result[name] = values.reshape(shape + ((components,) if components > 1 else ()))
    return result


def read_vtp(path):
    """An fddem particle file (.vtp): dict with "centre" (n, 3), "radius" (n), "velocity" (n, 3)
    and "angular_velocity" (n, 3), in body order."""
    arrays, _ = _appended_arrays(path)
    result = {}
    for name, values, components in arrays:
        if name is None:  # the Points array has no name
            result["centre"] = values.reshape(-1, 3)
        elif name in ("radius", "velocity", "angular_velocity"):
            result[name] = values.reshape(-1, components) if components > 1 else values
    return result


def frame_times(run_dir):
    """The times of the field frames."""
    return np.array([t for t, _ in read_pvd(run_dir)])
