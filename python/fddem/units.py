"""Axis labels with the units of a case.

A case is dimensional in any consistent unit system (docs/case-file.md); fddem does not record
which. The labels follow the case: a case derived from [nondimensional] Re and ρr (the paper's
settling cases, D = 1, U_c = 1) is labelled in D and U_c; a gravity of about 981 means CGS
(cm, g, s: the paper's box cases, Uhlmann's DKT); anything else is labelled SI.
"""

import math

SYSTEMS = {
    "SI": {"length": "m", "time": "s", "velocity": "m/s", "angular_velocity": "rad/s",
           "mass": "kg", "force": "N", "torque": "N m", "energy": "J", "pressure": "Pa"},
    "CGS": {"length": "cm", "time": "s", "velocity": "cm/s", "angular_velocity": "rad/s",
            "mass": "g", "force": "dyn", "torque": "dyn cm", "energy": "erg", "pressure": "Ba"},
    "nondimensional": {"length": "D", "time": "D/U_c", "velocity": "U_c",
                       "angular_velocity": "U_c/D", "mass": "ρ_f D²", "force": "ρ_f U_c² D",
                       "torque": "ρ_f U_c² D²", "energy": "ρ_f U_c² D²", "pressure": "ρ_f U_c²"},
}

# Quantities that are per unit depth in a 2D case (docs/output-files.md: 2D forces per depth).
_PER_DEPTH = {"mass", "force", "torque", "energy"}


class Units:
    """Unit strings of one case: `units.label("u", "velocity")` -> "u [m/s]"."""

    def __init__(self, system, dimension):
        self.system = system
        self.dimension = dimension

    def unit(self, kind):
        unit = SYSTEMS[self.system][kind]
        if self.dimension == 2 and kind in _PER_DEPTH and self.system != "nondimensional":
            unit += "/" + SYSTEMS[self.system]["length"]
        return unit

    def label(self, name, kind=None):
        return name if kind is None else f"{name} [{self.unit(kind)}]"


def unit_system(case):
    """"SI", "CGS" or "nondimensional" for a case as run (a dict from case.toml)."""
    nondimensional = case.get("nondimensional", {})
    if "reynolds" in nondimensional or "density_ratio" in nondimensional:
        return "nondimensional"
    gravity = case.get("fluid", {}).get("gravity", [])
    g = math.sqrt(sum(float(c) ** 2 for c in gravity)) if gravity else 0.0
    return "CGS" if 900.0 < g < 1100.0 else "SI"


def case_units(case):
    return Units(unit_system(case), len(case["domain"]["size"]))
