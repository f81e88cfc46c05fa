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
    """An fddem field file (.vtr), or a split run's frame in pieces (.pvtr, assembled by
    read_pvtr): dict with the node coordinates "x", "y", "z" and each cell array by name, shaped
    (nz, ny, nx) or (nz, ny, nx, components); nz = 1 in 2D."""
    if path.endswith(".pvtr"):
        return read_pvtr(path)
    arrays, _ = _appended_arrays(path)
    named = {name: (values, components) for name, values, components in arrays}
    x, y, z = (named.pop(k)[0] for k in ("x", "y", "z"))
    shape = (max(len(z) - 1, 1), len(y) - 1, len(x) - 1)
    result = {"x": x, "y": y, "z": z}
    for name, (values, components) in named.items():
        result[name] = values.reshape(shape + ((components,) if components > 1 else ()))
    return result


def _extent(text):
    """A VTK extent "x0 x1 y0 y1 z0 z1" as ((x0, x1), (y0, y1), (z0, z1))."""
    values = [int(v) for v in text.split()]
    return tuple((values[2 * d], values[2 * d + 1]) for d in range(3))


def _master_pieces(path, kind):
    """The root element of a parallel master file of `kind` (PRectilinearGrid, PPolyData), its
    arrays {name: components} and its pieces as (element, absolute path of the piece)."""
    root = ElementTree.parse(path).getroot()
    grid = root.find(kind)
    if grid is None:
        raise ValueError(f"{path}: not a {kind} file")
    arrays = {}
    for data in (grid.find("PCellData"), grid.find("PPointData")):
        if data is not None:
            for array in data.iter("PDataArray"):
                arrays[array.get("Name")] = int(array.get("NumberOfComponents", "1"))
    folder = os.path.dirname(path)
    pieces = [(piece, os.path.join(folder, piece.get("Source"))) for piece in grid.iter("Piece")]
    if not pieces:
        raise ValueError(f"{path}: no pieces")
    return grid, arrays, pieces


def read_pvtr(path):
    """A split run's field frame (.pvtr, one .vtr piece per rank) assembled into one frame, as
    read_vtr returns it. The pieces' extents must tile the whole extent: every cell in exactly
    one piece (ValueError otherwise)."""
    grid, listed, pieces = _master_pieces(path, "PRectilinearGrid")
    whole = _extent(grid.get("WholeExtent"))
    n = [max(hi - lo, 1) for lo, hi in whole]  # cells along x, y, z (1 along z in 2D)
    covered = np.zeros((n[2], n[1], n[0]), dtype=int)
    nodes = [np.full(hi - lo + 1, np.nan) for lo, hi in whole]
    result = {}
    for piece, piece_path in pieces:
        extent = _extent(piece.get("Extent"))
        frame = read_vtr(piece_path)
        starts = [extent[d][0] - whole[d][0] for d in range(3)]
        cells = tuple(
            slice(starts[d], starts[d] + max(extent[d][1] - extent[d][0], 1)) for d in (2, 1, 0)
        )
        for d, axis in enumerate("xyz"):
            if len(frame[axis]) != extent[d][1] - extent[d][0] + 1:
                raise ValueError(
                    f"{piece_path}: {len(frame[axis])} {axis} nodes for the extent {extent[d]}"
                )
            nodes[d][starts[d] : starts[d] + len(frame[axis])] = frame[axis]
        covered[cells] += 1
        for name in listed:
            if name not in frame:
                raise ValueError(f"{piece_path}: no array {name}, which {path} lists")
            values = frame[name]
            components = values.shape[3] if values.ndim == 4 else 1
            if components != listed[name]:
                raise ValueError(
                    f"{piece_path}: {name} has {components} components, {path} says {listed[name]}")
            if name not in result:
                result[name] = np.full(tuple(covered.shape) + values.shape[3:], np.nan)
            result[name][cells] = values
    if np.any(covered != 1):
        raise ValueError(f"{path}: the pieces cover {int(np.sum(covered == 0))} cells not at all "
                         f"and {int(np.sum(covered > 1))} more than once")
    result.update({"x": nodes[0], "y": nodes[1], "z": nodes[2]})
    return result


def read_vtp(path):
    """An fddem particle file (.vtp), or a split run's frame in pieces (.pvtp, assembled by
    read_pvtp): dict with "centre" (n, 3) and each point array by name ("id", "radius" (n),
    "velocity" (n, 3), "angular_velocity" (n, 3), "orientation" (n, 4), the forces, …), in body
    order."""
    if path.endswith(".pvtp"):
        return read_pvtp(path)
    arrays, _ = _appended_arrays(path)
    result = {}
    for name, values, components in arrays:
        if name is None:  # the Points array has no name
            result["centre"] = values.reshape(-1, 3)
        elif name not in ("connectivity", "offsets"):
            result[name] = values.reshape(-1, components) if components > 1 else values
    return result


def read_pvtp(path):
    """A split run's particle frame (.pvtp, one .vtp piece per rank: the bodies whose centre
    lies in its block) assembled into one, as read_vtp returns it, in id order."""
    _, listed, pieces = _master_pieces(path, "PPolyData")
    parts = []
    for _, piece_path in pieces:
        part = read_vtp(piece_path)
        for name, components in listed.items():
            if name not in part:
                raise ValueError(f"{piece_path}: no array {name}, which {path} lists")
            held = part[name].shape[1] if part[name].ndim == 2 else 1
            if held != components:
                raise ValueError(
                    f"{piece_path}: {name} has {held} components, {path} says {components}")
        parts.append(part)
    result = {name: np.concatenate([part[name] for part in parts]) for name in parts[0]}
    if "id" not in result:
        return result
    order = np.argsort(result["id"], kind="stable")
    if len(np.unique(result["id"])) != len(order):
        raise ValueError(f"{path}: a body is in more than one piece")
    return {name: values[order] for name, values in result.items()}


def frame_times(run_dir):
    """The times of the field frames."""
    return np.array([t for t, _ in read_pvd(run_dir)])
