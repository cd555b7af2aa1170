#!/usr/bin/env bash
# 'Output/Grid fields': nodal fields in the grid.pvd series beside the point
# files, read back with VTK by tests/check_grid_files.py and checked against
# numbers by hand:
#  * the collapse (collapse_h1_4steps: an 8 m x 8 m block of density 1000
#    under gravity 10 m/s^2 on a 16 x 8 grid of 1 m cells, rollers on x-
#    and y-, steps cut on the way), every converged step written: the nodal
#    mass sums to rho A = 1000 x 64 = 64000 kg/m; the external force to
#    -lambda rho g A = -lambda 640000 N/m and the vertical reaction to
#    +lambda 640000 (the weight at the step's load factor lambda:
#    equilibrium); reactions only on the rollers' DoFs, where the
#    displacement increment is zero; internal = external force elsewhere;
#    only cells the points' supports cover (fewer than the 128 of the grid,
#    every cell with a point at the step's start, none farther than a node
#    from one); no velocity without inertia;
#  * the vibrating bar with inertia (25 m x 1 m, density 1, 2 x 2 points per
#    1 m cell: 100 points of 0.25 kg/m), shortened to 10 steps and written
#    every 5: the series holds steps 5 and 10, the mass is 25 kg/m, and
#    the grid's momentum sum_I M_I v_I equals the points' sum_p 0.25 v_p in
#    the point files of the same steps (partition of unity); the same for
#    the column of column_gimp_elastic_8 (6.25 m x 50 m, density 80:
#    25000 kg/m, 32 points of 781.25 kg/m) under its weight at once with
#    explicit MUSL steps (no equilibrium check: its internal force holds
#    no inertia);
#  * in 3D, the column of column_3d_gimp_plastic_8 (6.25 x 6.25 x 50 m,
#    density 80, g = 10, rollers on five faces), every 10th of 50 steps:
#    the mass 156250 kg, the vertical reaction lambda 1562500 N, and the
#    rest as for the collapse;
#  * on two processes the same checks, and every field of both runs equal
#    to those of a run on one process (the same sums);
#  * a run stopped after step 4 and resumed from its checkpoint writes
#    the uninterrupted run's series and fields;
#  * a grid piece that cannot be written (on two processes only the second
#    process's) stops the run with one error line naming it;
#  * the point and grid files written with 'Output/Compression' = best
#    compression and none hold the same data as those of the default (best
#    speed), the uncompressed ones more than 1.5 times as large, the best
#    compressed ones no larger;
#  * the default writes no grid file; velocity without inertia and grid
#    fields with 'Output/Interval = 0' are refused with one line.
# Usage: grid_files.sh IMPM TESTS_DIR [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
check="/usr/bin/python3 $tests/check_grid_files.py"
collapse=(--set "Output/Grid fields=all" --set "Output/Interval=1")
bar=(--set "Time/End time=2" --set "Solver/Load steps=10"
  --set "Output/Grid fields=all" --set "Output/Interval=5")

"${launcher[@]}" "$impm" "$tests/collapse_h1_4steps.prm" "${collapse[@]}" \
  --set "Output directory=collapse" > log.txt 2>&1 || fail "the collapse failed"
$check collapse --mass 64000 --weight 640000 --grid-cells 128 ||
  fail "the collapse's grid files"
"${launcher[@]}" "$impm" "$tests/vibrating_bar.prm" "${bar[@]}" \
  --set "Output directory=bar" > log.txt 2>&1 || fail "the bar failed"
$check bar --mass 25 --momentum 0.25 --grid-cells 27 --steps 5,10 \
  --held x=0,y=0,y=1 || fail "the bar's grid files"
# The column of column_gimp_elastic_8 (6.25 m x 50 m, density 80: 25000
# kg/m in 32 points of 781.25 kg/m) under its full weight at once, explicit
# (MUSL), 100 steps written every 50: mass and momentum as for the bar.
explicit=(--set "Gravity/Ramped=false" --set "Time/End time=2"
  --set "Time/Time step=0.02" --set "Inertia/Enabled=true"
  --set "Inertia/Integrator=explicit MUSL" --set "Output/Grid fields=all"
  --set "Output/Interval=50")
"${launcher[@]}" "$impm" "$tests/column_gimp_elastic_8.prm" "${explicit[@]}" \
  --set "Output directory=explicit" > log.txt 2>&1 ||
  fail "the explicit column failed"
$check explicit --mass 25000 --momentum 781.25 --cell-size 6.25 \
  --steps 50,100 --held x=0,x=6.25,y=0 --explicit ||
  fail "the explicit column's grid files"
# In 3D: the column of column_3d_gimp_plastic_8 (6.25 m x 6.25 m x 50 m,
# density 80, g = 10: 156250 kg and 1562500 N; rollers on x-, x+, y-, y+,
# z-), 50 load steps written every 10.
column3d=(--set "Output/Grid fields=all" --set "Output/Interval=10")
"${launcher[@]}" "$impm" "$tests/column_3d_gimp_plastic_8.prm" \
  "${column3d[@]}" --set "Output directory=column3d" > log.txt 2>&1 ||
  fail "the 3D column failed"
$check column3d --dim 3 --mass 156250 --weight 1562500 --cell-size 6.25 \
  --steps 10,20,30,40,50 --held x=0,x=6.25,y=0,y=6.25,z=0 ||
  fail "the 3D column's grid files"

# A grid piece that cannot be written (a directory of its name; on two
# processes the second one's piece, so that one process fails alone): one
# error line naming it, and no hang.
piece=grid_00002.0000.vtu
[ ${#launcher[@]} -gt 0 ] && piece=grid_00002.0001.vtu
mkdir -p unwritable/$piece
timeout 120 "${launcher[@]}" "$impm" "$tests/collapse_h1_4steps.prm" \
  "${collapse[@]}" --set "Output directory=unwritable" > log.txt 2>&1
status=$?
[ $status -eq 124 ] && fail "a grid piece that cannot be written: no exit"
[ $status -eq 0 ] && fail "a grid piece that cannot be written: no error"
# (Since the start of a run refuses an entry with one of IMPM's names
# that no run of it wrote, the obstacle is refused before the write: the
# line names it either way.)
[ "$(grep -c '^Error: ' log.txt)" = 1 ] &&
  grep -q "^Error: .*$piece" log.txt ||
  fail "not one error line naming the grid piece"

if [ ${#launcher[@]} -gt 0 ]; then
  "$impm" "$tests/collapse_h1_4steps.prm" "${collapse[@]}" \
    --set "Output directory=collapse_1" > log.txt 2>&1 ||
    fail "the collapse on one process failed"
  $check --compare collapse_1 collapse || fail "one and two processes differ"
  "$impm" "$tests/vibrating_bar.prm" "${bar[@]}" \
    --set "Output directory=bar_1" > log.txt 2>&1 ||
    fail "the bar on one process failed"
  $check --compare bar_1 bar || fail "one and two processes differ (bar)"
  "$impm" "$tests/column_gimp_elastic_8.prm" "${explicit[@]}" \
    --set "Output directory=explicit_1" > log.txt 2>&1 ||
    fail "the explicit column on one process failed"
  $check --compare explicit_1 explicit ||
    fail "one and two processes differ (explicit)"
  "$impm" "$tests/column_3d_gimp_plastic_8.prm" "${column3d[@]}" \
    --set "Output directory=column3d_1" > log.txt 2>&1 ||
    fail "the 3D column on one process failed"
  $check --compare column3d_1 column3d --dim 3 ||
    fail "one and two processes differ (3D)"
  exit 0
fi

"$impm" "$tests/collapse_h1_4steps.prm" "${collapse[@]}" \
  --set "Checkpoint/Interval=1" --set "Output directory=resumed" \
  --stop-after-step 4 > log.txt 2>&1 || fail "the run stopped after step 4"
"$impm" "$tests/collapse_h1_4steps.prm" "${collapse[@]}" \
  --set "Checkpoint/Interval=1" --set "Output directory=resumed" \
  --resume > log.txt 2>&1 || fail "the resumed run"
$check --compare collapse resumed || fail "the resumed run's grid files"
# 'Output/Compression': the collapse's files written at the smallest zlib
# level and without compression hold the default (fastest) level's data,
# point files and grid files alike, each file marked as compressed or not.
for level in "best compression" none; do
  dir=collapse_${level// /_}
  "$impm" "$tests/collapse_h1_4steps.prm" "${collapse[@]}" \
    --set "Output/Compression=$level" --set "Output directory=$dir" \
    > log.txt 2>&1 || fail "the collapse with compression $level"
  $check --compare collapse "$dir" || fail "grid files with compression $level"
  /usr/bin/python3 - collapse "$dir" <<'PY' || fail "point files with compression $level"
import glob, os, sys
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy
reference, other = sys.argv[1:]
names = sorted(os.path.basename(f) for f in glob.glob(reference + "/*.vtu"))
assert names and names == sorted(os.path.basename(f) for f in glob.glob(other + "/*.vtu"))
size = lambda d: sum(os.path.getsize(d + "/" + name) for name in names)
# zlib's stored blocks without compression: about twice the fastest level's
# bytes; its smallest level: no more than the fastest level's.
if other.endswith("none") and not size(other) > 1.5 * size(reference):
    sys.exit("uncompressed files not larger")
if other.endswith("compression") and not size(other) <= size(reference):
    sys.exit("best compression's files larger than best speed's")
for name in names:
    data = []
    for directory in (reference, other):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(directory + "/" + name)
        reader.Update()
        data.append(reader.GetOutput())
    a, b = data
    if a.GetNumberOfPoints() != b.GetNumberOfPoints() or not np.array_equal(
            vtk_to_numpy(a.GetPoints().GetData()), vtk_to_numpy(b.GetPoints().GetData())):
        sys.exit(name + ": the points differ")
    for i in range(a.GetPointData().GetNumberOfArrays()):
        array = a.GetPointData().GetArrayName(i)
        if not np.array_equal(vtk_to_numpy(a.GetPointData().GetArray(array)),
                              vtk_to_numpy(b.GetPointData().GetArray(array))):
            sys.exit(name + ": " + array + " differs")
PY
done
"$impm" "$tests/collapse_h1_4steps.prm" --set "Output/Interval=1" \
  --set "Output directory=default" > log.txt 2>&1 || fail "the default run"
ls default/grid* > /dev/null 2>&1 && fail "grid files without Grid fields"
refused() {
  "$impm" "$tests/collapse_h1_4steps.prm" "$@" \
    --set "Output directory=refused" > log.txt 2>&1 && fail "accepted: $*"
  [ "$(grep -c . log.txt)" = 1 ] || fail "not one line: $*"
}
refused --set "Output/Grid fields=velocity" --set "Output/Interval=1"
grep -q "^Error: Output/Grid fields names velocity, which only a scene with \
inertia has" log.txt || fail "the message on velocity without inertia"
refused --set "Output/Grid fields=mass" --set "Output/Interval=0"
grep -q "^Error: Output/Grid fields are written on the steps of the point \
files" log.txt || fail "the message on Interval = 0"
echo "grid_files: the grid fields are right"
