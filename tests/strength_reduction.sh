#!/usr/bin/env bash
# Strength reduction's hard cases on the Tresca block of
# strength_reduction_block.prm, whose factor of safety is exactly
# 2c / q (the stress is homogeneous, so no grid error):
#  1. q = 2c, the block exactly at its limit, and the first trial at F = 1:
#     the final bracket holds F = 1 and is at most 'Tolerance' wide;
#  2. q = 2c / 1.25 searched from above (First factor = 2, trials that fail
#     first): the bracket holds 1.25;
#  3. the files: factor_of_safety.csv lists the trials, last_stable and
#     first_failed link to the bracket's trials, whose point files end with
#     the last converged state (the failed one beyond the displacement
#     limit, the stable one within it); a second search in the same
#     directory removes the first one's trials;
#  4. no displacement limit: the block flattens past its limit and its
#     nominal traction is carried by a wider block, so trials stand far
#     above F = 1.25 until a point leaves the grid, which fails the trial
#     (not the search);
#  5. a trial that fails on a load step (strength_reduction_slope.prm at
#     F = 2.5 without a displacement limit): its point files end with its
#     last converged step, though that is no output step;
#  6. the block in 3D (a cube on rollers under a traction on z+, uniaxial
#     stress): its bracket holds 1.25 too;
#  7. a failure displacement below the block's elastic settlement (1e-9 m
#     against 3.5e-6 m in the first step): every trial would fail alike, whatever F (until
#     2026-11-28 the search ran its 30 trials down to F = 8e-6); the search
#     stops after the second trial with one line saying the displacement
#     does not depend on the strength.
# Usage: strength_reduction.sh IMPM TESTS_DIRECTORY [MPIEXEC N]
source "$(dirname "$0")/script_helpers.sh" "$@"
scene=$2/strength_reduction_block.prm
run() { "${launcher[@]}" "$impm" "$scene" "$@" > log.txt 2>&1 || fail "the run failed: $*"; }
# bracket DIR: "stands fails" of the final line of the search in DIR.
bracket() {
  /usr/bin/python3 - "$1/factor_of_safety.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
stood = [float(r["factor"]) for r in rows if r["stands"] == "1"]
failed = [float(r["factor"]) for r in rows if r["stands"] == "0"]
print(max(stood), min(failed))
EOF
}
# holds DIR F TOL: the bracket of DIR holds F and is at most TOL wide.
holds() {
  read -r low high < <(bracket "$1")
  /usr/bin/python3 -c "import sys; l, h, f, t = map(float, sys.argv[1:]); sys.exit(not (l <= f <= h and h - l <= t + 1e-12))" \
    "$low" "$high" "$2" "$3" || fail "bracket [$low, $high] of $1 does not hold F = $2 within $3"
}

# 1. Exactly at the limit.
run --set "Traction/Traction=0, -20000" --set "Output directory=at_limit"
holds at_limit 1 0.01
grep -q "^trial  1: F = 1.000000" log.txt || fail "the first trial is not at F = 1"

# 2. From above.
run --set "Strength reduction/First factor=2" --set "Output directory=from_above"
holds from_above 1.25 0.01
head -2 from_above/factor_of_safety.csv | tail -1 | grep -q "^1,2.00000000,0,displacement," ||
  fail "the first trial from above did not fail on its displacement"

# 3. The files of the bracket's trials.
run --set "Output directory=files" --set "Output/Interval=1"
[ -L files/last_stable ] && [ -L files/first_failed ] || fail "no links to the bracket's trials"
/usr/bin/python3 - files <<'EOF' || fail "the bracket's point files"
import glob, math, os, sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
base = sys.argv[1]
def largest(directory):
    series = sorted(glob.glob(os.path.join(base, directory, "points_*.vtu")),
                    key=lambda f: int(f.rsplit("_", 1)[1].split(".")[0]))
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(series[-1])
    reader.Update()
    u = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("displacement"))
    return max(math.sqrt(sum(c * c for c in row)) for row in u)
stable, failed = largest("last_stable"), largest("first_failed")
print("largest displacement: last stable %.3e m, first failed %.3e m" % (stable, failed))
sys.exit(not (stable <= 1e-3 < failed))
EOF
n_trials=$(ls -d files/trial_* | wc -l)
run --set "Output directory=files" --set "Strength reduction/Tolerance=0.2"
n_again=$(ls -d files/trial_* | wc -l)
[ "$n_again" -lt "$n_trials" ] || fail "the second search kept the first one's trials ($n_again of $n_trials)"

# 4. No displacement limit: points leave the grid, the trial fails.
run --set "Strength reduction/Failure displacement=0" --set "Output directory=no_limit"
grep -q "fails (left the grid)" log.txt || fail "no trial failed by leaving the grid"
read -r low high < <(bracket no_limit)
/usr/bin/python3 -c "import sys; sys.exit(not float(sys.argv[1]) > 1.5)" "$low" ||
  fail "without a displacement limit the block stood only up to $low"

# 6. The block in 3D.
run --set "Dimension=3" --set "Gravity/Acceleration=0, 0, -10" \
  --set "Grid/Lower corner=0, 0, 0" --set "Grid/Upper corner=2, 2, 1.5" \
  --set "Grid/Number of cells=4, 4, 3" --set "Grid/Condition y-=roller" \
  --set "Grid/Condition z-=roller" --set "Body 1/Lower corner=0, 0, 0" \
  --set "Body 1/Upper corner=1, 1, 1" --set "Traction/Boundary=z+" \
  --set "Traction/Traction=0, 0, -16000" --set "Output directory=in_3d"
holds in_3d 1.25 0.01

# 7. A failure displacement below the elastic settlement.
"${launcher[@]}" "$impm" "$scene" --set "Output directory=elastic" \
  --set "Strength reduction/Failure displacement=1e-9" > log.txt 2>&1 &&
  fail "a failure displacement below the elastic settlement was accepted"
grep -q "^Error: Strength reduction: the trials at F = 1.000000 and F = 0.666667 failed alike (a point moved .* m by the load factor .* in both): the displacement does not depend on the strength" log.txt ||
  { cat log.txt; fail "no line saying the failure does not depend on the strength"; }
[ "$(grep -c '^Error' log.txt)" = 1 ] && [ "$(grep -c . elastic/factor_of_safety.csv)" = 3 ] ||
  fail "not one error line after two trials"

# 5. A load step that cannot be solved.
scene=$2/strength_reduction_slope.prm
run --set "Output directory=load_step" --set "Strength reduction/Failure displacement=0" \
  --set "Strength reduction/First factor=2.5" --set "Strength reduction/Bracket ratio=3" \
  --set "Strength reduction/Tolerance=10" --set "Output/Interval=1000"
grep -q "^trial  1: F = 2.500000  fails (load step)" log.txt || fail "F = 2.5 did not fail on a load step"
grep -q "^Error: Load step .* Newton" load_step/first_failed/terminal.txt || fail "no error in the trial's terminal.txt"
last=$(ls load_step/first_failed/points_*.pvtu load_step/first_failed/points_*.vtu 2>/dev/null |
  sed 's/.*points_0*\([0-9][0-9]*\)\..*/\1/' | sort -n | tail -1)
steps=$(sed -n 's/.* (load [0-9.]*, \([0-9]*\) steps.*/\1/p' log.txt | head -1)
[ -n "$last" ] && [ "$last" = "$steps" ] ||
  fail "the failed trial's last point file is of step '$last', its last converged step $steps"
echo "strength reduction hard cases: passed"
