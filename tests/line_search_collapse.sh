#!/usr/bin/env bash
# 'Solver/Line search' on a hard case: the granular column collapse
# (prm/granular_column_collapse.prm) at aspect ratio 7 (1 m x 7 m,
# phi = 35.26, h = 0.1 m), 5 steps of 0.01 s without step control, on
# MPIEXEC N processes if given:
#  1. with full Newton steps, step 4's residual cycles between 2e-4 and
#     2.7e-4 (points changing return region as the column spreads) to the
#     iteration limit: the run stops with one line that says Newton
#     cycles far above the round-off and names 'Solver/Line search';
#  2. with the line search every step converges (no cut), and the
#     line-search residuals are counted on the terminal and in
#     summary.json.
# Usage: line_search_collapse.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() {
  local name=$1
  shift
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" \
    --set "Grid/Upper corner=12.6, 7.25" --set "Grid/Number of cells=126, 73" \
    --set "Body 1/Upper corner=1, 7" --set "Time/End time=0.05" --set "Solver/Load steps=5" \
    --set "Output/Interval=0" --set "Body 1/Material/Mohr-Coulomb/Friction angle=35.26" \
    --set "Solver/Step control=false" "$@" > "$name.txt" 2>&1
}
if run full_steps; then
  cp full_steps.txt log.txt
  fail "full Newton steps converged where they cycle"
fi
[ "$(grep -c '^Error: ' full_steps.txt)" = 1 ] || { cp full_steps.txt log.txt; fail "not one error line"; }
grep -qE "^Error: Load step 4 .*Newton iteration limit\. Its residual stalled at .* far above the round-off of the internal forces .*: Newton cycles between iterates.*'Solver/Line search = true'" full_steps.txt ||
  { cp full_steps.txt log.txt; fail "the error does not name the cycling and the line search"; }
run searched --set "Solver/Line search=true" || { cp searched.txt log.txt; fail "the run with the line search failed"; }
grep -qE "^Finished .*: 5 load steps \(0 cuts\), [0-9]+ Newton iterations \(and [1-9][0-9]* line-search residuals\)" searched.txt ||
  { cp searched.txt log.txt; fail "not 5 steps without a cut, with line-search residuals"; }
/usr/bin/python3 -c "
import json, sys
s = json.load(open('searched/summary.json'))
sys.exit(0 if s['line_search_evaluations'] > 0 and s['load_step_cuts'] == 0 else 1)" ||
  fail "summary.json does not count the line-search residuals"
echo "line_search_collapse: passed"
