#!/usr/bin/env bash
# A restart in the middle of the vibration (issue 33): the vibrating bar
# (tests/vibrating_bar.prm) with generalised-alpha (spectral radius 0.8,
# which weighs the residual of each step's start) over 200 steps (two
# periods), v0 = 0.1 m/s,
#  1. without interruption: the reference steps.csv (its non-timing
#     columns: time, kinetic, strain and total energy, Newton iterations)
#     and point_history.csv;
#  2. with a checkpoint every 25 steps, stopped after step 60 (a quarter
#     period past a checkpoint, the bar moving) and resumed from step 50 on
#     MPIEXEC N processes if given: the same rows (numdiff at the suite's
#     tolerances). The points' velocities and accelerations come from the
#     checkpoint; a resumed run does not take its first acceleration from
#     the balance at its start, as a new run does.
# Usage: vibrating_bar_resume.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
settings=(--set "Time/End time=20" --set "Solver/Load steps=200"
  --set "Inertia/Integrator=generalised-alpha" --set "Inertia/Spectral radius=0.8"
  --set "Inertia/Initial velocity=0.1*sin(pi*x/50); 0")
"$impm" "$scene" "${settings[@]}" > log.txt 2>&1 || fail "the uninterrupted run failed"
untimed results/steps.csv > full_steps.csv
cp results/point_history.csv full_history.csv
[ "$(wc -l < full_steps.csv)" -eq 201 ] || fail "the reference has not 200 steps"
"$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=25" \
  --stop-after-step 60 > log.txt 2>&1 || fail "the first part failed"
grep -q "^control.converged steps = 50$" results/checkpoint/state.txt ||
  fail "the newest checkpoint is not that of step 50"
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=25" \
  --resume > log.txt 2>&1 || fail "the resumed run failed"
untimed results/steps.csv > resumed_steps.csv
[ "$(wc -l < resumed_steps.csv)" -eq 201 ] || fail "the resumed steps.csv has not 200 steps"
compare full_steps.csv resumed_steps.csv "the resumed vibration differs from the uninterrupted one"
compare full_history.csv results/point_history.csv "the resumed point history differs"
echo "vibrating_bar_resume: the run resumed at step 50 of 200 ends as the uninterrupted one"
