"""Small run directories written in fddem's output formats (docs/output-files.md), so that the
Python package can be tested without running the solver: 2D or 3D, with or without bodies, with
fields the tests know exactly."""

import json
import os
import struct

import numpy as np


def _appended(arrays):
    """VTK appended raw data: each array a UInt64 byte count and its values; the offsets."""
    blob, offsets = b"", []
    for values in arrays:
        offsets.append(len(blob))
        data = np.ascontiguousarray(values).tobytes()
        blob += struct.pack("<Q", len(data)) + data
    return blob, offsets


def write_vtr(path, x, y, z, cell_arrays):
    """cell_arrays: name -> array shaped (nz, ny, nx[, 3])."""
    names = list(cell_arrays)
    blob, offsets = _appended([cell_arrays[n].astype("<f8").ravel() for n in names]
                              + [np.asarray(c, "<f8") for c in (x, y, z)])
    nx, ny, nz = len(x) - 1, len(y) - 1, max(len(z) - 1, 0)
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="RectilinearGrid" version="1.0" byte_order="LittleEndian" '
             'header_type="UInt64">',
             f'  <RectilinearGrid WholeExtent="0 {nx} 0 {ny} 0 {nz}">',
             f'    <Piece Extent="0 {nx} 0 {ny} 0 {nz}">', "      <CellData>"]
    for name, offset in zip(names, offsets):
        components = ' NumberOfComponents="3"' if cell_arrays[name].ndim == 4 else ""
        lines.append(f'        <DataArray type="Float64" Name="{name}"{components} '
                     f'format="appended" offset="{offset}"/>')
    lines.append("      </CellData>\n      <Coordinates>")
    for axis, offset in zip("xyz", offsets[len(names):]):
        lines.append(f'        <DataArray type="Float64" Name="{axis}" format="appended" '
                     f'offset="{offset}"/>')
    lines += ["      </Coordinates>", "    </Piece>", "  </RectilinearGrid>",
              '  <AppendedData encoding="raw">', "   _"]
    with open(path, "wb") as f:
        f.write("\n".join(lines).encode() + blob + b"\n  </AppendedData>\n</VTKFile>\n")


def write_vtp(path, centres, radii, velocities, ids=None):
    """Bodies at `centres`; with `ids`, an "id" array as well (fddem writes one)."""
    n = len(radii)
    blob, offsets = _appended([np.asarray(centres, "<f8").ravel(), np.asarray(radii, "<f8"),
                               np.asarray(velocities, "<f8").ravel(), np.zeros(3 * n),
                               np.arange(n, dtype="<i8"), np.arange(1, n + 1, dtype="<i8"),
                               np.asarray(ids if ids is not None else [], "<f8")])
    id_array = (f'        <DataArray type="Float64" Name="id" format="appended" '
                f'offset="{offsets[6]}"/>\n' if ids is not None else "")
    text = f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <PolyData>
    <Piece NumberOfPoints="{n}" NumberOfVerts="{n}" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0">
      <PointData Scalars="radius" Vectors="velocity">
{id_array}        <DataArray type="Float64" Name="radius" format="appended" offset="{offsets[1]}"/>
        <DataArray type="Float64" Name="velocity" NumberOfComponents="3" format="appended" offset="{offsets[2]}"/>
        <DataArray type="Float64" Name="angular_velocity" NumberOfComponents="3" format="appended" offset="{offsets[3]}"/>
      </PointData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="appended" offset="{offsets[0]}"/>
      </Points>
      <Verts>
        <DataArray type="Int64" Name="connectivity" format="appended" offset="{offsets[4]}"/>
        <DataArray type="Int64" Name="offsets" format="appended" offset="{offsets[5]}"/>
      </Verts>
    </Piece>
  </PolyData>
  <AppendedData encoding="raw">
   _"""
    with open(path, "wb") as f:
        f.write(text.encode() + blob + b"\n  </AppendedData>\n</VTKFile>\n")


def write_split_frame(folder, stem, nodes, cell_arrays, cuts):
    """A field frame in pieces as a split run writes it (docs/output-files.md): folder/stem.pvtr
    listing folder/stem/stem_RRRR.vtr. `cuts` gives per axis the cell indices where the blocks
    meet ([] for an axis not split); the pieces are the blocks, x fastest."""
    n_cells = [max(len(c) - 1, 1) for c in nodes]
    bounds = [[0] + list(cuts[d]) + [n_cells[d]] for d in range(3)]
    os.makedirs(os.path.join(folder, stem), exist_ok=True)
    pieces = []
    for k in range(len(bounds[2]) - 1):
        for j in range(len(bounds[1]) - 1):
            for i in range(len(bounds[0]) - 1):
                lo = [bounds[0][i], bounds[1][j], bounds[2][k]]
                hi = [bounds[0][i + 1], bounds[1][j + 1], bounds[2][k + 1]]
                if len(nodes[2]) == 1:  # 2D: one node along z, extent 0 0
                    hi[2] = 0
                cells = (slice(lo[2], max(hi[2], 1)), slice(lo[1], hi[1]), slice(lo[0], hi[0]))
                source = f"{stem}/{stem}_{len(pieces):04d}.vtr"
                write_vtr(os.path.join(folder, source),
                          *[nodes[d][lo[d]:hi[d] + 1] for d in range(3)],
                          {name: values[cells] for name, values in cell_arrays.items()})
                extent = " ".join(f"{lo[d]} {hi[d]}" for d in range(3))
                pieces.append(f'    <Piece Extent="{extent}" Source="{source}"/>')
    write_pvtr(os.path.join(folder, stem + ".pvtr"), nodes, cell_arrays, pieces)


def write_pvtr(path, nodes, cell_arrays, pieces):
    """The master of a field frame in `pieces` (their <Piece> lines)."""
    whole = " ".join(f"0 {len(c) - 1}" for c in nodes)
    arrays = "".join(
        f'      <PDataArray type="Float64" Name="{name}"'
        + (' NumberOfComponents="3"' if values.ndim == 4 else "") + "/>\n"
        for name, values in cell_arrays.items())
    coordinates = "".join(f'      <PDataArray type="Float64" Name="{a}"/>\n' for a in "xyz")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PRectilinearGrid" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n'
                f'  <PRectilinearGrid WholeExtent="{whole}" GhostLevel="0">\n'
                f"    <PCellData>\n{arrays}    </PCellData>\n"
                f"    <PCoordinates>\n{coordinates}    </PCoordinates>\n"
                + "\n".join(pieces) + "\n  </PRectilinearGrid>\n</VTKFile>\n")


def write_split_bodies(folder, stem, pieces):
    """A particle frame in pieces: folder/stem.pvtp listing folder/stem/stem_RRRR.vtp, one per
    entry of `pieces` (each a dict of "id", "centre", "radius", "velocity" lists)."""
    os.makedirs(os.path.join(folder, stem), exist_ok=True)
    lines = []
    for rank, piece in enumerate(pieces):
        source = f"{stem}/{stem}_{rank:04d}.vtp"
        write_vtp(os.path.join(folder, source), piece["centre"], piece["radius"],
                  piece["velocity"], piece["id"])
        lines.append(f'    <Piece Source="{source}"/>')
    arrays = "".join(
        f'      <PDataArray type="Float64" Name="{name}"{components}/>\n'
        for name, components in (("id", ""), ("radius", ""),
                                 ("velocity", ' NumberOfComponents="3"'),
                                 ("angular_velocity", ' NumberOfComponents="3"')))
    with open(os.path.join(folder, stem + ".pvtp"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n'
                '  <PPolyData GhostLevel="0">\n'
                f"    <PPointData>\n{arrays}    </PPointData>\n"
                '    <PPoints>\n      <PDataArray type="Float64" NumberOfComponents="3"/>\n'
                "    </PPoints>\n" + "\n".join(lines) + "\n  </PPolyData>\n</VTKFile>\n")


def write_pvd(path, entries):
    rows = "".join(f'    <DataSet timestep="{t}" part="0" file="{f}"/>\n' for t, f in entries)
    with open(path, "w") as f:
        f.write(f'<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n'
                f"  <Collection>\n{rows}  </Collection>\n</VTKFile>\n")


def velocity_field(x, y, z, time):
    """A known cell-centred field: u = time · (y, −x + 2 z, x) (in 2D z = 0, w = 0)."""
    xc = 0.5 * (x[1:] + x[:-1])
    yc = 0.5 * (y[1:] + y[:-1])
    zc = 0.5 * (z[1:] + z[:-1]) if len(z) > 1 else np.zeros(1)
    Z, Y, X = np.meshgrid(zc, yc, xc, indexing="ij")
    w = X if len(z) > 1 else np.zeros_like(X)
    return time * np.stack([Y, -X + 2 * Z, w], axis=-1)


def make_run(directory, dimension=2, n_bodies=2, n_frames=3, cells=16):
    """A run directory: a box [0,1]^dim (cells per side), bodies of radius 0.1 moving down."""
    os.makedirs(os.path.join(directory, "fields"), exist_ok=True)
    size = [1.0] * dimension
    gravity = [0.0] * dimension
    gravity[-1 if dimension == 3 else 1] = -9.81
    bodies = [{"shape": "disk" if dimension == 2 else "sphere", "diameter": 0.2,
               "density": 2.0, "position": [0.25 + 0.5 * k] + [0.7] * (dimension - 1),
               "motion": "free"} for k in range(n_bodies)]
    case = ["# The case as run by fddem: defaults filled in and --set overrides applied.",
            "# Source: synthetic.toml", "", "[case]", "title = 'synthetic run'", "",
            "[domain]", f"size = {size}", f"cells = {[cells] * dimension}", "",
            "[fluid]", "density = 1.0", "viscosity = 0.01", f"gravity = {gravity}", "",
            "[time]", "dt = 0.1", "", "[simple]", "tolerance = 1e-05", "",
            "[contact]", "model = 'linear'"]
    for body in bodies:
        case += ["", "[[bodies]]"] + [f"{k} = {json.dumps(v)}" for k, v in body.items()]
    with open(os.path.join(directory, "case.toml"), "w") as f:
        f.write("\n".join(case) + "\n")
    times = [0.1 * k for k in range(n_frames)]
    with open(os.path.join(directory, "solver.csv"), "w") as f:
        f.write("step,time,dt,outer_iterations,total_outer_iterations,is_converged,"
                "mass_residual,momentum_residual,courant,rate_of_change,retries,wall_seconds\n")
        for step in range(1, 11):
            f.write(f"{step},{0.02 * step},0.02,5,{5 * step},1,1e-6,2e-6,0.3,0.1,0,{0.01 * step}\n")
    nodes = [np.linspace(0, 1, cells + 1)] * 2 + (
        [np.linspace(0, 1, cells + 1)] if dimension == 3 else [np.zeros(1)])
    vector_names = ("x", "y", "z")[:dimension]
    velocity_names = ("u", "v", "w")[:dimension]
    field_entries, body_entries, rows = [], [], []
    for k, t in enumerate(times):
        velocity = velocity_field(*nodes, t)
        arrays = {"velocity": velocity, "p": velocity[..., 0].copy(),
                  "vorticity": velocity if dimension == 3 else velocity[..., 0].copy()}
        name = f"fields/fields_{k:06d}.vtr"
        write_vtr(os.path.join(directory, name), *nodes, arrays)
        field_entries.append((t, name))
        centres = []
        for b, body in enumerate(bodies):
            centre = list(body["position"]) + [0.0] * (3 - dimension)
            centre[1 if dimension == 2 else 2] -= t  # falls at speed 1
            centres.append(centre)
            contact = 1.0 if (b == 0 and k == n_frames - 1) else 0.0
            rows.append([t, b] + centre[:dimension] + [0.0] * (dimension - 1) + [-1.0]
                        + ([0.0, 0.0] if dimension == 2 else [0.0] * 3)
                        + [0.0] * dimension + ([0.0] if dimension == 2 else [0.0] * 3)
                        + [0.0] * (dimension - 1) + [contact]
                        + ([0.0] if dimension == 2 else []))
        if bodies:
            os.makedirs(os.path.join(directory, "particles"), exist_ok=True)
            name = f"particles/particles_{k:06d}.vtp"
            write_vtp(os.path.join(directory, name), centres, [0.1] * len(bodies),
                      [[0.0, -1.0, 0.0]] * len(bodies))
            body_entries.append((t, name))
    write_pvd(os.path.join(directory, "fields.pvd"), field_entries)
    if bodies:
        write_pvd(os.path.join(directory, "particles.pvd"), body_entries)
        if dimension == 2:
            header = ["time", "id", "x", "y", "u", "v", "omega", "theta", "fx", "fy", "torque",
                      "contact_fx", "contact_fy", "contact_torque"]
        else:
            header = ["time", "id", "x", "y", "z", "u", "v", "w", "omega_x", "omega_y",
                      "omega_z", "fx", "fy", "fz", "torque_x", "torque_y", "torque_z",
                      "contact_fx", "contact_fy", "contact_fz"]
        with open(os.path.join(directory, "particles.csv"), "w") as f:
            f.write(",".join(header) + "\n")
            for row in rows:
                assert len(row) == len(header), (len(row), len(header))
                f.write(",".join(f"{v:g}" for v in row) + "\n")
    summary = {"status": "completed", "steps": 10, "time": times[-1],
               "wall_seconds_stepping": 0.1,
               "wall_seconds_by_phase": {"momentum": 0.02, "pressure": 0.05, "coupling": 0.01,
                                         "contact": 0.01, "other": 0.01},
               "max_relative_overlap": 0.001, "max_overlap_time": times[-1]}
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump(summary, f)
    return directory
