#!/usr/bin/env bash
# The scene kept in the checkpoint. The scene is stopped after step 2 with a
# checkpoint after every step; then --resume
#  1. with a changed Young's modulus: refused in one line naming the entry
#     with both values, non-zero exit status;
#  2. with two changed entries: refused, both named;
#  3. with a changed 'Output/Interval' (an entry that may change): resumed,
#     ending in the state of the uninterrupted run;
#  4. with the changed Young's modulus and --resume-with-changes: resumed.
# Usage: resume_scene_changes.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
settings=(--set "Checkpoint/Interval=1")
young="Body 1/Material/von Mises/Young's modulus"

"$impm" "$scene" > full.txt 2>&1 || fail "the uninterrupted run failed"
summary full.txt > full_summary.txt
"$impm" "$scene" "${settings[@]}" --stop-after-step 2 > part1.txt 2>&1 ||
  fail "the first part failed"
cp -a results pristine

# refused PATTERN: the last run (out.txt) stopped with one line matching it.
refused() {
  [ "$status" -ne 0 ] || { cat out.txt; fail "a changed scene was resumed (exit status 0)"; }
  [ "$(grep -c '^Error: ' out.txt)" -eq 1 ] || { cat out.txt; fail "not one line 'Error: '"; }
  grep -qE "^Error: --resume: the scene differs from the one the checkpoint was written from in $1" out.txt ||
    { cat out.txt; fail "no error line matching '$1'"; }
}

# 1. A changed Young's modulus.
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "$young=2e6" --resume > out.txt 2>&1
status=$?
refused "1 entry: '$young' 1e6 -> 2e6 \(resume with that scene, or give --resume-with-changes\)\.$"
# 2. Two changed entries.
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "$young=2e6" \
  --set "Body 1/Density=900" --resume > out.txt 2>&1
status=$?
refused "2 entries: 'Body 1/Density' 1000 -> 900; '$young' 1e6 -> 2e6 "
# 3. A changed output interval.
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Output/Interval=2" \
  --resume > log.txt 2>&1 || fail "a resume with another output interval was refused"
summary log.txt > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the resume with another output interval ends in another state"
ls results/points_*.vtu results/points_*.pvtu > /dev/null 2>&1 ||
  fail "the changed output interval wrote no point file"
# 4. --resume-with-changes.
rm -rf results && cp -a pristine results
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "$young=2e6" \
  --resume-with-changes > log.txt 2>&1 || fail "--resume-with-changes was refused"
grep -q "^step   3 " log.txt || fail "--resume-with-changes did not continue at step 3"
echo "resume_scene_changes: changed scenes refused with their differences, allowed changes resumed"
