#!/usr/bin/env bash
# The residual floor: a block compressed 10 % by a prescribed face under a
# gravity of 1e-3 m/s^2 has |f_ext| about 1e-7 of the internal forces, so
# 'Solver/Tolerance' = 1e-9 |f_ext| lies below their round-off. Without
# 'Solver/Absolute tolerance' the step must fail with the message saying so
# (and naming the entry); with it at 1e-6 N every step converges in a few
# iterations, to the state of the same block without gravity (the printed,
# scaled stresses within 1e-4).
# Usage: residual_floor.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
tiny_gravity=(--set "Gravity/Enabled=true" --set "Gravity/Acceleration=0, -1e-3"
              --set "Solver/Load steps=4" --overwrite)

"$impm" "$scene" "${tiny_gravity[@]}" --set "Solver/Step control=false" > log.txt 2>&1 &&
  fail "the run converged below round-off"
grep -qE "^Error: Load step 1 .*Newton iteration limit\. Its residual \([0-9.e+-]+ N\) is at the round-off level of the internal forces \([0-9.e+-]+ N\): set 'Solver/Absolute tolerance' above it\." log.txt ||
  fail "the failure does not name the round-off and the entry"

"$impm" "$scene" "${tiny_gravity[@]}" --set "Solver/Absolute tolerance=1e-6" > log.txt 2>&1 ||
  fail "with an absolute tolerance the run failed"
[ "$(grep -cE '^step +[1-4]  load [0-9.]+  iterations [2-6]$' log.txt)" -eq 4 ] ||
  fail "not all four steps converged in 2 to 6 iterations"
grep -v "^step \|mass\|gravity\|Newton iterations\|reactions balance" log.txt > with_gravity.txt
"$impm" "$scene" --set "Solver/Load steps=4" --overwrite > reference.txt 2>&1 ||
  fail "the reference run failed"
grep -v "^step \|mass\|gravity\|Newton iterations\|reactions balance" reference.txt > without_gravity.txt
numdiff -q -a 1e-4 -s ' \t\n=,:;<>[](){}^' without_gravity.txt with_gravity.txt > /dev/null ||
  { diff without_gravity.txt with_gravity.txt; fail "the state differs from the block without gravity"; }
echo "residual_floor: the failure names the round-off; the absolute tolerance converges"
