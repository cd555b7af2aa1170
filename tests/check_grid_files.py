"""Check the grid files (Output/Grid fields) of a run with VTK, against
numbers given on the command line (computed by hand in grid_files.sh) and
the run's point files; used by tests/grid_files.sh.

  check_grid_files.py DIR --mass M [--weight W] [options]
      every grid file of DIR/grid.pvd: the series at the load factors of
      the converged steps of steps.csv (or only those given by --steps);
      every node written carries mass and their sum (each node once) is M;
      with W, the external force sums to -lambda W and the vertical
      reaction to +lambda W (lambda: the step's load factor; the loads ramp
      with it); the reaction is zero off the rollers' nodes (--held:
      x=0,y=0 by default: the x component on x = 0, the y component on
      y = 0) and the displacement increment is zero on them; internal =
      external force on the other DoFs (equilibrium; not with --explicit:
      an explicit step's internal force holds no inertial force); each cell
      is written once, fewer cells than the grid's (--grid-cells N, if
      given), every cell holding a point at the step's start (the point
      file of the step before, where there is one) is written and every
      written cell shares a node with such a cell; with --momentum P (the
      points' mass, equal for all), the grid's momentum sum_I M_I v_I
      equals sum_p P v_p of the point file of the same step; without it,
      no velocity field. --dim 3: a 3D run (z the vertical axis).
  check_grid_files.py --compare DIR1 DIR2
      the two runs' grid files (one and two processes) hold the same nodes
      with the same values.
Data are single precision (deal.II 9.4's VTU writer): sums are compared to
1e-5 of their scale.
"""
import argparse
import csv
import itertools
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

problems = []


def check(condition, message):
    if not condition:
        problems.append(message)


def unstructured(file_name):
    """The (parallel) VTU file's unstructured grid."""
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(file_name)
    reader.Update()
    return reader.GetOutput()


def read(file_name):
    """Nodes (each once: positions, field arrays) and cells (as lists of
    node indices) of a .pvtu file of grid fields."""
    grid = unstructured(file_name)
    positions = vtk_to_numpy(grid.GetPoints().GetData())[:, :DIM].astype(float)
    keys = np.round(positions * 1e4).astype(np.int64)
    unique, first, inverse = np.unique(keys, axis=0, return_index=True,
                                       return_inverse=True)
    data = grid.GetPointData()
    fields = {}
    for i in range(data.GetNumberOfArrays()):
        array = data.GetArray(i)
        fields[array.GetName()] = vtk_to_numpy(array).astype(float)[first]
    cells = [[inverse.ravel()[grid.GetCell(c).GetPointId(k)]
              for k in range(grid.GetCell(c).GetNumberOfPoints())]
             for c in range(grid.GetNumberOfCells())]
    return positions[first], fields, cells


def series(directory):
    root = ET.parse(os.path.join(directory, "grid.pvd")).getroot()
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def read_points(file_name):
    """Positions and fields of a point file (.pvtu)."""
    grid = unstructured(file_name)
    data = grid.GetPointData()
    fields = {data.GetArray(i).GetName(): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    return vtk_to_numpy(grid.GetPoints().GetData())[:, :DIM], fields


def check_run(args):
    directory = args.directory
    steps = [s for s in csv.DictReader(open(os.path.join(directory, "steps.csv")))
             if s["converged"] == "1"]
    wanted = ([int(s) for s in args.steps.split(",")] if args.steps
              else list(range(1, len(steps) + 1)))
    entries = series(directory)
    expected = [(float(steps[n - 1]["load_factor"]), "grid_%05d.pvtu" % n)
                for n in wanted]
    check(len(entries) == len(expected) and
          all(abs(a[0] - b[0]) < 1e-12 and a[1] == b[1]
              for a, b in zip(entries, expected)),
          "series %s, expected %s" % (entries, expected))
    h = args.cell_size
    for (load, name), step in zip(expected, wanted):
        where = "%s: " % name
        X, f, cells = read(os.path.join(directory, name))
        M, W = args.mass, args.weight * load
        check(f["mass"].min() > 0., where + "a node without mass")
        check(abs(f["mass"].sum() - M) <= 1e-5 * M,
              where + "mass %.8g, expected %.8g" % (f["mass"].sum(), M))
        if W > 0.:
            up = DIM - 1
            check(abs(f["external_force"][:, up].sum() + W) <= 1e-5 * W,
                  where + "external force %.8g, expected %.8g"
                  % (f["external_force"][:, up].sum(), -W))
            check(abs(f["reaction"][:, up].sum() - W) <= 1e-5 * W,
                  where + "vertical reaction %.8g, expected %.8g"
                  % (f["reaction"][:, up].sum(), W))
        on_face = [np.zeros(len(X), bool) for d in range(DIM)]
        for face in args.held.split(","):
            d, value = "xyz".index(face[0]), float(face[2:])
            on_face[d] |= np.abs(X[:, d] - value) < 1e-6
        scale = max(W, np.abs(f["internal_force"]).max())
        for d in range(DIM):
            check(np.all(f["reaction"][~on_face[d], d] == 0.),
                  where + "a reaction off the face held in direction %d" % d)
            check(np.all(f["displacement_increment"][on_face[d], d] == 0.),
                  where + "the increment is not zero on a held face (%d)" % d)
            free = np.abs(f["internal_force"][~on_face[d], d] -
                          f["external_force"][~on_face[d], d])
            largest = free.max() if len(free) else 0.
            check(args.explicit or largest <= 1e-5 * scale,
                  where + "internal - external force %.3g on a free DoF"
                  % largest)
        # The cells, by their lower-left node's (i, j).
        corners = {tuple(np.round(X[c].min(axis=0) / h).astype(int))
                   for c in cells}
        check(len(corners) == len(cells), where + "a cell written twice")
        if args.grid_cells is not None:
            check(len(cells) < args.grid_cells,
                  where + "%d cells written, the grid has %d"
                  % (len(cells), args.grid_cells))
        start_file = os.path.join(directory, "points_%05d.pvtu" % (step - 1))
        if os.path.exists(start_file):
            start, _ = read_points(start_file)
            held = {tuple(c) for c in np.floor(start / h).astype(int)}
            check(held <= corners, where + "cells with points not written: %s"
                  % sorted(held - corners))
            near = {tuple(np.add(cell, shift)) for cell in held
                    for shift in itertools.product((-1, 0, 1), repeat=DIM)}
            check(corners <= near,
                  where + "cells written away from the points: %s"
                  % sorted(corners - near))
        if args.momentum is None:
            check("velocity" not in f, where + "a velocity without inertia")
            continue
        _, pf = read_points(os.path.join(directory, "points_%05d.pvtu" % step))
        v = [pf["velocity_%d" % d] for d in range(DIM)]
        points = args.momentum * np.array([c.sum() for c in v])
        grid = (f["mass"][:, None] * f["velocity"][:, :DIM]).sum(axis=0)
        scale = args.momentum * sum(np.abs(c).sum() for c in v)
        check(np.all(np.abs(grid - points) <= 1e-5 * scale),
              where + "momentum on the grid %s, of the points %s"
              % (grid, points))
    print("%s: %d grid files checked" % (directory, len(expected)))


def compare(first, second):
    a, b = series(first), series(second)
    check(a == b, "series differ: %s and %s" % (a, b))
    for _, name in a:
        X1, f1, c1 = read(os.path.join(first, name))
        X2, f2, c2 = read(os.path.join(second, name))
        check(X1.shape == X2.shape and np.abs(X1 - X2).max() < 1e-6,
              name + ": the nodes differ")
        check(len(c1) == len(c2), name + ": %d and %d cells" % (len(c1), len(c2)))
        check(sorted(f1) == sorted(f2), name + ": the fields differ")
        for field in f1:
            if X1.shape != X2.shape or field not in f2:
                continue
            scale = max(np.abs(f1[field]).max(), 1e-300)
            check(np.abs(f1[field] - f2[field]).max() <= 1e-5 * scale,
                  name + ": %s differs by %.3g of its largest value"
                  % (field, np.abs(f1[field] - f2[field]).max() / scale))
    print("%s and %s: %d grid files equal" % (first, second, len(a)))


parser = argparse.ArgumentParser()
parser.add_argument("directory", nargs="?")
parser.add_argument("--compare", nargs=2)
parser.add_argument("--mass", type=float)
parser.add_argument("--weight", type=float, default=0.)
parser.add_argument("--momentum", type=float)
parser.add_argument("--cell-size", type=float, default=1.)
parser.add_argument("--grid-cells", type=int)
parser.add_argument("--steps")
parser.add_argument("--held", default="x=0,y=0")
parser.add_argument("--explicit", action="store_true")
parser.add_argument("--dim", type=int, default=2)
arguments = parser.parse_args()
DIM = arguments.dim
if arguments.compare:
    compare(*arguments.compare)
else:
    check_run(arguments)
for problem in problems:
    print(problem)
sys.exit(1 if problems else 0)
