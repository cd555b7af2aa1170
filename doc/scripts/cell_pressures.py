#!/usr/bin/env python3
"""Cell means of the points' pressure, row by row, for a 2D run.

Usage: cell_pressures.py OUTPUT_DIR STEP CELL_SIZE BODY [ROWS] [COLUMNS]
           [--volume INITIAL_POINT_VOLUME]

Reads points_<STEP>.pvtu of OUTPUT_DIR (written with 'Output/Fields'
holding stress and body), groups the points of body BODY (1 for 'Body 1')
by the grid cell that holds their current position (cells of size
CELL_SIZE from the origin) and prints, for the ROWS highest rows of cells
(default 4) and the first COLUMNS columns (default 8), the mean of
p = -(sigma_xx + sigma_yy + sigma_zz) / 3 in kPa. A pressure that
alternates from cell to cell along a row is the checkerboard mode of
constant-per-cell volume averaging (doc/benchmarks/notes.md, "The
Mohr-Coulomb footing with plain F-bar").
With --volume (and the field volume written), prints instead the mean
volume change J - 1 of the points in each cell, in per mille, J being a
point's volume over INITIAL_POINT_VOLUME (the same for every point of a
body seeded on a regular lattice: (h / points per cell direction)^2).
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_points(directory, step):
    """Positions and point data of every piece of points_<step>.pvtu."""
    pvtu = os.path.join(directory, "points_%05d.pvtu" % step)
    data = {}
    for piece in ET.parse(pvtu).getroot().iter("Piece"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(directory, piece.get("Source")))
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfPoints() == 0:
            continue
        data.setdefault("x", []).append(vtk_to_numpy(grid.GetPoints().GetData()))
        point_data = grid.GetPointData()
        for i in range(point_data.GetNumberOfArrays()):
            data.setdefault(point_data.GetArrayName(i), []).append(
                vtk_to_numpy(point_data.GetArray(i)))
    return {name: np.concatenate(chunks) for name, chunks in data.items()}


def main():
    arguments = sys.argv[1:]
    initial_volume = None
    if "--volume" in arguments:
        at = arguments.index("--volume")
        if at + 1 >= len(arguments):
            sys.exit(__doc__)
        initial_volume = float(arguments[at + 1])
        del arguments[at:at + 2]
    if len(arguments) < 4:
        sys.exit(__doc__)
    directory, step = arguments[0], int(arguments[1])
    cell_size, body = float(arguments[2]), int(arguments[3])
    n_rows = int(arguments[4]) if len(arguments) > 4 else 4
    n_columns = int(arguments[5]) if len(arguments) > 5 else 8
    points = read_points(directory, step)
    needed = ("volume", "body") if initial_volume else (
        "stress_xx", "stress_yy", "stress_zz", "body")
    for name in needed:
        if name not in points:
            sys.exit("cell_pressures.py: %s has no field '%s' (write it with "
                     "'Output/Fields')" % (directory, name))
    mine = points["body"] == body
    if initial_volume:
        # The printed quantity: J - 1 in per mille.
        pressure = (points["volume"][mine] / initial_volume - 1.0) * 1000.0
    else:
        pressure = -(points["stress_xx"] + points["stress_yy"] +
                     points["stress_zz"])[mine] / 3.0 / 1000.0
    number = "%6.2f" if initial_volume else "%6.0f"
    cells = np.floor(points["x"][mine, :2] / cell_size).astype(int)
    top = cells[:, 1].max()
    for row in range(top, top - n_rows, -1):
        means = []
        for column in range(n_columns):
            here = (cells[:, 0] == column) & (cells[:, 1] == row)
            means.append((number % pressure[here].mean()) if here.any() else
                         "     -")
        print("y = %-7g" % (row * cell_size), " ".join(means))


if __name__ == "__main__":
    main()
