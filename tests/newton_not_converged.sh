#!/usr/bin/env bash
# Runs newton_not_converged.prm, which must stop at its Newton iteration limit
# with the message naming the load step, the load factors, the cause and the
# residuals of the attempt; then checks the test's premise, that the same scene
# converges when four iterations are allowed. In time (quasi-static, End time
# 2 s), the messages give the times in seconds, and the limit of the step
# control 'Minimum load step' times the end time.
# Usage: newton_not_converged.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"

"$impm" "$scene" > log.txt 2>&1 && fail "the run did not stop"
grep -qF "Error: Load step 1 (from load factor 0 to 1): Newton iteration limit. Relative residuals:" log.txt ||
  fail "no error naming the load step and the iteration limit"
# Three residuals (the start and two iterations), decreasing.
grep -qE "^  load 1 \(increment 1\): iteration limit, relative residuals: 1 0\.[0-9]+ 0\.0[0-9]+$" log.txt ||
  fail "the attempt's residuals are not listed"
# steps.csv holds the one failed attempt, marked unconverged after 2 iterations.
[ "$(wc -l < results/steps.csv)" -eq 2 ] || fail "steps.csv does not hold one attempt"
tail -1 results/steps.csv | grep -q "^1,1,1,0,2," || fail "the attempt is not marked unconverged"
[ -e results/summary.json ] && fail "a summary was written for a failed run"

"$impm" "$scene" --set "Solver/Maximum iterations=4" > log.txt 2>&1 ||
  fail "with four iterations allowed the scene does not converge"
grep -q "^step   1  load 1.0000  iterations [34]$" log.txt ||
  fail "with four iterations allowed the step does not converge in 3 or 4"
# The same scene in time: the load step, the attempts and the smallest step
# in seconds (0.3 of 2 s: 2 s and 1 s tried, 0.5 s would be below 0.6 s).
"$impm" "$scene" --set "Time/End time=2" > log.txt 2>&1 && fail "the run in time did not stop"
grep -qF "Error: Load step 1 (from t = 0 s to 2 s): Newton iteration limit. Relative residuals:" log.txt ||
  fail "in time: no error naming the step's times"
grep -qE "^  t 2 s \(step 2 s\): iteration limit, relative residuals: 1 0\.[0-9]+ 0\.0[0-9]+$" log.txt ||
  fail "in time: the attempt is not listed in seconds"
"$impm" "$scene" --set "Time/End time=2" --set "Solver/Maximum iterations=1" \
  --set "Solver/Step control=true" --set "Solver/Minimum load step=0.3" > log.txt 2>&1 &&
  fail "the run in time with step control did not stop"
grep -qF "Error: Load step 1 (from t = 0 s to 1 s): Newton iteration limit. The time step would fall below 'Solver/Minimum load step' times 'Time/End time' = 0.6 s. Attempts:" log.txt ||
  fail "in time: the step control's limit is not given in seconds"
[ "$(grep -c "^  t [12] s (step [12] s): iteration limit" log.txt)" -eq 2 ] ||
  fail "in time: the two attempts (2 s and 1 s) are not listed"
echo "newton_not_converged: the run stopped at the iteration limit with a clear error"
