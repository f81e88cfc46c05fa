"""Published data for a run, found through the case file it was started from.

A run's case.toml records its source case file ("# Source: …"); a case that has published data
keeps it in `reference/` beside its case file (cases/*/<case>/reference/, with SOURCE.md). The
recognised files are listed in this module, each with the reader the plots use. The DKT
comparison with Uhlmann (2005) reads a digitisation kept outside the repository
(../shared/reference/digitized/uhlmann_2005, or $FDDEM_UHLMANN_REFERENCE).
"""

import csv
import os

import numpy as np

from . import io

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
SOURCE_ROOT = os.path.dirname(os.path.dirname(PACKAGE_DIR))  # the repository, in-tree


def case_directory(run_dir):
    """The directory of the case file the run started from, or None when it cannot be found
    (a relative source path is tried from the working directory and the repository root)."""
    source = io.read_case_source(run_dir)
    if not source:
        return None
    candidates = [source] if os.path.isabs(source) else [source, os.path.join(SOURCE_ROOT, source)]
    for candidate in candidates:
        if os.path.isfile(candidate):
            return os.path.dirname(os.path.abspath(candidate))
    return None


def _read_table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def ghia(case_dir):
    """Ghia, Ghia & Shin (1982) cavity centrelines: {"u": (y, u), "v": (x, v)} or None."""
    if case_dir is None:
        return None
    u_path = os.path.join(case_dir, "reference", "ghia1982_u_vertical_centerline.csv")
    v_path = os.path.join(case_dir, "reference", "ghia1982_v_horizontal_centerline.csv")
    if not (os.path.exists(u_path) and os.path.exists(v_path)):
        return None
    u = np.loadtxt(u_path, delimiter=",", skiprows=1)
    v = np.loadtxt(v_path, delimiter=",", skiprows=1)
    return {"u": (u[:, 0], u[:, 1]), "v": (v[:, 0], v[:, 1]),
            "label": "Ghia, Ghia & Shin (1982)"}


def schafer_turek(case_dir):
    """Schäfer & Turek (1996) 2D-1 bounds: quantity -> (lower, upper), or None."""
    path = case_dir and os.path.join(case_dir, "reference", "schafer_turek_1996_2d1.csv")
    if not path or not os.path.exists(path):
        return None
    bounds = {r["quantity"]: (float(r["lower"]), float(r["upper"])) for r in _read_table(path)}
    bounds["label"] = "Schäfer & Turek (1996)"
    return bounds


def unbounded_cylinder(case_dir):
    """Published C_D and eddy length L/D of an unbounded cylinder (Re 40): a list of
    (source, C_D or None, L/D or None), or None."""
    path = case_dir and os.path.join(case_dir, "reference", "unbounded_re40.csv")
    if not path or not os.path.exists(path):
        return None

    def number(text):
        return float(text) if text else None

    return [(r["source"], number(r["drag_coefficient"]), number(r["eddy_length_over_diameter"]))
            for r in _read_table(path)]


def uhlmann_directory():
    """The digitised Uhlmann (2005) curves, or None when they are not on this machine."""
    directory = os.environ.get("FDDEM_UHLMANN_REFERENCE") or os.path.join(
        SOURCE_ROOT, "..", "shared", "reference", "digitized", "uhlmann_2005")
    return directory if os.path.isdir(directory) else None


def names_uhlmann(case_dir):
    return case_dir is not None and os.path.basename(case_dir) == "dkt_uhlmann2005"
