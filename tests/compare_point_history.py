#!/usr/bin/env python3
"""Compare point_history.csv with the point files of the same steps.

Usage: compare_point_history.py OUTPUT_DIRECTORY

For each row of point_history.csv, the point with the row's id in the point
file of the row's step (points.pvd's entries, in order: step 0 is the
first) must hold the same position, displacement, stresses and fields (the
point files store fields in single precision: compared to 1e-6 of each
column's largest magnitude). Prints one line per checked column and exits
non-zero on a difference."""
import csv
import re
import sys
import xml.etree.ElementTree as ElementTree

import vtk
from vtk.util.numpy_support import vtk_to_numpy

directory = sys.argv[1]
rows = list(csv.DictReader(open(directory + "/point_history.csv")))
series = ElementTree.parse(directory + "/points.pvd").getroot()
files = [d.get("file") for d in series.iter("DataSet")]
by_step = {}
for index, name in enumerate(files):
    reader = vtk.vtkXMLPUnstructuredGridReader() if name.endswith(".pvtu") \
        else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(directory + "/" + name)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    # The point files' ids are not stored: the points are matched by their
    # initial position, which the history's position minus displacement is.
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    arrays["points"] = vtk_to_numpy(grid.GetPoints().GetData())
    by_step[index] = arrays
dim = 3 if "z" in rows[0] else 2
axes = "xyz"[:dim]
largest = {}
failed = False
checked = set()
for row in rows:
    arrays = by_step[int(row["step"])]
    initial = [float(row[a]) - float(row["displacement_" + a]) for a in axes]
    found = arrays["initial_position"]
    distances = sum((found[:, d] - initial[d]) ** 2 for d in range(dim))
    p = int(distances.argmin())
    if distances[p] > 1e-10:
        print("step %s point %s: no point at its initial position" %
              (row["step"], row["point"]))
        failed = True
        continue
    pairs = [(a, float(row[a]), arrays["points"][p][d])
             for d, a in enumerate(axes)]
    pairs += [("displacement_" + a, float(row["displacement_" + a]),
               arrays["displacement"][p][d]) for d, a in enumerate(axes)]
    for name in row:
        if name in arrays and arrays[name].ndim == 1:
            pairs.append((name, float(row[name]), float(arrays[name][p])))
    for name, history, point_file in pairs:
        scale = max(largest.get(name, 0.), abs(history), 1e-30)
        largest[name] = scale
        checked.add(name)
        if abs(history - point_file) > 1e-6 * scale + 1e-12:
            print("step %s point %s %s: history %.9g, point file %.9g" %
                  (row["step"], row["point"], name, history, point_file))
            failed = True
print("compared %d rows, columns: %s" % (len(rows), " ".join(sorted(checked))))
sys.exit(1 if failed else 0)
