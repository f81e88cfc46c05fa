"""Planes through a field frame, and the bodies those planes cut: one code for 2D and 3D.

A field frame (io.read_vtr) holds cell arrays shaped (nz, ny, nx[, components]), nz = 1 in 2D.
`plane_slice(frame, normal_axis, position)` returns the cell values on the plane normal to
axis `normal_axis` (0 x, 1 y, 2 z) at `position`, linearly interpolated between the two
nearest cell layers; a 2D frame is its own z plane. The in-plane axes (a, b) are the other two
in increasing order, and every returned 2D array is indexed [b, a] (rows b, columns a), ready
for imshow(origin="lower") and streamplot.
"""

import numpy as np

AXIS_NAMES = "xyz"


def cell_centres(nodes):
    """Cell-centre coordinates from node coordinates (a single node: that coordinate)."""
    nodes = np.asarray(nodes, float)
    return 0.5 * (nodes[1:] + nodes[:-1]) if len(nodes) > 1 else nodes.copy()


def in_plane_axes(normal_axis):
    return tuple(k for k in range(3) if k != normal_axis)


def plane_slice(frame, normal_axis=2, position=None):
    """The frame on a plane: dict with "axes" (a, b), "position", "a", "b" (cell-centre
    coordinates), "ua", "ub" (in-plane velocity), "un" (normal velocity), "speed" (|u|, all
    components), "p", and "vorticity" (2D: the scalar; 3D: the component along the normal)."""
    nodes = [frame["x"], frame["y"], frame["z"]]
    centres = [cell_centres(n) for n in nodes]
    array_axis = 2 - normal_axis  # arrays are (z, y, x)
    n_layers = frame["velocity"].shape[array_axis]
    along = centres[normal_axis]
    if position is None:
        position = 0.5 * (nodes[normal_axis][0] + nodes[normal_axis][-1])
    if n_layers == 1:
        lower, weight = 0, 0.0
    else:
        lower = int(np.clip(np.searchsorted(along, position) - 1, 0, n_layers - 2))
        weight = float(np.clip((position - along[lower]) / (along[lower + 1] - along[lower]), 0, 1))

    def cut(array):
        first = np.take(array, lower, axis=array_axis)
        if weight == 0.0:
            return first
        return (1.0 - weight) * first + weight * np.take(array, lower + 1, axis=array_axis)

    a, b = in_plane_axes(normal_axis)
    velocity = cut(frame["velocity"])
    result = {
        "axes": (a, b),
        "normal_axis": normal_axis,
        "position": float(position),
        "a": centres[a],
        "b": centres[b],
        "extent": [nodes[a][0], nodes[a][-1], nodes[b][0], nodes[b][-1]],
        "ua": velocity[..., a],
        "ub": velocity[..., b],
        "un": velocity[..., normal_axis],
        "speed": np.linalg.norm(velocity, axis=-1),
    }
    if "p" in frame:
        result["p"] = cut(frame["p"])
    if "vorticity" in frame:
        vorticity = cut(frame["vorticity"])
        result["vorticity"] = vorticity if vorticity.ndim == 2 else vorticity[..., normal_axis]
    return result


def bodies_cut_by_plane(centres, radii, normal_axis=2, position=0.0):
    """The circles in which a plane cuts spheres (or, in 2D, the disks themselves): a list of
    (body index, a, b, radius of the cut) for every body the plane meets. `centres` is (n, 3)
    (z = 0 in 2D, where every disk is cut at its full radius by the plane z = 0)."""
    centres = np.asarray(centres, float).reshape(-1, 3)
    a, b = in_plane_axes(normal_axis)
    cuts = []
    for k, (centre, radius) in enumerate(zip(centres, np.asarray(radii, float))):
        distance = centre[normal_axis] - position
        if abs(distance) < radius:
            cuts.append((k, centre[a], centre[b], float(np.sqrt(radius**2 - distance**2))))
    return cuts


def line_profile(plane, along_axis, at=None):
    """Values along the line of a plane slice through `at` (default: the plane's middle),
    parallel to in-plane axis `along_axis`: (coordinates, ua, ub) interpolated linearly across
    the line between the two nearest cell rows or columns."""
    a, b = plane["axes"]
    if along_axis == a:
        across, values_axis = plane["b"], 0  # a line of constant b: interpolate over rows
        extent = plane["extent"][2:]
        coordinates = plane["a"]
    elif along_axis == b:
        across, values_axis = plane["a"], 1
        extent = plane["extent"][:2]
        coordinates = plane["b"]
    else:
        raise ValueError(f"axis {along_axis} is not in the plane")
    if at is None:
        at = 0.5 * (extent[0] + extent[1])
    lower = int(np.clip(np.searchsorted(across, at) - 1, 0, len(across) - 2))
    weight = float(np.clip((at - across[lower]) / (across[lower + 1] - across[lower]), 0, 1))

    def take(array):
        return ((1 - weight) * np.take(array, lower, axis=values_axis)
                + weight * np.take(array, lower + 1, axis=values_axis))

    return coordinates, take(plane["ua"]), take(plane["ub"])
