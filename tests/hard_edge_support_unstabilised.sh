#!/usr/bin/env bash
# Hard case 1 without ghost stabilisation (SCENE:
# tests/hard_edge_support_unstabilised.prm): in load step 2 the nodes at
# the grid's base enter the system fed only by the edges of the lowest
# points' domains, and the system is nearly singular. The test asserts that:
# the run completes and its worst condition estimate (summary.json, at full
# precision) exceeds 1e6 (about 4e8), and the same scene with only 'Ghost
# stabilisation/Enabled' set to true stays below 1e6 (about 4e2), so that
# the stabilisation is what removes it. The stresses the unstabilised run
# reaches (about 1 Pa for 5 kPa in the lowest points) are the failure, not
# an answer to compare; tests/hard_edge_support_stabilised.prm checks the
# right answer (the one-step result, doc/hard_cases.md).
# Usage: hard_edge_support_unstabilised.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
# condition VARIABLE [ARGS...]: run the scene, set VARIABLE to its worst
# condition estimate.
condition() {
  local variable=$1
  shift
  rm -rf results
  "$impm" "$scene" --set "Output/Interval=0" "$@" > log.txt 2>&1 ||
    fail "the run did not complete ($*)"
  grep -q "^material points: " log.txt || fail "the run printed no summary ($*)"
  printf -v "$variable" '%s' "$(sed -n \
    's/^ *"worst_condition_estimate": \([^,]*\),$/\1/p' results/summary.json)"
  [ -n "${!variable}" ] || fail "summary.json holds no condition estimate ($*)"
}
# above VALUE: whether VALUE is a number above 1e6.
above() { awk -v c="$1" 'BEGIN { exit !(c + 0 == c && c > 1e6) }'; }
condition without
condition with --set "Ghost stabilisation/Enabled=true"
status=0
if above "$without"; then
  echo "condition estimate above 1e6 without stabilisation: yes"
else
  echo "condition estimate above 1e6 without stabilisation: NO ($without)"
  status=1
fi
if above "$with"; then
  echo "condition estimate above 1e6 with stabilisation: yes ($with)"
  status=1
else
  echo "condition estimate above 1e6 with stabilisation: no"
fi
exit $status
