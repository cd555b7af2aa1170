#!/usr/bin/env bash
# SIGINT (Ctrl-C) like SIGTERM: a run sent SIGINT after its first load step
# stops after the current step with a checkpoint ("Stopped after load step
# K (SIGINT)", exit status 0), and --resume ends in the state of the
# uninterrupted run. One process (mpiexec handles SIGINT itself).
# Usage: sigint_stop.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
settings=(--set "Solver/Load steps=200")
"$impm" "$scene" "${settings[@]}" > full.txt 2>&1 || fail "the uninterrupted run failed"
summary full.txt > full_summary.txt
rm -rf results
"$impm" "$scene" "${settings[@]}" > part1.txt 2>&1 &
pid=$!
# steps.csv grows by a row per step (the printout may be buffered).
for _ in $(seq 600); do
  [ -f results/steps.csv ] && [ "$(wc -l < results/steps.csv)" -gt 2 ] && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.02
done
kill -INT $pid
wait $pid
status=$?
[ $status -eq 0 ] || { cat part1.txt; fail "the run sent SIGINT ended with exit status $status"; }
grep -q "^Stopped after load step [0-9]* (SIGINT); a checkpoint is written" part1.txt ||
  { cat part1.txt; fail "the run did not stop with a checkpoint on SIGINT"; }
"$impm" "$scene" "${settings[@]}" --resume > part2.txt 2>&1 || fail "the resumed run failed"
summary part2.txt > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the run resumed after SIGINT ends in another state"
echo "sigint_stop: SIGINT saved and stopped the run; the resumed run ends in the uninterrupted state"
