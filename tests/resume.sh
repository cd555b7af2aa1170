#!/usr/bin/env bash
# Checkpoints and --resume. The collapse at h = 1 m over 40 load steps (with
# point files every 4 steps) is run
#  1. without interruption: the reference (the test summary and the
#     non-timing columns of steps.csv and newton.csv);
#  2. with a checkpoint every 3 steps, stopped after step 10
#     (--stop-after-step) and resumed from the checkpoint of step 9 (on
#     MPIEXEC N processes if given, after the first part ran on one): the
#     same final summary, steps.csv and newton.csv (numdiff at the suite's
#     tolerances), and a .pvd naming each point file once;
#  3. on one process only: killed with SIGKILL at four moments drawn with a
#     fixed seed (0 to 0.15 s after the run has done two steps), resumed after each kill (started afresh if no checkpoint
#     was complete yet) and finally run to the end: the same final summary,
#     and every point file complete and readable by VTK's XML readers;
#  4. on MPIEXEC N processes only: stopped and resumed on N processes, the
#     same bytes as the uninterrupted run on N (steps.csv and newton.csv
#     without timings, the summary).
# Usage: resume.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
settings=(--set "Solver/Load steps=40" --set "Output/Interval=4")

# 1. The reference.
"$impm" "$scene" "${settings[@]}" > full.txt 2>&1 || fail "the uninterrupted run failed"
summary full.txt > full_summary.txt
untimed results/steps.csv > full_steps.csv
untimed results/newton.csv > full_newton.csv
[ "$(grep -c '^step ' full.txt)" -ge 40 ] || fail "the reference did not print its steps"

# 2. Stopped after step 10, resumed from step 9.
"$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=3" \
  --stop-after-step 10 > part1.txt 2>&1 || fail "the first part failed"
grep -q "Stopped after load step 10" part1.txt || fail "the first part did not stop after step 10"
grep -q "^control.converged steps = 9$" results/checkpoint/state.txt ||
  fail "the newest checkpoint is not that of step 9"
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=3" \
  --resume > part2.txt 2>&1 || fail "the resumed run failed"
grep -q "^step  10 " part2.txt || fail "the resumed run did not start at step 10"
grep -q "^step   9 " part2.txt && fail "the resumed run repeated step 9"
summary part2.txt > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the resumed run ends in another state"
untimed results/steps.csv > resumed_steps.csv
untimed results/newton.csv > resumed_newton.csv
compare full_steps.csv resumed_steps.csv "steps.csv of the resumed run differs"
compare full_newton.csv resumed_newton.csv "newton.csv of the resumed run differs"
dataset_files=$(grep -o 'file="[^"]*"' results/points.pvd)
[ "$(echo "$dataset_files" | sort -u | wc -l)" -eq "$(echo "$dataset_files" | wc -l)" ] ||
  fail "points.pvd names a file twice"
/usr/bin/python3 "$here/check_point_files.py" results > check.txt || { cat check.txt; fail "a point file is incomplete"; }

# 3. Killed and resumed (one process: SIGKILL to mpiexec would leave its
#    children running).
if [ ${#launcher[@]} -eq 0 ]; then
  rm -rf results
  RANDOM=2026
  for kill in 1 2 3 4; do
    # 0 to 0.15 s after the run has done two steps of its own (its start-up,
    # MPI's included, takes about 0.7 s here, its 40 steps about 0.6 s):
    # the first one's checkpoint is then complete. After one step only, on
    # a machine slowed by other work, all four kills came before the first
    # checkpoint was written, and the resume was never tried.
    delay=$(printf '0.%02d' $((RANDOM % 15)))
    if [ -f results/checkpoint/state.txt ] || [ -f results/checkpoint.old/state.txt ]; then
      mode=(--resume)
    else
      mode=(--overwrite)
    fi
    rows=0
    [ "${mode[0]}" = --resume ] && rows=$(wc -l < results/steps.csv)
    "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=1" "${mode[@]}" \
      > "killed_$kill.txt" 2>&1 &
    pid=$!
    # steps.csv is cut back to the checkpoint and grows by a row per step.
    for _ in $(seq 300); do
      [ -f results/steps.csv ] && [ "$(wc -l < results/steps.csv)" -gt $((rows + 2)) ] && break
      kill -0 $pid 2> /dev/null || break
      sleep 0.1
    done
    sleep "$delay"
    kill -KILL $pid 2> /dev/null
    wait $pid 2> /dev/null
    echo "kill $kill $delay s after two steps of its own (${mode[*]}): steps.csv $rows -> $(wc -l < results/steps.csv) rows" >> kills.txt
  done
  [ -f results/checkpoint/state.txt ] || [ -f results/checkpoint.old/state.txt ] ||
    { cat kills.txt; fail "no checkpoint was complete after four kills"; }
  "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=1" --resume \
    > last.txt 2>&1 || { cat kills.txt; fail "the run after the kills failed"; }
  summary last.txt > killed_summary.txt
  compare full_summary.txt killed_summary.txt "the killed and resumed run ends in another state"
  /usr/bin/python3 "$here/check_point_files.py" results > check.txt ||
    { cat kills.txt check.txt; fail "a point file is incomplete after the kills"; }
  [ -f results/summary.json ] || fail "no summary.json after the last part"
  cat kills.txt
fi
# 4. On MPIEXEC N processes throughout: the uninterrupted run and the one
#    stopped after step 10 and resumed from step 9 write the same bytes
#    (steps.csv and newton.csv without their timings, and the test
#    summary): a resume on the same number of processes continues
#    identically, not only within the suite's tolerances.
if [ ${#launcher[@]} -gt 0 ]; then
  rm -rf results
  "${launcher[@]}" "$impm" "$scene" "${settings[@]}" > same_full.txt 2>&1 ||
    fail "the uninterrupted run on ${launcher[2]} processes failed"
  untimed results/steps.csv > same_full_steps.csv
  untimed results/newton.csv > same_full_newton.csv
  summary same_full.txt > same_full_summary.txt
  rm -rf results
  "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=3" \
    --stop-after-step 10 > same_part1.txt 2>&1 || fail "the first part on ${launcher[2]} processes failed"
  "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=3" \
    --resume > same_part2.txt 2>&1 || fail "the resumed run on ${launcher[2]} processes failed"
  untimed results/steps.csv > same_resumed_steps.csv
  untimed results/newton.csv > same_resumed_newton.csv
  summary same_part2.txt > same_resumed_summary.txt
  for part in steps.csv newton.csv summary.txt; do
    cmp -s "same_full_$part" "same_resumed_$part" ||
      fail "the resumed run on ${launcher[2]} processes is not bit-identical ($part)"
  done
fi
echo "resume: the resumed runs end in the state of the uninterrupted one"
