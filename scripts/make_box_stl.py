#!/usr/bin/env python3
"""Write a box [lo, hi] as an ASCII STL whose every side is split into n x n
squares, two triangles each (12 n^2 triangles, outward oriented): a rigid
surface with many triangles for the search benchmark of doc/benchmarks.
Usage: make_box_stl.py XL,YL,ZL XU,YU,ZU N FILE"""
import sys
lo = [float(v) for v in sys.argv[1].split(',')]
hi = [float(v) for v in sys.argv[2].split(',')]
n = int(sys.argv[3])
out = open(sys.argv[4], 'w')
out.write('solid box\n')
def point(axis, side, u, v):
    p = [0.0, 0.0, 0.0]
    a, b = [d for d in range(3) if d != axis]
    p[axis] = hi[axis] if side else lo[axis]
    p[a] = lo[a] + (hi[a] - lo[a]) * u / n
    p[b] = lo[b] + (hi[b] - lo[b]) * v / n
    return p
def tri(p, q, r):
    out.write(' facet normal 0 0 0\n  outer loop\n')
    for x in (p, q, r):
        out.write('   vertex %.17g %.17g %.17g\n' % tuple(x))
    out.write('  endloop\n endfacet\n')
for axis in range(3):
    for side in (0, 1):
        for i in range(n):
            for j in range(n):
                p, q = point(axis, side, i, j), point(axis, side, i + 1, j)
                r, s = point(axis, side, i + 1, j + 1), point(axis, side, i, j + 1)
                # Outward: the normal's component along the axis has the
                # side's sign.
                e1 = [q[k] - p[k] for k in range(3)]
                e2 = [r[k] - p[k] for k in range(3)]
                normal = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                          e1[0] * e2[1] - e1[1] * e2[0]]
                if (normal[axis] > 0) != bool(side):
                    q, s = s, q
                tri(p, q, r); tri(p, r, s)
out.write('endsolid box\n')
