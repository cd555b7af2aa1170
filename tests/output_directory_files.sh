#!/usr/bin/env bash
# The start of a run removes only what IMPM wrote (issue 31): the record
# impm-run.txt lists what a run found in its directory and did not write
# ("kept = NAME"); the next run removes the earlier run's files (IMPM's
# names, not kept) and leaves the rest.
#  1. a directory holding a user's notes.txt and no run: refused with one
#     line naming notes.txt; with --overwrite the run completes, notes.txt
#     is unchanged and listed as kept;
#  2. a second run with point files and checkpoints, then a third without
#     them: the second's point files and checkpoints are gone, notes.txt
#     stays, and the third is not refused (notes.txt was kept before);
#  3. a user's file inside checkpoint/: refused, also with --overwrite,
#     naming that file; it and the checkpoint stay;
#  4. a directory that held no run of IMPM, with a checkpoint/ and a
#     points_1.vtu of the user's (the issue's case): refused, also with
#     --overwrite, naming one of them; both stay.
# Usage: output_directory_files.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() { "${launcher[@]}" "$impm" "$scene" "$@"; }
# refused LOG PATTERN: a non-zero status (checked by the caller), one line
# "Error: ..." matching PATTERN.
refused() {
  [ "$(grep -c "^Error: " "$1")" -eq 1 ] || { cat "$1"; fail "not one error line"; }
  grep -qE "^Error: $2" "$1" || { cat "$1"; fail "no error line matching '$2'"; }
  grep -qE "Stacktrace|An error occurred|MPI_ABORT" "$1" && { cat "$1"; fail "a raw report"; }
  true
}

# 1.
mkdir results && echo "the user's" > results/notes.txt
run > log.txt 2>&1 && fail "a directory with a user's file was taken without --overwrite"
refused log.txt "The output directory 'results' holds 'notes.txt', which IMPM did not write: .*--overwrite"
run --overwrite > log.txt 2>&1 || fail "the run with --overwrite failed"
[ "$(cat results/notes.txt)" = "the user's" ] || fail "notes.txt changed"
grep -qx "kept = notes.txt" results/impm-run.txt || fail "notes.txt not listed as kept"

# 2.
run --set "Output/Interval=1" --set "Checkpoint/Interval=2" > log.txt 2>&1 ||
  fail "the run with point files and checkpoints failed (notes.txt kept before)"
ls results/points_00001.pvtu results/checkpoint/manifest.txt > /dev/null ||
  fail "the second run wrote no point files or checkpoint"
run > log.txt 2>&1 || fail "the third run failed"
ls results | grep -qE "^points|^checkpoint" && { ls results; fail "the second run's files stayed"; }
[ "$(cat results/notes.txt)" = "the user's" ] || fail "notes.txt changed or went"
[ -s results/summary.json ] || fail "the third run wrote no summary"

# 3.
run --set "Checkpoint/Interval=2" > log.txt 2>&1 || fail "the run with checkpoints failed"
echo "mine" > results/checkpoint/mine.txt
run --overwrite > log.txt 2>&1 && fail "a user's file in checkpoint/ did not stop the run"
refused log.txt "The output directory 'results' holds 'results/checkpoint/mine.txt', which IMPM did not write, in a checkpoint directory"
[ -f results/checkpoint/mine.txt ] && [ -f results/checkpoint/manifest.txt ] ||
  fail "the user's file or the checkpoint went"

# 4.
mkdir -p other/checkpoint && echo "u" > other/checkpoint/grid && echo "v" > other/points_1.vtu
run --set "Output directory=other" --overwrite > log.txt 2>&1 &&
  fail "a directory of no run with a checkpoint/ and points_1.vtu was taken"
refused log.txt "The output directory 'other' holds '(checkpoint|points_1\.vtu)', which no earlier run of IMPM there lists as its own"
[ "$(cat other/checkpoint/grid)" = u ] && [ "$(cat other/points_1.vtu)" = v ] ||
  fail "the user's checkpoint/ or points_1.vtu changed"
echo "output_directory_files: only IMPM's files removed, the user's kept or refused"
