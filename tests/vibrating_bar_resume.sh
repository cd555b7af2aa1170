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
#     the balance at its start, as a new run does;
#  3. the same in explicit MUSL steps (400 steps of 0.05 s, a checkpoint
#     every 50, stopped after step 120, resumed from step 100): a resumed
#     run does not take the half step of a new run's first step, and its
#     energy balance (kept at each step's start) goes on as before;
#  4. finer steps after a resume (doc/running.md allows it): the
#     trapezoidal run in steps of 0.2 s to 20 s, stopped after step 30,
#     resumed from step 25 (t = 5 s) with 'Time/Time step' = 0.1: the
#     steps after the checkpoint take 0.1 s (t = 5.1, 5.2, ...) and the run
#     ends at 20 s after 25 + 150 steps. Until 2026-11-29 the checkpoint's
#     step size was kept: 100 steps of 0.2 s.
# Usage: vibrating_bar_resume.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
# resume_case NAME STEPS INTERVAL STOP SETTINGS...: the run of STEPS
# steps against the one stopped after step STOP and resumed from the last
# checkpoint before it (every INTERVAL steps).
resume_case() {
  local name=$1 steps=$2 interval=$3 stop=$4
  shift 4
  local settings=(--set "Time/End time=20" --set "Solver/Load steps=$steps" "$@"
    --set "Inertia/Initial velocity=0.1*sin(pi*x/50); 0")
  local resumed_from=$((stop / interval * interval))
  rm -rf results
  "$impm" "$scene" "${settings[@]}" > log.txt 2>&1 || fail "$name: the uninterrupted run failed"
  untimed results/steps.csv > full_steps.csv
  cp results/point_history.csv full_history.csv
  [ "$(wc -l < full_steps.csv)" -eq $((steps + 1)) ] || fail "$name: the reference has not $steps steps"
  "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=$interval" \
    --stop-after-step "$stop" > log.txt 2>&1 || fail "$name: the first part failed"
  grep -q "^control.converged steps = $resumed_from$" results/checkpoint/state.txt ||
    fail "$name: the newest checkpoint is not that of step $resumed_from"
  "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=$interval" \
    --resume > log.txt 2>&1 || fail "$name: the resumed run failed"
  untimed results/steps.csv > resumed_steps.csv
  [ "$(wc -l < resumed_steps.csv)" -eq $((steps + 1)) ] || fail "$name: the resumed steps.csv has not $steps steps"
  compare full_steps.csv resumed_steps.csv "$name: the resumed vibration differs from the uninterrupted one"
  compare full_history.csv results/point_history.csv "$name: the resumed point history differs"
  echo "vibrating_bar_resume ($name): the run resumed at step $resumed_from of $steps ends as the uninterrupted one"
}
resume_case generalised-alpha 200 25 60 \
  --set "Inertia/Integrator=generalised-alpha" --set "Inertia/Spectral radius=0.8"
resume_case "explicit MUSL" 400 50 120 --set "Inertia/Integrator=explicit MUSL"
finer=(--set "Time/End time=20" --set "Time/Time step=0.2" --set "Checkpoint/Interval=25")
rm -rf results
"$impm" "$scene" "${finer[@]}" --stop-after-step 30 > log.txt 2>&1 || fail "finer: the first part failed"
"${launcher[@]}" "$impm" "$scene" "${finer[@]}" --set "Time/Time step=0.1" --resume > log.txt 2>&1 ||
  { cat log.txt; fail "finer: the resumed run failed"; }
/usr/bin/python3 - results/steps.csv <<'PY' || fail "finer: the steps after the resume"
import csv, sys
times = [float(r["time"]) for r in csv.DictReader(open(sys.argv[1])) if r["converged"] == "1"]
print("finer steps after a resume: %d steps, t = %g, %g, %g ... %g" % (len(times), times[24], times[25], times[26], times[-1]))
sys.exit(0 if len(times) == 175 and abs(times[24] - 5) < 1e-9 and abs(times[25] - 5.1) < 1e-9
         and abs(times[-1] - 20) < 1e-9 else 1)
PY
echo "vibrating_bar_resume: passed"
