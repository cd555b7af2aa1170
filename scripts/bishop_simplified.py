#!/usr/bin/env python3
"""Bishop's simplified method of slices with a search for the critical circle.

An independent check of IMPM's strength reduction (it shares no code with
IMPM): the factor of safety of a homogeneous, dry slope in plane strain.

  python3 scripts/bishop_simplified.py --surface "0,10; 12,10; 32,0; 60,0" \
      --base 0 --left 0 --unit-weight 20e3 --cohesion 10e3 --friction 20

The ground surface is a polyline from left to right, the slope falling to the
right; the soil fills everything below it down to the rigid base (no circle
may pass below --base) and right of --left (no circle may leave the soil
through the left boundary). For a circle of centre (xc, yc) and radius R the
sliding mass lies between the circle's lower arc y_a(x) = yc - sqrt(R^2 -
(x - xc)^2) and the surface y_s(x); it is cut into slices of width b, and
Bishop's simplified method (moment equilibrium about the centre, the
inter-slice shear forces neglected) gives

  F = sum (c b + W tan(phi)) / m_a  /  sum W sin(a),
  m_a = cos(a) + sin(a) tan(phi) / F,

with W = gamma b (y_s - y_a) and sin(a) = (xc - x) / R at the slice's middle
(a > 0 where the base falls towards the toe). The equation is solved by
fixed-point iteration. The search: a grid of centres above the slope, and for
each centre the radii from the one that reaches the toe's level to the one
tangent to the base, then a pattern search from the best three circles,
halving its steps down to 1e-4 of the slope's height. Circles whose sliding
mass is thinner than 1 % of the height, or whose m_a falls below 0.2
(the method's known trouble near the toe), are skipped.
"""

import argparse
import math
import sys


def parse_polyline(text):
    points = []
    for pair in text.split(";"):
        x, y = (float(v) for v in pair.split(","))
        points.append((x, y))
    if any(b[0] <= a[0] for a, b in zip(points, points[1:])):
        sys.exit("--surface: x must increase along the polyline")
    return points


def surface_height(points, x):
    if x <= points[0][0]:
        return points[0][1]
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return points[-1][1]


class Slope:
    def __init__(self, args):
        self.surface = parse_polyline(args.surface)
        self.base = args.base
        self.left = args.left
        self.gamma = args.unit_weight
        self.c = args.cohesion
        self.tan_phi = math.tan(math.radians(args.friction))
        self.n_slices = args.slices
        ys = [p[1] for p in self.surface]
        self.height = max(ys) - min(ys)

    def factor(self, xc, yc, R):
        """Bishop's F of the circle, or None if it is not admissible."""
        if yc - R < self.base - 1e-9 * self.height:
            return None
        x_min, x_max = xc - R, xc + R
        # The arc's part below the surface: sample finely for its ends.
        n = 400
        inside = []
        for i in range(n + 1):
            x = x_min + (x_max - x_min) * i / n
            y_arc = yc - math.sqrt(max(R * R - (x - xc) ** 2, 0.0))
            inside.append(surface_height(self.surface, x) - y_arc > 0.0)
        if not any(inside):
            return None
        first = inside.index(True)
        last = n - inside[::-1].index(True)
        # One connected sliding mass only.
        if not all(inside[first:last + 1]):
            return None
        step = (x_max - x_min) / n

        def depth(x):
            y_arc = yc - math.sqrt(max(R * R - (x - xc) ** 2, 0.0))
            return surface_height(self.surface, x) - y_arc

        def bisect(a, b):
            # depth(a) <= 0 < depth(b) or the reverse
            fa = depth(a)
            for _ in range(60):
                m = 0.5 * (a + b)
                if (depth(m) > 0.0) == (fa > 0.0):
                    a, fa = m, depth(m)
                else:
                    b = m
            return 0.5 * (a + b)

        x_entry = x_min if first == 0 else bisect(x_min + (first - 1) * step,
                                                  x_min + first * step)
        x_exit = x_max if last == n else bisect(x_min + last * step,
                                                x_min + (last + 1) * step)
        if x_entry < self.left - 1e-9:
            return None
        b = (x_exit - x_entry) / self.n_slices
        slices = []
        thickest = 0.0
        for i in range(self.n_slices):
            x = x_entry + (i + 0.5) * b
            h = depth(x)
            if h <= 0.0:
                continue
            thickest = max(thickest, h)
            sin_a = (xc - x) / R
            cos_a = math.sqrt(max(1.0 - sin_a * sin_a, 0.0))
            slices.append((self.gamma * b * h, sin_a, cos_a))
        if thickest < 0.01 * self.height:
            return None
        driving = sum(W * s for W, s, _ in slices)
        if driving <= 0.0:
            return None
        F = 1.0
        for _ in range(200):
            resisting = 0.0
            for W, s, c in slices:
                m = c + s * self.tan_phi / F
                if m < 0.2:
                    return None
                resisting += (self.c * b + W * self.tan_phi) / m
            F_new = resisting / driving
            if abs(F_new - F) < 1e-12 * F:
                return F_new
            F = F_new
        return F


def search(slope, args):
    H = slope.height
    xs = [p[0] for p in slope.surface]
    toe_level = min(p[1] for p in slope.surface)
    best = []
    nx, ny, nr = args.grid, args.grid, args.grid
    x_lo, x_hi = xs[0], xs[-1]
    y_lo, y_hi = toe_level + 0.5 * H, toe_level + 4.0 * H
    for i in range(nx + 1):
        xc = x_lo + (x_hi - x_lo) * i / nx
        for j in range(ny + 1):
            yc = y_lo + (y_hi - y_lo) * j / ny
            r_max = yc - slope.base
            r_min = max(yc - toe_level - H, 0.05 * H)
            for k in range(nr + 1):
                R = r_min + (r_max - r_min) * k / nr
                F = slope.factor(xc, yc, R)
                if F is not None:
                    best.append((F, xc, yc, R))
    if not best:
        sys.exit("no admissible circle found")
    best.sort()
    results = []
    for F, xc, yc, R in best[:3]:
        step = 0.05 * H
        while step > 1e-4 * H:
            improved = False
            for dx, dy, dr in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0),
                               (0, 0, 1), (0, 0, -1)):
                candidate = (xc + dx * step, yc + dy * step, R + dr * step)
                # Keep a circle tangent to the base tangent when moved.
                G = slope.factor(*candidate)
                if G is None and dr == 0 and abs(yc - R - slope.base) < 1e-9:
                    candidate = (candidate[0], candidate[1],
                                 candidate[1] - slope.base)
                    G = slope.factor(*candidate)
                if G is not None and G < F:
                    F, (xc, yc, R) = G, candidate
                    improved = True
            if not improved:
                step *= 0.5
        results.append((F, xc, yc, R))
    results.sort()
    return results[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--surface", required=True,
                        help="ground surface polyline 'x,y; x,y; ...'")
    parser.add_argument("--base", type=float, required=True,
                        help="level of the rigid base")
    parser.add_argument("--left", type=float, required=True,
                        help="x of the left boundary of the soil")
    parser.add_argument("--unit-weight", type=float, required=True)
    parser.add_argument("--cohesion", type=float, required=True)
    parser.add_argument("--friction", type=float, required=True,
                        help="friction angle in degrees")
    parser.add_argument("--slices", type=int, default=100)
    parser.add_argument("--grid", type=int, default=16,
                        help="grid points per direction of the first search")
    args = parser.parse_args()
    slope = Slope(args)
    F, xc, yc, R = search(slope, args)
    print("Bishop's simplified method: F = %.4f" % F)
    print("critical circle: centre (%.3f, %.3f), radius %.3f" % (xc, yc, R))


if __name__ == "__main__":
    main()
