#!/usr/bin/env bash
# The AMG hierarchy kept over a load step's Newton iterations
# ('Solver/AMG reuse factor'). The collapse (prm/collapse.prm) at
# h = 0.25 m, 2x2 points per cell, gravity 6 of 10 kN/m^3 in 24 steps, with
# GMRES and AMG (about 2,200 system DoFs: ML builds more than one level):
#  * factor 0 builds a hierarchy for every solve;
#  * factor 2 builds at least one for each new matrix (a load step whose
#    setup keeps the matrix of the step before keeps the hierarchy too:
#    8 of this run's 26 setups) and fewer than one per solve;
#  * factor 0.6 keeps a hierarchy only after a solve of at most 6
#    iterations and lets a kept one try 12 iterations: some solves fail
#    with a kept hierarchy and are repeated with a new one;
#  * all three reach the full load with the same load factors and the same
#    reactions (numdiff at the suite's tolerances): keeping the hierarchy
#    changes the cost of a solve, not what Newton converges to.
# Usage: amg_reuse.sh IMPM PRM_DIRECTORY [MPIEXEC N]
scenes=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
for factor in 0 2 0.6; do
  "${launcher[@]}" "$impm" "$scenes/collapse.prm" \
    --set "Grid/Number of cells=64, 32" \
    --set "Body 1/Points per cell direction=2" \
    --set "Gravity/Acceleration=0, -6" --set "Solver/Load steps=24" \
    --set "Solver/Linear solver=GMRES with AMG" \
    --set "Solver/AMG reuse factor=$factor" \
    --set "Output/Interval=0" --set "Output directory=factor$factor" > "log$factor.txt" 2>&1 ||
    { cp "log$factor.txt" log.txt; fail "the run with factor $factor failed"; }
  # The converged steps' load factors and reactions in units of 1e5 N (the
  # body weighs 3.84e5 N; the Newton tolerance leaves ~1e-4 N of noise).
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "converged") c = i;
                       if ($i == "load_factor") load = i;
                       if ($i ~ /^reaction_/) reaction[i] = 1 } next }
           $c == 1 { line = $load; for (i = 1; i <= NF; ++i) if (reaction[i])
                       line = line sprintf(" %.9e", $i / 1e5);
                     print line }' "factor$factor/steps.csv" > "states$factor.txt"
  [ "$(tail -1 "states$factor.txt" | cut -d' ' -f1)" = 1 ] ||
    { cp "log$factor.txt" log.txt; fail "factor $factor did not reach the full load"; }
done
statistics() {
  sed -n 's/^AMG hierarchy built for \([0-9]*\) of \([0-9]*\) GMRES solves (\([0-9]*\) repeated.*/\1 \2 \3/p' "log$1.txt"
}
read -r builds0 solves0 repeated0 <<< "$(statistics 0)"
read -r builds2 solves2 repeated2 <<< "$(statistics 2)"
read -r builds06 solves06 repeated06 <<< "$(statistics 0.6)"
setups=$(sed -n 's/^sparsity pattern kept in [0-9]* of \([0-9]*\) load-step setups$/\1/p' log2.txt)
kept=$(sed -n 's/^sparsity pattern kept in \([0-9]*\) of [0-9]* load-step setups$/\1/p' log2.txt)
echo "factor 0: $builds0 hierarchies for $solves0 solves; factor 2: $builds2 for $solves2" \
  "($setups load-step setups, $kept of them kept the matrix); factor 0.6: $builds06 for" \
  "$solves06, $repeated06 repeated"
[ -n "$solves0" ] && [ "$builds0" -eq "$solves0" ] && [ "$repeated0" -eq 0 ] ||
  fail "factor 0 did not build a hierarchy for every solve"
[ -n "$solves2" ] && [ -n "$setups" ] && [ -n "$kept" ] &&
  [ "$builds2" -ge $((setups - kept)) ] && [ "$builds2" -lt "$solves2" ] ||
  fail "factor 2 did not keep its hierarchies, or kept one over a new matrix"
[ -n "$solves06" ] && [ "$repeated06" -gt 0 ] ||
  fail "factor 0.6 repeated no solve"
compare states2.txt states0.txt "factor 2 converged to other states than factor 0"
compare states0.6.txt states0.txt "factor 0.6 converged to other states than factor 0"
echo "amg_reuse: fewer hierarchies, the same converged states"
