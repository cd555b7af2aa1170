#!/usr/bin/env bash
# The ghost penalty of the mass (issue 33, 'Inertia/Mass ghost penalty'),
# on the vibrating bar of tests/vibrating_bar.prm (v0 = 0.1 m/s, first-mode
# period 10 s), whose tip cell is barely filled whenever the bar is
# stretched (the last points' GIMP domains reach into it):
#  1. consistent mass, trapezoidal rule, 500 steps a period: the
#     matrix is dominated by the mass (c_1 M), so the stiffness's ghost
#     penalty no longer keeps it well conditioned: the worst condition
#     estimate is above 1e4 (3.5e4; 1.4e5 at 1000 steps a period) without
#     the mass penalty and below 300 with gamma_m = 0.1 (125); the bar's
#     answers stay (tests/
#     vibrating_bar_check.py over 1.6 periods: the tip within 2.5 % of the
#     amplitude, 1.8 % either way; the period within 5e-3; the energy
#     within 1e-4 at every step: the penalty acts on the increment and
#     puts no energy in), and
#     the two runs' tip displacements differ by less than 1e-3 of the
#     amplitude at every step;
#  2. the same with the lumped mass (7.1e4 -> 141; the energy within 1e-3,
#     the lumped mapping's loss, 3.4e-4 either way);
#  3. generalised-alpha, consistent mass, the first 10 steps (the tip
#     moving out into its cell): the matrix with the penalty agrees with
#     central differences of the forces (Testing/Check tangent), and the
#     penalty acts in those steps (the condition estimate 1e5 without it,
#     1e2 with it).
# Usage: mass_ghost_penalty.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
condition() { # condition NAME: the run's worst condition estimate
  /usr/bin/python3 -c "import json, sys; print(json.load(open(sys.argv[1] + '/summary.json'))['worst_condition_estimate'])" "$1"
}
run() { # run NAME GAMMA [--set ...]: the bar in directory NAME
  local name=$1 gamma=$2
  shift 2
  rm -rf "$name"
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" \
    --set "Solver/Estimate condition number=true" --set "Inertia/Mass ghost penalty=$gamma" \
    "$@" > "$name.log" 2>&1 || fail "the run $name failed"
}
bounded() { # bounded NAME LOW HIGH: LOW < the condition estimate < HIGH
  local c
  c=$(condition "$1")
  /usr/bin/python3 -c "import sys; sys.exit(not ($2 < float(sys.argv[1]) < $3))" "$c" ||
    fail "$1: the worst condition estimate $c is not between $2 and $3"
  printf '%s: worst condition estimate %.3g (between %s and %s)\n' "$1" "$c" "$2" "$3"
}
# 1.6 periods: the period from the downward zero crossings at 5 and 15 s.
period=(--set "Time/End time=16" --set "Solver/Load steps=800")
# On two processes the consistent mass only (the lumped case adds no
# parallel code).
masses=$([ ${#launcher[@]} = 0 ] && echo "consistent lumped" || echo consistent)
for mass in $masses; do
  energy=$([ $mass = consistent ] && echo 1e-4 || echo 1e-3)
  run "${mass}_without" 0 "${period[@]}" --set "Inertia/Mass=$mass"
  run "${mass}_with" 0.1 "${period[@]}" --set "Inertia/Mass=$mass"
  bounded "${mass}_without" 1e4 1e7
  bounded "${mass}_with" 10 300
  for name in "${mass}_without" "${mass}_with"; do
    /usr/bin/python3 "$here/vibrating_bar_check.py" "$name" 16 0.1 2.5e-2 "$energy" > check.txt ||
      { sed "s/^/$name: /" check.txt; fail "the bar ($name) differs from its analytical solution"; }
    sed "s/^/$name: /" check.txt
  done
  /usr/bin/python3 - "${mass}_without" "${mass}_with" <<'PY' || fail "the penalty changed the bar's motion ($mass mass)"
import csv, math, sys
u = [[float(r["displacement_x"]) for r in csv.DictReader(open(d + "/point_history.csv"))]
     for d in sys.argv[1:]]
amplitude = 0.1 / (math.pi * 10 / 50) * math.sin(math.pi * 24.75 / 50)
difference = max(abs(a - b) for a, b in zip(*u)) / amplitude
print("%s against %s: the tip's largest difference / amplitude %.1e (below 1e-3)"
      % (sys.argv[2], sys.argv[1], difference))
sys.exit(len(u[0]) != len(u[1]) or len(u[0]) < 800 or difference >= 1e-3)
PY
done
start=(--set "Time/End time=0.1" --set "Solver/Load steps=10" --set "Inertia/Mass=consistent"
  --set "Inertia/Integrator=generalised-alpha" --set "Testing/Enabled=true" --set "Testing/Check tangent=true")
run start_without 0 "${start[@]}"
run start_with 0.1 "${start[@]}"
grep -q "every assembled matrix agrees with central differences of the internal force to 1e-6: yes" start_with.log ||
  fail "the mass penalty's matrix differs from central differences"
echo "start_with: every matrix agrees with central differences"
bounded start_without 1e4 1e7
bounded start_with 10 1e3
echo "mass_ghost_penalty: passed"
