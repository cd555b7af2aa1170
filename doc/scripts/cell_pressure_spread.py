#!/usr/bin/env python3
"""Lowest and highest point pressure in each cell below the Mohr-Coulomb footing.

Usage: cell_pressure_spread.py OUTPUT_DIR STEP

Reads points_<STEP>.pvtu of a run of prm/strip_footing_mohr_coulomb.prm at
h = 0.125 m written with 'Output/Fields = stress, body, initial_position',
groups the layer's points (the lowest body index) by the cell of their
initial position and prints, for the four rows of cells below the footing
(y from 1.5 to 2 m) and the first ten columns (x from 0 to 1.25 m), the
lowest and highest -(sigma_xx + sigma_yy) / 2 in kPa, then the largest
spread within a cell (doc/benchmarks/soils.md, "Cell pressures").
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

CELL = 0.125


def read(directory, step):
    """The point data of every piece of points_<step>.pvtu."""
    pvtu = os.path.join(directory, "points_%05d.pvtu" % step)
    data = {}
    for piece in ET.parse(pvtu).getroot().iter("Piece"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(directory, piece.get("Source")))
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfPoints() == 0:
            continue
        point_data = grid.GetPointData()
        for i in range(point_data.GetNumberOfArrays()):
            data.setdefault(point_data.GetArrayName(i), []).append(
                vtk_to_numpy(point_data.GetArray(i)))
    return {name: np.concatenate(arrays) for name, arrays in data.items()}


def main():
    data = read(sys.argv[1], int(sys.argv[2]))
    layer = data["body"] == data["body"].min()
    positions = data["initial_position"][layer]
    pressure = -(data["stress_xx"][layer] + data["stress_yy"][layer]) / 2e3
    cells = {}
    for position, value in zip(positions, pressure):
        key = (int(position[1] / CELL), int(position[0] / CELL))
        cells.setdefault(key, []).append(value)
    spreads = []
    for row in range(15, 11, -1):
        line = []
        for column in range(10):
            values = cells[(row, column)]
            line.append("%3.0f-%3.0f" % (min(values), max(values)))
            spreads.append(max(values) - min(values))
        print("y=%.3f " % (row * CELL) + " ".join(line))
    print("largest spread within a cell (kPa): %.1f" % max(spreads))


if __name__ == "__main__":
    main()
