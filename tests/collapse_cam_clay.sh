#!/usr/bin/env bash
# The collapse with modified Cam-clay (prm/collapse_cam_clay.prm; issue 34,
# doc/hard_cases.md case 14):
#  1. the scene (in time, with inertia, rough base): it runs to its end
#     (8 s), the reactions balance the load (the inertial force included)
#     in every step, mass is kept, the heap comes to rest (kinetic energy
#     at the end below 0.2 % of its peak; it is 0.05 %) and its slope from
#     x = 4 m to 12 m lies below the critical-state friction angle in plane
#     strain, asin(M / sqrt 3) = 43.9 degrees for M = 1.2 (it is 34), with
#     the toe inside the grid;
#  2. quasi-static, without time or inertia: without 'Initial stress
#     release' the K0 traction on the free face is unbalanced in full at
#     the first step and the run stops there; with it the first step starts
#     in equilibrium and the face stands until load factor 0.818 (its
#     largest displacement then under 0.1 m) and the run stops with
#     Newton's report (a cohesionless face has no static equilibrium past
#     its active state; the collapse beyond it is dynamic, as in 1).
# Usage: collapse_cam_clay.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
"$impm" "$scene" --set "Output directory=dynamic" --set "Testing/Enabled=true" \
  --set "Output/Interval=160" > dynamic.txt 2>&1 ||
  { cp dynamic.txt log.txt; fail "the collapse with inertia failed"; }
quasi_static=(--set "Time/End time=0" --set "Inertia/Enabled=false" --set "Solver/Load steps=40"
  --set "Testing/Enabled=true")
"$impm" "$scene" --set "Output directory=at_once" "${quasi_static[@]}" > at_once.txt 2>&1 &&
  fail "the quasi-static collapse without the release did not stop"
"$impm" "$scene" --set "Output directory=released" "${quasi_static[@]}" \
  --set "Initial stress release/Enabled=true" --set "Output/Interval=1" > released.txt 2>&1 &&
  fail "the quasi-static collapse with the release did not stop"
/usr/bin/python3 - <<'PY' || fail "the Cam-clay collapse"
import csv, glob, math, re
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

def positions(name):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(name)
    reader.Update()
    points = reader.GetOutput().GetPoints().GetData()
    return vtk_to_numpy(points)

text = open("dynamic.txt").read()
rows = [r for r in csv.DictReader(open("dynamic/steps.csv")) if r["converged"] == "1"]
kinetic = [float(r["kinetic_energy"]) for r in rows]
mass = re.search(r"total mass: (\S+) \(initial (\S+)\)", text)
x = positions(sorted(glob.glob("dynamic/points_*.pvtu"))[-1])
top = lambda a, b: x[(x[:, 0] >= a) & (x[:, 0] < b), 1].max()
slope = math.degrees(math.atan((top(4, 5) - top(11, 12)) / 7))
critical = math.degrees(math.asin(1.2 / math.sqrt(3)))

def errors(name):
    return [l for l in open(name) if l.startswith("Error: ")]
at_once, released = errors("at_once.txt"), errors("released.txt")
released_rows = [r for r in csv.DictReader(open("released/steps.csv")) if r["converged"] == "1"]
last = released_rows[-1]
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName("released/points_%05d.pvtu" % int(last["step"]))
reader.Update()
u = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("displacement"))
face = np.linalg.norm(u, axis=1).max()
checks = [
    ("with inertia: runs to 8 s", abs(float(rows[-1]["time"]) - 8) < 1e-9, rows[-1]["time"]),
    ("reactions balance the load in every step", "reactions balance the load to 1e-8 in every step: yes" in text, ""),
    ("mass kept", mass is not None and mass.group(1) == mass.group(2), mass.group(0) if mass else "none"),
    ("at rest: kinetic energy at the end below 0.2 % of its peak", kinetic[-1] < 0.002 * max(kinetic),
     "%.3f %%" % (100 * kinetic[-1] / max(kinetic))),
    ("the heap's slope (4 to 12 m) below %.1f degrees and above 20" % critical, 20 < slope < critical, "%.1f" % slope),
    ("the toe inside the grid", 8 < x[:, 0].max() < 16, "%.2f m" % x[:, 0].max()),
    ("quasi-static without the release: stops in load step 1",
     len(at_once) == 1 and at_once[0].startswith("Error: Load step 1 "), at_once[0][:60] if at_once else "no error"),
    ("with it: one error line, Newton's report", len(released) == 1 and "Newton" in released[0],
     released[0][:60] if released else "no error"),
    ("the face stands to a load factor in [0.78, 0.85]", 0.78 <= float(last["load_factor"]) <= 0.85, last["load_factor"]),
    ("... having moved less than 0.1 m", face < 0.1, "%.3f m" % face),
]
failed = 0
for text_, ok, figure in checks:
    print("%s: %s (%s)" % ("ok" if ok else "FAILED", text_, figure))
    failed += not ok
raise SystemExit(failed)
PY
