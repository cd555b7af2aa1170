#!/usr/bin/env bash
# The granular column collapse against Lube et al. (2005)
# (doc/benchmarks/inertia.md, "Granular column collapse"): the scene
# prm/granular_column_collapse.prm at aspect ratios a = 0.5, 1, 1.5, 4 and
# 7 (H0 = a L0, L0 = 1 m, h = L0/20 throughout; the grid sized to the
# expected run-out; 1.5 sqrt(max(1, a)) s at 0.005 s a step) with the FLIP
# fractions given (default 0.95 and 0.8; APIC for 'Velocity update' =
# 'APIC'). Prints per run the front's
# run-out (L_inf - L0)/L0 from the outermost point, Lube's value, the
# difference, the kinetic energy left at the end against its peak, and the
# wall time.
# Arguments after '--' are passed to every run (e.g. --set "Body
# 1/Material/Mohr-Coulomb/Friction angle=35").
# REFINEMENT=2 in the environment halves the cell and the time step (h =
# L0/40, 0.0025 s). RATIOS="4 7" in the environment runs only those
# aspect ratios.
# Usage: [REFINEMENT=R] scripts/granular_collapse_study.sh [IMPM] [FLIP FRACTIONS or APIC...] [-- IMPM ARGUMENTS]
impm=${1:-build/impm}
shift
fractions=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do fractions+=("$1"); shift; done
[ "$1" = -- ] && shift
extra=("$@")
[ ${#fractions[@]} -eq 0 ] && fractions=(0.95 0.8)
impm=$(cd "$(dirname "$impm")" && pwd)/$(basename "$impm")
scene=$(cd "$(dirname "$0")/.." && pwd)/prm/granular_column_collapse.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
printf '%-5s %-6s %-10s %-8s %-8s %-12s %s\n' a FLIP "run-out" Lube diff "Ek end/peak" "wall time"
for a in ${RATIOS:-0.5 1 1.5 4 7}; do
  read -r X Y NX NY T N <<< "$(/usr/bin/python3 -c "
a = $a; ref = 1.2 * a if a < 1.8 else 1.9 * a ** (2 / 3)
r = ${REFINEMENT:-1}
X = round(1 + 1.6 * ref + 0.5, 1); Y = round(a + 0.25, 2); h = 0.05 / r
T = round(1.5 * max(1, a) ** 0.5, 2)
print(X, Y, round(X / h), round(Y / h), T, int(round(T * r / 0.005)))")"
  for flip in "${fractions[@]}"; do
    out=a${a}_flip$flip
    # APIC: the affine transfer (FLIP fraction 1) in place of a fraction.
    update=(--set "Inertia/FLIP fraction=$flip")
    [ "$flip" = APIC ] && update=(--set "Inertia/FLIP fraction=1" --set "Inertia/Velocity update=APIC")
    start=$(date +%s.%N)
    "$impm" "$scene" --set "Output directory=$out" --set "Grid/Upper corner=$X, $Y" \
      --set "Grid/Number of cells=$NX, $NY" --set "Body 1/Upper corner=1, $a" \
      --set "Time/End time=$T" --set "Solver/Load steps=$N" --set "Output/Interval=$N" \
      "${update[@]}" "${extra[@]}" > $out.txt 2>&1 || { echo "a = $a, FLIP $flip: failed"; tail -2 $out.txt; continue; }
    end=$(date +%s.%N)
    /usr/bin/python3 - "$out" "$a" "$flip" "$start" "$end" <<'PY'
import csv, glob, sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
out, a, flip, start, end = sys.argv[1], float(sys.argv[2]), sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName(sorted(glob.glob(out + "/points_*.pvtu"))[-1])
reader.Update()
x = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
rows = [r for r in csv.DictReader(open(out + "/steps.csv")) if r["converged"] == "1"]
kinetic = [float(r["kinetic_energy"]) for r in rows]
runout = x[:, 0].max() - 1
lube = 1.2 * a if a < 1.8 else 1.9 * a ** (2 / 3)
print("%-5g %-6s %-10.3f %-8.3f %+-8.1f %-12.1e %.0f s" % (a, flip, runout, lube, 100 * (runout / lube - 1),
      kinetic[-1] / max(kinetic), end - start))
PY
  done
done
