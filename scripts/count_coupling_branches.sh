#!/usr/bin/env bash
# Counts the branches of the load-step code that name a coupling (issue 30):
# lines of LoadStepProblem, LoadStepSystem, the Assembler and MPMSolver
# (headers and sources) with an 'if', a '?:' or a '&&'/'||' condition that
# names ghost stabilisation, F-bar, cell pressures, rigid contact, rigid
# bodies' unknowns or springs. Usage: scripts/count_coupling_branches.sh
# [REVISION] (default: the work tree).
set -eu
revision=${1:-}
files="include/impm/solver/load_step_problem.h source/solver/load_step_problem.cc
include/impm/system/load_step_system.h source/system/load_step_system.cc
include/impm/assembly/assembler.h source/assembly/assembler.cc
include/impm/simulator/mpm_solver.h source/simulator/mpm_solver.cc"
names='f_bar|FBar|rigid_contact|RigidContact|ghost_stabilisation|GhostStabilisation|has_unknowns|pressure|with_pressures|rigid_bodies|spring|Spring'
total=0
for f in $files; do
  if [ -n "$revision" ]; then text=$(git show "$revision:$f"); else text=$(cat "$f"); fi
  n=$(printf '%s\n' "$text" | grep -E "\bif \(|\?|&&|\|\|" | grep -cE "$names" || true)
  printf '%4d  %s\n' "$n" "$f"
  total=$((total + n))
done
echo "total: $total"
