#!/usr/bin/env pvpython
"""Opens a split run's frames in ParaView, as a user would, and compares them with a one-process run.

    pvpython tools/paraview_pieces.py SPLIT_RUN ONE_PROCESS_RUN

For the last field frame (fields/fields_NNNNNN.pvtr, written in pieces, one per rank) and the
last particle frame (particles/particles_NNNNNN.pvtp), ParaView's own readers
(XMLPartitionedRectilinearGridReader, XMLPartitionedPolydataReader) must give one dataset with
the grid's cells and points and the bodies of the one-process frame, every array equal to the
one-process run's to 1e-10 of its largest value (or of 1e-6 of the frame's largest, for an array of
round-off) (cells matched by their centres, bodies by their
ids). Needs ParaView's Python (Debian: `apt-get install paraview`, which is not one of fddem's
dependencies). Exit status 0 if all holds, 1 with the first difference otherwise.
"""

import pathlib
import sys

import numpy as np
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy


def last_frame(run, folder, suffix):
    frames = sorted((run / folder).glob(f"{folder}_*.{suffix}"))
    if not frames:
        sys.exit(f"{run / folder}: no .{suffix} frame")
    return frames[-1]


def fetch(proxy):
    """The dataset ParaView shows for `proxy`: a partitioned reader may hand back its pieces as
    blocks, which the user sees as one dataset, so they are merged."""
    data = servermanager.Fetch(proxy)
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkPartitionedDataSet"):
        data = servermanager.Fetch(simple.MergeBlocks(Input=proxy))
    return data


def arrays(data, where):
    attributes = data.GetCellData() if where == "cell" else data.GetPointData()
    return {attributes.GetArrayName(k): vtk_to_numpy(attributes.GetArray(k))
            for k in range(attributes.GetNumberOfArrays())}


def cell_order(reader):
    """The cells of `reader`'s dataset sorted by their centres (ParaView's CellCenters)."""
    centres = fetch(simple.CellCenters(Input=reader))
    xyz = vtk_to_numpy(centres.GetPoints().GetData())
    return np.lexsort(np.round(xyz, 12).T)


def compare(name, a, b, order_a, order_b):
    if not b:
        sys.exit(f"{name}: the one-process frame has no arrays to compare")
    # An array that is round-off everywhere (a frictionless contact's torque) is measured
    # against the frame's largest value, as tests/mpi/split_run.py measures it.
    floor = 1e-6 * max(np.abs(values).max() for values in b.values())
    for key, values in b.items():
        if key not in a:
            sys.exit(f"{name}: array {key} missing in the split run's frame")
        x = a[key][order_a]
        y = values[order_b]
        if x.shape != y.shape:
            sys.exit(f"{name}: array {key} has shape {x.shape}, one process {y.shape}")
        scale = max(np.abs(y).max(), floor, 1e-300)
        worst = np.abs(x - y).max() / scale
        if worst > 1e-10:
            sys.exit(f"{name}: array {key} differs by {worst:.2e} of its largest value")
    print(f"{name}: {len(b)} arrays equal to 1e-10")


def main():
    split, one = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    pvtr = last_frame(split, "fields", "pvtr")
    vtr = one / "fields" / (pvtr.stem + ".vtr")
    split_reader = simple.XMLPartitionedRectilinearGridReader(FileName=[str(pvtr)])
    one_reader = simple.XMLRectilinearGridReader(FileName=[str(vtr)])
    grid, whole = fetch(split_reader), fetch(one_reader)
    print(f"{pvtr.name}: ParaView reads {grid.GetClassName()} with {grid.GetNumberOfCells()} cells "
          f"and {grid.GetNumberOfPoints()} points; the one-process frame has "
          f"{whole.GetNumberOfCells()} and {whole.GetNumberOfPoints()}")
    if grid.GetNumberOfCells() != whole.GetNumberOfCells():
        sys.exit("the split frame does not have the grid's cells")
    order_a, order_b = cell_order(split_reader), cell_order(one_reader)
    compare(pvtr.name, arrays(grid, "cell"), arrays(whole, "cell"), order_a, order_b)

    pvtp = last_frame(split, "particles", "pvtp")
    vtp = one / "particles" / (pvtp.stem + ".vtp")
    bodies = fetch(simple.XMLPartitionedPolydataReader(FileName=[str(pvtp)]))
    alone = fetch(simple.XMLPolyDataReader(FileName=[str(vtp)]))
    a, b = arrays(bodies, "point"), arrays(alone, "point")
    print(f"{pvtp.name}: ParaView reads {bodies.GetNumberOfPoints()} bodies; the one-process "
          f"frame has {alone.GetNumberOfPoints()}")
    if bodies.GetNumberOfPoints() != alone.GetNumberOfPoints():
        sys.exit("the split frame does not have every body once")
    compare(pvtp.name, a, b, np.argsort(a["id"]), np.argsort(b["id"]))


if __name__ == "__main__":
    main()
