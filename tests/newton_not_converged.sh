#!/usr/bin/env bash
# Runs newton_not_converged.prm, which must stop at its Newton iteration limit
# with the message naming the load step, the load factors, the cause and the
# residuals of the attempt; then checks the test's premise, that the same scene
# converges when four iterations are allowed.
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
echo "newton_not_converged: the run stopped at the iteration limit with a clear error"
