#!/usr/bin/env bash
# Load balance on two processes. The collapse's block fills the left half of
# the grid, so the grid's own partition would put every point on one
# process: the grid is first partitioned by the points each cell will
# receive, and each process seeds half of them (no repartition at the
# start, both processes write 288 of the 576 points at step 0). With
# 'Load imbalance threshold' = 1 the grid is repartitioned by the points'
# cell weights whenever they drift out of balance; the results are the same
# as without repartitioning and as on one process.
# Usage: load_balance.sh IMPM SCENE MPIEXEC 2
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"

"${launcher[@]}" "$impm" "$scene" --set "Testing/Enabled=false" \
  --set "Output/Interval=1" > log.txt 2>&1 || fail "the run failed"
! grep -q "repartitioned" <(sed -n '1,/^step /p' log.txt) ||
  fail "the points were seeded out of balance and repartitioned at the start"
for piece in 0000 0001; do
  grep -q 'NumberOfPoints="288"' "results/points_00000.$piece.vtu" ||
    fail "process $piece does not hold half the points at step 0"
done

"${launcher[@]}" "$impm" "$scene" --set "Testing/Enabled=false" \
  --set "Material points/Load imbalance threshold=1" \
  --set "Output directory=eager" > log.txt 2>&1 || fail "the eager run failed"
grep -qE "repartitioned: most points on a process / mean [0-9.]+ -> 1(\.0[0-9]*)?$" log.txt ||
  fail "no repartition with threshold 1"

"${launcher[@]}" "$impm" "$scene" > balanced.txt 2>&1 || fail "the balanced run failed"
"${launcher[@]}" "$impm" "$scene" --set "Material points/Load imbalance threshold=1" \
  --set "Output directory=eager" --overwrite > eager.txt 2>&1 ||
  fail "the eagerly balanced run failed"
"${launcher[@]}" "$impm" "$scene" --set "Material points/Load imbalance threshold=3" \
  > unbalanced.txt 2>&1 || fail "the unbalanced run failed"
"$impm" "$scene" > serial.txt 2>&1 || fail "the serial run failed"
[ "$(grep -c '^step ' serial.txt)" -gt 4 ] || fail "the serial run printed no steps"
compare balanced.txt eager.txt "repartitioning changed the results"
compare balanced.txt unbalanced.txt "the threshold changed the results"
compare balanced.txt serial.txt "two processes differ from one"
echo "load_balance: seeded in balance, repartitioned when the points drift, same results"
