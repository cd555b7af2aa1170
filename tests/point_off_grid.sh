#!/usr/bin/env bash
# Runs point_off_grid.prm, which must fail, and checks the error message and
# that the output written before the failure is complete.
# Usage: point_off_grid.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"

"${launcher[@]}" "$impm" "$scene" > log.txt 2>&1 && fail "the run did not stop"
grep -q "Load step 3: material point [0-9]* (initially at 0.[27]5 0.75) moved to" log.txt ||
  fail "no error naming the step, the point and its positions"
grep -q "outside the background grid \[0 0\] - \[1 10\]" log.txt ||
  fail "the error does not name the grid"

# steps.csv: a header and one complete row for each of the 2 converged steps.
[ "$(wc -l < results/steps.csv)" -eq 3 ] || fail "steps.csv does not hold 2 steps"
columns=$(head -1 results/steps.csv | tr ',' '\n' | wc -l)
awk -F, -v n="$columns" 'NF != n { exit 1 }' results/steps.csv ||
  fail "a row of steps.csv is incomplete"
# The point files of steps 0-2, each complete, and a .pvd naming them.
for step in 00000 00001 00002; do
  grep -q "</VTKFile>" "results/points_$step.pvtu" || fail "points_$step.pvtu incomplete"
  grep -q "points_$step.pvtu" results/points.pvd || fail "points.pvd lacks step $step"
  for piece in results/points_$step.*.vtu; do
    grep -q "</VTKFile>" "$piece" || fail "$piece incomplete"
  done
done
grep -q "</VTKFile>" results/points.pvd || fail "points.pvd incomplete"
[ -z "$(ls results | grep '\.tmp$')" ] || fail "temporary files left behind"
echo "point_off_grid: the run stopped with a clear error, output intact"
