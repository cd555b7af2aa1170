#!/usr/bin/env bash
# The granular column collapse (prm/granular_column_collapse.prm) at
# aspect ratios 0.5 and 1 against Lube et al. (2005): (L_inf - L0)/L0 =
# 1.2 a, within 15 % (the issue's bar; it is -8.6 % and +12 %), the run
# reaching its end, the reactions balancing the load (the inertial force
# included), mass kept and the column at rest at the end (kinetic energy
# below 1e-3 of its peak). The other ratios, where the bar is not met, and
# the FLIP fraction's effect: doc/benchmarks/inertia.md, "Granular column
# collapse".
# Usage: granular_collapse.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
"$impm" "$scene" --set "Output directory=a1" --set "Testing/Enabled=true" \
  --set "Output/Interval=300" > a1.txt 2>&1 || { cp a1.txt log.txt; fail "a = 1 failed"; }
"$impm" "$scene" --set "Output directory=a0.5" --set "Testing/Enabled=true" \
  --set "Body 1/Upper corner=1, 0.5" --set "Grid/Upper corner=2.5, 0.75" \
  --set "Grid/Number of cells=50, 15" --set "Output/Interval=300" > a0.5.txt 2>&1 ||
  { cp a0.5.txt log.txt; fail "a = 0.5 failed"; }
/usr/bin/python3 - <<'PY' || fail "the granular column collapse"
import csv, glob, re
import vtk
from vtk.util.numpy_support import vtk_to_numpy
failed = 0
for a in (1, 0.5):
    name = "a%g" % a
    text = open(name + ".txt").read()
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(sorted(glob.glob(name + "/points_*.pvtu"))[-1])
    reader.Update()
    x = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
    rows = list(csv.DictReader(open(name + "/steps.csv")))
    kinetic = [float(r["kinetic_energy"]) for r in rows if r["converged"] == "1"]
    mass = re.search(r"total mass: (\S+) \(initial (\S+)\)", text)
    runout, lube = x[:, 0].max() - 1, 1.2 * a
    checks = [
        ("run-out (L_inf - L0)/L0 within 15 %% of Lube's %.2f" % lube, abs(runout / lube - 1) < 0.15,
         "%.3f, %+.1f %%" % (runout, 100 * (runout / lube - 1))),
        ("runs to 1.5 s (a cut attempt is redone smaller)", rows[-1]["converged"] == "1" and
         abs(float(rows[-1]["time"]) - 1.5) < 1e-9,
         "%d steps, %d cut" % (len(kinetic), len(rows) - len(kinetic))),
        ("reactions balance the load", "reactions balance the load to 1e-8 in every step: yes" in text, ""),
        ("mass kept", mass is not None and mass.group(1) == mass.group(2), ""),
        ("at rest: kinetic energy at the end below 1e-3 of its peak", kinetic[-1] < 1e-3 * max(kinetic),
         "%.1e" % (kinetic[-1] / max(kinetic))),
    ]
    for text_, ok, figure in checks:
        print("a = %g: %s: %s (%s)" % (a, "ok" if ok else "FAILED", text_, figure))
        failed += not ok
raise SystemExit(failed)
PY
