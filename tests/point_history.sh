#!/usr/bin/env bash
# The point history (subsection "Point history", the first postprocessor
# with parameters of its own): the collapse at h = 1 m in 4 load steps with
# point files at every step follows three points chosen by initial
# position. point_history.csv must hold, for every written step, the values
# the point files hold for the same point (read back by VTK's XML reader,
# tests/compare_point_history.py); a point history resumed from a
# checkpoint equals the uninterrupted one; and with a region, every point
# that starts in it is followed too (their number counted from the point
# files, their values compared as above).
# Usage: point_history.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
settings=(--set "Output/Interval=1" --set "Point history/Positions=0.5, 0.5; 7.9, 7.9; 3, 4")
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" > log.txt 2>&1 || fail "the run failed"
converged=$(grep -c "^step .* iterations [0-9]" log.txt)
[ "$(wc -l < results/point_history.csv)" -eq $((1 + 3 * (converged + 1))) ] ||
  fail "point_history.csv has $(wc -l < results/point_history.csv) lines, not a header and 3 points x $((converged + 1)) states"
/usr/bin/python3 "$here/compare_point_history.py" results > check.txt ||
  { cat check.txt; fail "the point history differs from the point files"; }
cat check.txt
cp results/point_history.csv full_history.csv
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=2" \
  --stop-after-step 3 --overwrite > part1.txt 2>&1 || fail "the first part failed"
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=2" \
  --resume > part2.txt 2>&1 || fail "the resumed run failed"
compare full_history.csv results/point_history.csv "the resumed point history differs"
# A region: every point that starts in the box [0, 2] x [0, 1.5], after the
# three positions; their number counted from the first point file's
# initial positions, their values compared with the point files as above.
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --overwrite \
  --set "Point history/Region lower corner=0, 0" \
  --set "Point history/Region upper corner=2, 1.5" > region.txt 2>&1 || fail "the run with a region failed"
in_region=$(/usr/bin/python3 - results <<'PY'
import sys, xml.etree.ElementTree as ElementTree
import vtk
from vtk.util.numpy_support import vtk_to_numpy
first = [d.get("file") for d in
         ElementTree.parse(sys.argv[1] + "/points.pvd").getroot().iter("DataSet")][0]
reader = vtk.vtkXMLPUnstructuredGridReader() if first.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1] + "/" + first)
reader.Update()
X = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("initial_position"))
print(sum(1 for x in X if 0 <= x[0] <= 2 and 0 <= x[1] <= 1.5))
PY
) || fail "counting the points in the region"
[ "$in_region" -gt 0 ] || fail "no point starts in the region"
[ "$(wc -l < results/point_history.csv)" -eq $((1 + (3 + in_region) * (converged + 1))) ] ||
  fail "point_history.csv with a region has $(wc -l < results/point_history.csv) lines, not a header and (3 + $in_region) points x $((converged + 1)) states"
/usr/bin/python3 "$here/compare_point_history.py" results > check.txt ||
  { cat check.txt; fail "the region's point history differs from the point files"; }
echo "point_history: the history equals the point files and survives a resume"
