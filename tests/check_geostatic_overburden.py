#!/usr/bin/env python3
"""Checks the start of tests/geostatic_overburden.prm: every point's
initial stress against the overburden of the bodies above it, found here
without IMPM's ray crossings.

Usage: check_geostatic_overburden.py POINTS.pvtu

The bodies of the scene are restated below. For a point at (x, y) the
vertical line through it (from 0 to the grid's top, once per column of
points) is sampled at 400 heights (0.035 m apart at most; the
shortest piece a point here sees is the disc's 1.66 m); each change between
inside and outside a body is then bisected to 1e-12 m with a
point-in-shape test (winding number for the polygon), and the pieces
inside each body are summed. Expected: sigma_yy = -g sum(rho_b h_b), or,
for the box with its named surface, -g rho (13 - y); sigma_xx = sigma_zz =
K0 sigma_yy; sigma_xy = 0. Exits with status 1 when a stress is off by more
than 1e-6 of the largest: the point files hold single precision, positions
and stresses (relative rounding 6e-8; through the disc's chord, whose slope
is steep near its rim, up to 1.4e-7 here), while a point missing one body's
weight or counting a layer twice is off by 1e-2 or more.
"""

import sys

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

G = 10.0
TOP = 14.0
SLOPE = [(0, 0), (20, 0), (20, 5), (13, 5), (8, 10), (0, 10)]


def in_polygon(x, y):
    """Winding number of the polygon around (x, y) (y a number or an
    array), nonzero inside."""
    y = numpy.asarray(y, dtype=float)
    winding = numpy.zeros(y.shape, dtype=int)
    for (ax, ay), (bx, by) in zip(SLOPE, SLOPE[1:] + SLOPE[:1]):
        cross = (bx - ax) * (y - ay) - (x - ax) * (by - ay)
        winding += ((ay <= y) & (y < by) & (cross > 0)).astype(int)
        winding -= ((by <= y) & (y < ay) & (cross < 0)).astype(int)
    return winding != 0


def in_box(x, y):
    return (1 <= x <= 4) & (10 <= numpy.asarray(y)) & (numpy.asarray(y) <= 12)


def in_disc(x, y):
    return (x - 16) ** 2 + (numpy.asarray(y) - 6.5) ** 2 <= 1.5 ** 2


BODIES = [(in_polygon, 2000.0, 0.6), (in_box, 1000.0, 0.5), (in_disc, 3000.0, 0.4)]


def pieces_inside(inside, x):
    """The pieces (bottom, top) of the vertical line at x, from 0 to TOP,
    inside a body: changes found by sampling, then bisected."""
    n = 400
    heights = TOP * numpy.arange(n + 1) / n
    state = inside(x, heights)
    ends = [0.0] if state[0] else []
    for k in numpy.nonzero(state[:-1] != state[1:])[0]:
        low, high = heights[k], heights[k + 1]
        while high - low > 1e-12:
            middle = 0.5 * (low + high)
            if bool(inside(x, middle)) == bool(state[k]):
                low = middle
            else:
                high = middle
        ends.append(0.5 * (low + high))
    if state[-1]:
        ends.append(TOP)
    return list(zip(ends[0::2], ends[1::2]))


columns = {}


def height_inside_above(inside, x, y):
    key = (inside, float(x))
    if key not in columns:
        columns[key] = pieces_inside(inside, x)
    return sum(max(top - max(bottom, y), 0.0) for bottom, top in columns[key])


reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput().GetPointData()
field = {name: vtk_to_numpy(data.GetArray(name))
         for name in ("initial_position", "stress_xx", "stress_yy", "stress_zz",
                      "stress_xy", "body")}
positions = field["initial_position"]
largest = max(abs(field["stress_yy"]).max(), 1.0)
worst = 0.0
counted = [0, 0, 0]
for i in range(len(positions)):
    x, y = positions[i][0], positions[i][1]
    b = int(round(field["body"][i])) - 1  # the files number bodies from 1
    counted[b] += 1
    if b == 1:
        vertical = -G * 1000.0 * max(13.0 - y, 0.0)
    else:
        vertical = -G * sum(rho * height_inside_above(inside, x, y)
                            for inside, rho, _ in BODIES)
    k0 = BODIES[b][2]
    for name, expected in (("stress_yy", vertical), ("stress_xx", k0 * vertical),
                           ("stress_zz", k0 * vertical), ("stress_xy", 0.0)):
        worst = max(worst, abs(field[name][i] - expected) / largest)
print("points per body: %s; largest stress %.1f Pa; largest error %.2e of it"
      % (counted, largest, worst))
if worst > 1e-6 or min(counted) == 0:
    print("FAILED: the start's stresses differ from the overburden")
    sys.exit(1)
