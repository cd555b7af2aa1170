#!/usr/bin/python3
"""Figures of doc/figures/: the strip footing's load-settlement curve against
Prandtl's limit load, and the cantilever's deflection against beam theory
under refinement (doc/cookbook/cantilever.md cites it).
Usage: python3 doc/scripts/scene_figures.py build/impm"""
import csv
import os
import re
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

impm = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/impm")
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
figures = os.path.join(root, "doc", "figures")
work = tempfile.mkdtemp()


def run(scene, *sets, testing=False):
    args = [impm, os.path.join(root, "prm", scene), "--set", "Output/Interval=0",
            "--set", "Output directory=" + work]
    for s in sets:
        args += ["--set", s]
    if testing:
        args += ["--set", "Testing/Enabled=true", "--set", "Testing/Printed points=100000"]
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


# Strip footing: reaction of the footing nodes against settlement.
run("strip_footing.prm")
rows = [r for r in csv.DictReader(open(os.path.join(work, "steps.csv"))) if r["converged"] == "1"]
settlement = [0.2 * float(r["load_factor"]) for r in rows]
load = [-float(r["reaction_y+_y"]) / 1e3 for r in rows]
prandtl = (2 + 3.141592653589793) * 2e4 / 2 ** 0.5 * 0.5 / 1e3
plt.figure(figsize=(5, 3.5))
plt.plot([0] + settlement, [0] + load, "o-", ms=3, label="IMPM (h = 0.25 m, GIMP 2x2)")
plt.axhline(prandtl, color="k", ls="--", label="Prandtl (2 + pi) c B/2 = %.1f kN" % prandtl)
plt.xlabel("settlement (m)")
plt.ylabel("footing load, half model (kN/m)")
plt.legend(loc="lower right", fontsize=8)
plt.tight_layout()
plt.savefig(os.path.join(figures, "scene_strip_footing.png"), dpi=100)
print("footing: final load %.2f kN, Prandtl %.2f kN" % (load[-1], prandtl))

# Cantilever: end deflection against beam theory under refinement.
depths, ratios = [], []
for nx, ny, depth in ((48, 12, 4), (96, 24, 8), (192, 48, 16)):
    out = run("cantilever.prm", "Grid/Number of cells=%d, %d" % (nx, ny), testing=True)
    points = [tuple(map(float, m.groups())) for m in
              re.finditer(r"X = (\S+) (\S+), u = (\S+) (\S+),", out)]
    end = max(p[0] for p in points)
    tip = [p[3] for p in points if p[0] == end]
    w = -end ** 2 * (30 - end) / (6 * 1e6 / 12) - end / (5 / 6 * 5e5)
    depths.append(depth)
    ratios.append(sum(tip) / len(tip) / w)
    print("cantilever: %d cells through the depth, end deflection / beam theory = %.4f" % (depth, ratios[-1]))
plt.figure(figsize=(5, 3.5))
plt.semilogx(depths, ratios, "o-", base=2)
plt.axhline(1, color="k", ls="--", label="beam theory (with shear)")
plt.xlabel("cells through the depth")
plt.ylabel("end deflection / beam theory")
plt.legend(fontsize=8)
plt.tight_layout()
plt.savefig(os.path.join(figures, "scene_cantilever.png"), dpi=100)
