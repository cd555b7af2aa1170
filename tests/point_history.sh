#!/usr/bin/env bash
# The point history (subsection "Point history", the first postprocessor
# with parameters of its own): the collapse at h = 1 m in 4 load steps with
# point files at every step follows three points chosen by initial
# position. point_history.csv must hold, for every written step, the values
# the point files hold for the same point (read back by VTK's XML reader,
# tests/compare_point_history.py); and a point history resumed from a
# checkpoint equals the uninterrupted one.
# Usage: point_history.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
settings=(--set "Output/Interval=1" --set "Point history/Positions=0.5, 0.5; 7.9, 7.9; 3, 4")
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" > log.txt 2>&1 || fail "the run failed"
converged=$(grep -c "^step .* iterations [0-9]" log.txt)
[ "$(wc -l < results/point_history.csv)" -eq $((1 + 3 * (converged + 1))) ] ||
  fail "point_history.csv has $(wc -l < results/point_history.csv) lines, not a header and 3 points x $((converged + 1)) states"
/usr/bin/python3 "$here/compare_point_history.py" results > check.txt ||
  { cat check.txt; fail "the point history differs from the point files"; }
cat check.txt
cp results/point_history.csv full_history.csv
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=2" \
  --stop-after-step 3 --overwrite > part1.txt 2>&1 || fail "the first part failed"
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=2" \
  --resume > part2.txt 2>&1 || fail "the resumed run failed"
compare full_history.csv results/point_history.csv "the resumed point history differs"
echo "point_history: the history equals the point files and survives a resume"
