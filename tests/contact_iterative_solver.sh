#!/usr/bin/env bash
# Rigid contact with the iterative solver (issues 10 and 13): every contact
# test scene (tests/contact_*.prm: plates, floors, discs, cones, an STL
# surface, a body pushed by a force, a rolling disc) runs with GMRES and
# ML's AMG, its tolerance tied to the Newton residual, to the same printed
# answers as with KLU: steps, Newton iterations, cuts, forces, stresses
# (the tangent checks are off: they test the matrix, not the solver).
# The contact's matrix is not symmetric with friction, and a body pushed
# by a force adds a bordered block (a second right-hand side per Newton
# iteration, whose material part starts at zero).
# Usage: contact_iterative_solver.sh IMPM TESTS_DIRECTORY [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
n_scenes=0
for scene in "$tests"/contact_*.prm; do
  name=$(basename "$scene" .prm)
  for solver in direct "GMRES with AMG"; do
    rm -rf results*
    "${launcher[@]}" "$impm" "$scene" --set "Testing/Check tangent=false" \
      --set "Solver/Linear solver=$solver" > "run.txt" 2> /dev/null ||
      fail "$name did not run with '$solver'"
    # GMRES estimates no condition number: that line alone may differ.
    grep -v "^worst condition estimate" run.txt > "${name}_${solver// /_}.txt"
  done
  compare "${name}_direct.txt" "${name}_GMRES_with_AMG.txt" \
    "$name: GMRES with AMG differs from KLU"
  n_scenes=$((n_scenes + 1))
done
[ "$n_scenes" -ge 11 ] || fail "only $n_scenes contact scenes found"
echo "contact_iterative_solver: $n_scenes contact scenes give the same answers with GMRES and AMG"
