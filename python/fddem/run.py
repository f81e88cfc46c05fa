"""One run directory as an object: the case, the summary and the outputs, read on demand."""

import math
import os

import numpy as np

from . import io
from .units import case_units


def expand_bodies(case, dimension):
    """One dict per body, in the order of the case, with its "id": as fddem numbers them
    (io/body_entries.hpp). An entry with `file` gives one body per row of the file (the case
    as run names it by its absolute path), with that row's id, position, diameter and
    density; a random insertion gives `count` bodies (or its volume fraction's worth) of its
    diameter without positions; every other entry one body. Entries without a file number
    their bodies on from the largest id before them."""
    bodies = []
    next_id = 0
    for entry in case.get("bodies", []):
        if "file" in entry:
            for row in io.read_body_file(entry["file"]):
                body = {k: v for k, v in entry.items() if k != "file"}
                body.update(row)
                bodies.append(body)
                next_id = max(next_id, row["id"] + 1)
            continue
        count = 1
        if "count" in entry or "volume_fraction" in entry:
            count = entry.get("count") or _random_count(case, entry, dimension)
        for _ in range(count):
            bodies.append(dict(entry, id=next_id))
            next_id += 1
    return bodies


def _random_count(case, entry, dimension):
    """The bodies of a random insertion by volume fraction: the fraction of the region, in
    whole bodies (io/body_entries.cpp's rounding)."""
    origin = case["domain"].get("origin", [0.0] * dimension)
    low = entry.get("region_low", origin)
    high = entry.get("region_high", [o + s for o, s in zip(origin, case["domain"]["size"])])
    region = math.prod(h - lo for lo, h in zip(low, high))
    r = 0.5 * float(entry["diameter"])
    body = math.pi * r * r if dimension == 2 else 4.0 / 3.0 * math.pi * r**3
    return max(1, int(math.floor(entry["volume_fraction"] * region / body + 0.5)))


class Run:
    """An fddem run directory.

    >>> run = Run("runs/fig09_eighteen_disks")
    >>> run.dimension, len(run.bodies), run.frame_times[-1]
    """

    def __init__(self, path):
        io.check_run_directory(path)
        self.path = path
        self.case = io.read_case(path)
        self.summary = io.read_summary(path)
        self.title = self.case.get("case", {}).get("title") or os.path.basename(
            os.path.normpath(path))
        self.dimension = len(self.case["domain"]["size"])
        self.origin = np.array(self.case["domain"].get("origin", [0.0] * self.dimension), float)
        self.size = np.array(self.case["domain"]["size"], float)
        self.bodies = expand_bodies(self.case, self.dimension)
        self._body_by_id = {b["id"]: b for b in self.bodies}
        self.units = case_units(self.case)
        self._frames = io.read_pvd(path)
        self._body_frames = io.read_pvd(path, "particles.pvd")

    # --- tables -------------------------------------------------------------------------
    def solver(self, as_frame=None):
        """solver.csv: numpy arrays by column, or a DataFrame (default when pandas exists)."""
        return io.read_solver(self.path, as_frame)

    def particles(self, as_frame=None):
        """particles.csv, one row per body per output time (DataFrame when pandas exists)."""
        return io.read_particle_rows(self.path, as_frame)

    def body_histories(self):
        """Body id -> dict of column arrays in time order (numpy)."""
        if not self.has_particle_history:
            return {}
        return io.read_particles(self.path)

    def samples(self, as_frame=None):
        """The line samples: name -> columns (DataFrame when pandas exists)."""
        return io.read_samples(self.path, as_frame)

    # --- fields -------------------------------------------------------------------------
    @property
    def frame_times(self):
        return np.array([t for t, _ in self._frames])

    def field(self, index=-1):
        """Field frame `index` (negative: from the end) as io.read_vtr returns it, plus "time"."""
        time, path = self._frames[index]
        frame = io.read_vtr(path)
        frame["time"] = time
        return frame

    def bodies_at_frame(self, index=-1):
        """The bodies at field frame `index` (particles/*.vtp): centre (n, 3), radius (n), …;
        None without bodies."""
        if not self._body_frames:
            return None
        return io.read_vtp(self._body_frames[index][1])

    # --- what the run holds -------------------------------------------------------------
    @property
    def has_particle_history(self):
        return os.path.exists(os.path.join(self.path, "particles.csv"))

    @property
    def has_bodies(self):
        return len(self.bodies) > 0 and self.has_particle_history

    @property
    def has_free_bodies(self):
        return any(b.get("motion", "free") != "fixed" for b in self.bodies)

    @property
    def is_steady(self):
        """A pseudo-time march to a steady state (time.steady): its times are not physical."""
        return bool(self.case.get("time", {}).get("steady", False))

    @property
    def has_contacts(self):
        return self.has_bodies and self.case.get("contact", {}).get("model", "linear") != "none"

    def body(self, body_id):
        """The keys of the body of `body_id`: its [[bodies]] entry's, and its file row's."""
        return self._body_by_id[body_id]

    def body_radius(self, body_id):
        return 0.5 * float(self.body(body_id)["diameter"])

    def body_density(self, body_id):
        body = self.body(body_id)
        if "density" in body:
            return float(body["density"])
        return float(self.case.get("derived", {})["body_density"])

    def body_mass_and_inertia(self, body_id):
        """Mass and moment of inertia (per unit depth in 2D: a disk; a sphere in 3D)."""
        r = self.body_radius(body_id)
        rho = self.body_density(body_id)
        if self.dimension == 2:
            mass = rho * math.pi * r * r
            return mass, 0.5 * mass * r * r
        mass = rho * 4.0 / 3.0 * math.pi * r**3
        return mass, 0.4 * mass * r * r

    def mean_inflow_speed(self):
        """Mean speed over an inflow side (parabolic: 2/3 of the maximum per walled transverse
        axis), or None without an inflow."""
        sides = self.case.get("boundaries", {})
        if "inflow" not in sides.values():
            return None
        inflow = self.case.get("inflow", {})
        speed = float(inflow["velocity"])
        if inflow.get("profile", "uniform") == "parabolic":
            speed *= (2.0 / 3.0) ** (self.dimension - 1)
        return speed
