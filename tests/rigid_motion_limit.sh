#!/usr/bin/env bash
# The rigid bodies' motion per load step (issue 31), on the plate of
# contact_plate_compression.prm (block [0,1]^2 m, h = 0.125 m, a 0.25 m
# plate on its top; S = 1e6 Pa, L = 0.125 m):
# * the plate moved 1.25 m down in one step, through the 1 m block: with
#   'Rigid contact/Maximum motion per step' = 0 (no limit) it passes
#   unseen (0 Newton iterations, zero force, exit status 0: what issue 31
#   found); with the default limit of 1 cell the first attempt is refused
#   ("moves by 10 cell sizes"), the steps are cut, the plate crushes the
#   block and the run stops with an error (non-zero status), as it must:
#   no state has the plate below the block;
# * the plate starting 0.5 m (4 cells) above the block and moved 0.75 m in
#   one step: the attempts of 3 and 1.5 cells are refused, and the cut
#   steps end in the compression test's state: the force on the plate
#   3.3626 S L (contact_plate_compression.output: 3.362624 in 10 steps,
#   whose header checks it by hand: sigma_yy = -0.371680 S with the
#   penalty) to 1e-4 relative, here 3.362511 (the faces' area taken at the
#   start of each step, 2e-5 there), and the largest vertical stress
#   -0.371680 S to 1e-4;
# * a rigid body moved sideways out of the grid: one line "Error: Load step
#   1 ...: Rigid body 1 leaves the grid" and a non-zero status, no step
#   line;
# * a small punch moved into the block without the limit: refused by the
#   tunnelling check (material points left inside it).
# Usage: rigid_motion_limit.sh IMPM contact_plate_compression.prm [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
plate() { sed -e 's/Check tangent = true/Check tangent = false/' \
              -e 's/Load steps = 10/Load steps = 1/' "$scene" "$@"; }
run() { "${launcher[@]}" "$impm" "$@"; }
value() { awk -v key="$2" '$0 ~ key { print $NF }' "$1" | tail -1; }

# The plate through the block.
plate -e 's/Displacement = 0, -0.25/Displacement = 0, -1.25/' > through.prm
run through.prm --set "Rigid contact/Maximum motion per step=0" > log.txt 2>&1 ||
  fail "without the limit the plate through the block did not end with status 0"
grep -q "^step   1  load 1.0000  iterations 0 .* R1y 0.000000" log.txt ||
  fail "without the limit the plate did not pass unseen (what the limit is for)"
rm -rf results
run through.prm > log.txt 2>&1 && fail "the plate through the block ended with status 0"
grep -q "^Error: Load step [0-9]* (from load factor" log.txt ||
  fail "the plate through the block did not stop with a load step's error"
grep -q "load 1 (increment 1): step refused: Rigid body 1 moves by 10 cell sizes in this step, more than 'Rigid contact/Maximum motion per step' = 1" log.txt ||
  fail "the first attempt was not refused by the motion limit"
grep -qE "Stacktrace|An error occurred|MPI_ABORT" log.txt && fail "a raw report"

# The plate from 4 cells above, 6 cells in one step.
rm -rf results
plate -e 's/Upper corner    = 1.5, 1.5/Upper corner    = 2, 2/' \
      -e 's/Number of cells = 12, 12/Number of cells = 16, 16/' \
      -e 's/Lower corner = -0.25, 1$/Lower corner = -0.25, 1.5/' \
      -e 's/Upper corner = 1.75, 1.25/Upper corner = 1.75, 1.75/' \
      -e 's/Displacement = 0, -0.25/Displacement = 0, -0.75/' > gap.prm
run gap.prm > log.txt 2>&1 || fail "the plate from above failed"
grep -q "step refused: Rigid body 1 moves by 3 cell sizes" log.txt ||
  fail "the attempt of 3 cells was not refused"
force=$(awk '/^final force on Rigid body 1/ { sub(",", "", $10); print $10 }' log.txt)
stress=$(value log.txt "^largest vertical stress")
/usr/bin/python3 -c "
import sys
force, stress = float('$force'), float('$stress')
assert abs(force / 3.362624 - 1) < 1e-4, force
assert abs(stress / -0.371680 - 1) < 1e-4, stress
" || fail "the plate from above ends at force $force S L, stress $stress S"

# A small punch (0.2 x 0.15 m, 0.3 m above the block) moved 0.75 m down in
# one step without the motion limit: no face of the block is near it at
# the start of the step, so no contact probe sees it; the attempts whose
# Newton solve converges leave material points inside it and are refused
# by the tunnelling check (deeper than 1/alpha = 0.01 cells), the cut steps
# crush the block under the punch and the run stops with an error.
rm -rf results
plate -e 's/Lower corner = -0.25, 1$/Lower corner = 0.4, 1.3/' \
      -e 's/Upper corner = 1.75, 1.25/Upper corner = 0.6, 1.45/' \
      -e 's/Displacement = 0, -0.25/Displacement = 0, -0.75/' > punch.prm
run punch.prm --set "Rigid contact/Maximum motion per step=0" > log.txt 2>&1 &&
  fail "the punch through the block ended with status 0"
grep -qE "step refused: the domain of the material point at \([0-9. ]*\) lies [0-9.]* cell sizes inside Rigid body 1 after this step, deeper than the contact lets a face in \(0.01\): the body passed into the material \(tunnelling\)" log.txt ||
  fail "no attempt was refused by the tunnelling check"
[ "$(grep -c "^Error" log.txt)" -eq 1 ] || fail "not one error line"
grep -qE "Stacktrace|An error occurred|MPI_ABORT" log.txt && fail "a raw report"

# A body moved sideways out of the grid.
rm -rf results
plate -e 's/Lower corner = -0.25, 1$/Lower corner = 1.1, 1.1/' \
      -e 's/Upper corner = 1.75, 1.25/Upper corner = 1.4, 1.4/' \
      -e 's/Displacement = 0, -0.25/Displacement = 2, 0/' \
      -e 's/Load steps = 1$/Load steps = 2/' > sideways.prm
run sideways.prm > log.txt 2>&1 && fail "the body moved out of the grid ended with status 0"
grep -q "^Error: Load step 1 (from load factor 0 to 0.5): Rigid body 1 leaves the grid in this step: its box \[2.1, 2.4\] x \[1.1, 1.4\] m does not meet the grid \[0, 1.5\] x \[0, 1.5\] m" log.txt ||
  fail "no line saying that the body left the grid"
[ "$(grep -c "^Error" log.txt)" -eq 1 ] || fail "more than one error line"
grep -q "^step" log.txt && fail "a step line before the error"
grep -qE "Stacktrace|An error occurred|MPI_ABORT" log.txt && fail "a raw report"
echo "rigid_motion_limit: the plate through the block stopped, the plate from above converged in cut steps, the punch passed into the block refused by the tunnelling check, the body out of the grid refused"
