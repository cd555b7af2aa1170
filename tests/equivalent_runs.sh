#!/usr/bin/env bash
# Two claims of the suite, checked by running both sides (not by comparing
# stored outputs):
#  1. the updated Lagrangian form gives the same iterates as the previously
#     converged one: column_updated_lagrangian.prm and
#     column_gimp_plastic_16.prm print the same summary;
#  2. the 3D column with rollers on its four sides is the plane-strain column:
#     column_3d_gimp_plastic_8.prm and column_gimp_plastic_8.prm print the
#     same step lines, Newton counts, vertical extent, stresses and reactions
#     (the vertical axis is z in 3D and y in 2D; the 3D printout has an extra
#     coordinate and the y faces' lateral reactions);
#  3. the MUMPS direct solver gives the same iterates as KLU;
#  4. GMRES with AMG, with its tolerance tied to the Newton residual, gives
#     the same steps, iterations and final state as KLU on the collapse
#     (it estimates no condition number).
# Values are compared with numdiff at the suite's tolerances.
# Usage: equivalent_runs.sh IMPM TESTS_DIRECTORY [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
compare() {
  numdiff -q -a 1e-6 -r 1e-8 -s ' \t\n=,:;<>[](){}^' "$1" "$2" > /dev/null ||
    { diff "$1" "$2"; fail "$3"; }
}
run() { "${launcher[@]}" "$impm" "$tests/$1.prm" --overwrite > "$1.txt" 2> /dev/null || fail "$1 did not run"; }

run column_updated_lagrangian
run column_gimp_plastic_16
[ "$(grep -c '^step ' column_gimp_plastic_16.txt)" -eq 50 ] || fail "the 2D column did not print its 50 steps"
compare column_updated_lagrangian.txt column_gimp_plastic_16.txt \
  "the updated Lagrangian form differs from the previously converged one"

run column_3d_gimp_plastic_8
run column_gimp_plastic_8
# The vertical axis becomes V; lines without a plane-strain counterpart go.
sed -e '/^extent in [xy]/d' -e '/^scales/d' -e '/^total mass/d' \
    -e '/reaction on face y[-+]/d' \
    -e 's/extent in z/extent in V/' -e 's/face z-, component z/face V-, component V/' \
    -e 's/^material points: [0-9]*, //' \
    -e 's/X = [^,]*,//' -e 's/u = [^ ]* [^ ]* \([^,]*\)/u = \1/' \
    column_3d_gimp_plastic_8.txt > column_3d.txt
sed -e '/^extent in x/d' -e '/^scales/d' -e '/^total mass/d' \
    -e 's/extent in y/extent in V/' -e 's/face y-, component y/face V-, component V/' \
    -e 's/^material points: [0-9]*, //' \
    -e 's/X = [^,]*,//' -e 's/u = [^ ]* \([^,]*\)/u = \1/' \
    column_gimp_plastic_8.txt > column_2d.txt
[ "$(grep -c '^step ' column_2d.txt)" -eq 50 ] || fail "the plane-strain column did not print its 50 steps"
grep -q "face V-, component V" column_2d.txt || fail "no base reaction printed"
compare column_3d.txt column_2d.txt "the 3D column differs from the plane-strain one"
"${launcher[@]}" "$impm" "$tests/column_gimp_plastic_8.prm" \
  --set "Solver/Linear solver=MUMPS" > column_mumps.txt 2> /dev/null || fail "the MUMPS run failed"
compare column_mumps.txt column_gimp_plastic_8.txt "MUMPS differs from KLU"
run collapse_h1_4steps
"${launcher[@]}" "$impm" "$tests/collapse_h1_4steps.prm" \
  --set "Solver/Linear solver=GMRES with AMG" > collapse_gmres.txt 2> /dev/null ||
  fail "the GMRES run failed"
# GMRES estimates no condition number: that line alone may differ.
grep -v "^worst condition estimate" collapse_gmres.txt > gmres.txt
grep -v "^worst condition estimate" collapse_h1_4steps.txt > klu.txt
compare gmres.txt klu.txt "GMRES with AMG differs from KLU"
echo "equivalent_runs: the four pairs of runs agree"
