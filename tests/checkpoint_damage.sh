#!/usr/bin/env bash
# Damaged checkpoints. The scene is run with a checkpoint after every load
# step and stopped after step 2 (checkpoint/ of step 2, checkpoint.old/ of
# step 1). Then:
#  1. each file of checkpoint/ (the grid's p4est file and its data files
#     with the points, state.txt, scene.prm, manifest.txt) is damaged in
#     turn (truncated to half, zeroed, 8 bytes flipped: on one process all
#     three for the grid's files, else one of these per file, in turn),
#     checkpoint.old/ removed, and --resume
#     must stop with a non-zero exit status (not a signal), one line
#     "Error: ..." naming the file, and no abort or backtrace;
#  2. with checkpoint.old/ kept, a damaged grid data file: the resumed run
#     says so in one line, continues from step 1 and ends in the state of
#     the uninterrupted run;
#  3. both damaged: refused, naming the newest's file.
# Usage: checkpoint_damage.sh IMPM SCENE [MPIEXEC N]
scene=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/script_helpers.sh" "$@"
settings=(--set "Checkpoint/Interval=1")

# damage FILE MODE: truncate (to half), zero (same size), flip (8 bytes in
# the middle inverted).
damage() { /usr/bin/python3 "$here/damage_file.py" "$1" "$2"; }

# refused NAME FILE_PATTERN: the last run (out.txt, status $status) stopped
# with one clear line naming the file.
n_failed=0
refused() {
  local problem=""
  [ "$status" -eq 0 ] && problem="exit status 0"
  [ "$status" -gt 128 ] && [ ${#launcher[@]} -eq 0 ] && problem="killed by a signal ($status)"
  [ "$(grep -c '^Error: ' out.txt)" -eq 1 ] || problem="$problem; not one line 'Error: '"
  grep -qE "^Error: --resume: the checkpoint is damaged: .*$2" out.txt ||
    problem="$problem; no error line naming $2"
  # (mpiexec's own note says "the job has been aborted", in lower case.)
  grep -qE "Abort|MPI_ABORT|[Bb]acktrace|Stacktrace|An error occurred in line|terminate called" out.txt &&
    problem="$problem; an abort or a backtrace"
  [ ${#launcher[@]} -eq 0 ] && [ "$(wc -l < out.txt)" -ne 1 ] &&
    problem="$problem; more than one line of output"
  if [ -n "$problem" ]; then
    echo "case $1: ${problem#; }"
    sed 's/^/    | /' out.txt | head -8
    n_failed=$((n_failed + 1))
  fi
}

"$impm" "$scene" > full.txt 2>&1 || fail "the uninterrupted run failed"
summary full.txt > full_summary.txt
"$impm" "$scene" "${settings[@]}" --stop-after-step 2 > part1.txt 2>&1 ||
  fail "the first part failed"
grep -q "^control.converged steps = 2$" results/checkpoint/state.txt ||
  fail "the newest checkpoint is not that of step 2"
grep -q "^control.converged steps = 1$" results/checkpoint.old/state.txt ||
  fail "the previous checkpoint (step 1) is not kept"
mv results pristine
files=$(cd pristine/checkpoint && ls)
for required in grid state.txt scene.prm manifest.txt; do
  echo "$files" | grep -qx "$required" || fail "the checkpoint has no $required"
done
echo "$files" | grep -q "_fixed.data$" || fail "the checkpoint has no grid data file"

# 1. Each file damaged, no previous checkpoint.
modes=(truncate zero flip)
n_cases=0
for file in $files; do
  if [ ${#launcher[@]} -eq 0 ] && [[ $file == grid* ]]; then
    chosen=("${modes[@]}")
  else
    chosen=("${modes[$((n_cases % 3))]}")
  fi
  for mode in "${chosen[@]}"; do
    n_cases=$((n_cases + 1))
    rm -rf results && cp -a pristine results && rm -rf results/checkpoint.old
    damage "results/checkpoint/$file" "$mode"
    timeout 60 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --resume > out.txt 2>&1
    status=$?
    refused "${file}_$mode" "checkpoint/${file//./\\.}"
  done
done
[ "$n_failed" -eq 0 ] || fail "$n_failed of $n_cases damaged checkpoints not refused clearly"

# 2. A damaged grid data file, the previous checkpoint kept.
data=$(echo "$files" | grep "_fixed.data$" | head -1)
rm -rf results && cp -a pristine results
damage "results/checkpoint/$data" flip
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --resume > log.txt 2>&1 ||
  fail "the resume from the previous checkpoint failed"
grep -q "^Note: the newest checkpoint is damaged: .*checkpoint/${data//./\\.}.*resuming from the previous one, results/checkpoint.old" log.txt ||
  fail "the fall-back to the previous checkpoint is not reported"
grep -q "^step   2 " log.txt || fail "the resumed run did not start at step 2"
summary log.txt | grep -v "^Note: " > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the run resumed from the previous checkpoint ends in another state"

# 3. Both damaged.
rm -rf results && cp -a pristine results
damage "results/checkpoint/$data" zero
damage results/checkpoint.old/state.txt flip
timeout 60 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --resume > out.txt 2>&1
status=$?
refused both_damaged "checkpoint/${data//./\\.}.*the previous one too: .*checkpoint.old/state\.txt"
[ "$n_failed" -eq 0 ] || fail "two damaged checkpoints not refused clearly"
echo "checkpoint_damage: $n_cases damaged checkpoints refused in one line each; the previous checkpoint taken when it verifies"
