#!/usr/bin/env bash
# Load balance on two processes: the collapse's block fills the left half of
# the grid, so the cell partition puts every point on one process. The run
# must repartition the grid by the points' cell weights at the start (both
# processes then write a piece of the points at step 0), and give the same
# summary as without repartitioning and as on one process.
# Usage: load_balance.sh IMPM SCENE MPIEXEC 2
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"

"${launcher[@]}" "$impm" "$scene" --set "Testing/Enabled=false" \
  --set "Output/Interval=1" > log.txt 2>&1 || fail "the run failed"
grep -qE "repartitioned: most points on a process / mean 2 -> 1(\.0[0-9]*)?$" log.txt ||
  fail "no repartition from all points on one process to a balance"
for piece in 0000 0001; do
  [ -e "results/points_00000.$piece.vtu" ] || fail "process $piece holds no points at step 0"
done

"${launcher[@]}" "$impm" "$scene" > balanced.txt 2>&1 || fail "the balanced run failed"
"${launcher[@]}" "$impm" "$scene" --set "Material points/Load imbalance threshold=3" \
  > unbalanced.txt 2>&1 || fail "the unbalanced run failed"
"$impm" "$scene" > serial.txt 2>&1 || fail "the serial run failed"
[ "$(grep -c '^step ' serial.txt)" -gt 4 ] || fail "the serial run printed no steps"
compare balanced.txt unbalanced.txt "repartitioning changed the results"
compare balanced.txt serial.txt "two processes differ from one"
echo "load_balance: repartitioned at the start, same results"
