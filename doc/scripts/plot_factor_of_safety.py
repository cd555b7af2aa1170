#!/usr/bin/env python3
"""The slope that stands and the slide of a strength reduction: the points of
the final bracket's two trials (last_stable, first_failed) at their last
written step, coloured by their displacement's magnitude.

  /usr/bin/python3 doc/scripts/plot_factor_of_safety.py OUTPUT_DIRECTORY FIGURE.png [XC,YC,R]

XC,YC,R: a circle to draw (Bishop's critical circle of
scripts/bishop_simplified.py), its part within the points' extent.
"""
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def last_points(directory):
    files = sorted(glob.glob(os.path.join(directory, "points_*.pvtu")),
                   key=lambda f: int(os.path.basename(f)[7:].split(".")[0]))
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    return x, np.linalg.norm(u, axis=1)


def factor(directory):
    name = os.path.basename(os.path.realpath(directory))
    for line in open(os.path.join(os.path.dirname(directory),
                                  "factor_of_safety.csv")):
        fields = line.strip().split(",")
        if fields[-1] == name:
            return float(fields[1])
    return float("nan")


base, figure = sys.argv[1], sys.argv[2]
fig, axes = plt.subplots(2, 1, figsize=(8, 6.4), sharex=True)
for axis, link, title in zip(axes, ("last_stable", "first_failed"),
                             ("stands", "fails")):
    directory = os.path.join(base, link)
    x, u = last_points(directory)
    points = axis.scatter(x[:, 0], x[:, 1], c=u, s=3, cmap="viridis",
                          vmin=0, vmax=max(u.max(), 1e-12))
    axis.set_aspect("equal")
    axis.set_ylabel("y (m)")
    axis.set_title("F = %.4f %s: largest displacement %.3f m"
                   % (factor(directory), title, u.max()))
    fig.colorbar(points, ax=axis, label="|u| (m)")
    if len(sys.argv) > 3:
        xc, yc, r = (float(v) for v in sys.argv[3].split(","))
        angle = np.linspace(-np.pi, 0, 400)
        arc_x, arc_y = xc + r * np.cos(angle), yc + r * np.sin(angle)
        inside = (arc_y <= x[:, 1].max()) & (arc_x >= x[:, 0].min()) & (arc_x <= x[:, 0].max())
        axis.plot(arc_x[inside], arc_y[inside], "r--", lw=1,
                  label="Bishop's critical circle")
        axis.legend(loc="lower left", fontsize=8)
axes[-1].set_xlabel("x (m)")
fig.tight_layout()
fig.savefig(figure, dpi=110)
