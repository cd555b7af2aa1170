#!/usr/bin/env bash
# Signals stop a run at once (issue 31): SIGINT (Ctrl-C) like SIGTERM; the
# load step in progress is abandoned at its next Newton iteration (all
# processes agree), the last converged state is saved in a checkpoint and
# the run stops with one line "Stopped by SIGINT in load step K, abandoned
# after N Newton iterations; the checkpoint after load step K-1 holds the
# last converged state ..." and exit status 128 + the signal (130, 143).
# The collapse's block, elastic (yield stress 1e9 Pa), on 128 x 64 cells
# (36,864 points) in 8 load steps of 3 Newton iterations, 0.1-0.3 s each:
#  1. uninterrupted;
#  2. SIGINT to every process once a step has converged: status 130, the
#     line, the checkpoint holds a converged step;
#  3. --resume (the checkpoint verifies: no note of a damaged one), then
#     SIGTERM to one process only (on two, rank 1's: the others follow)
#     once a further step has converged: status 143, the line;
#  4. --resume to the end: the uninterrupted run's final state (the test
#     summary; on two processes to numdiff's tolerances);
#  5. SIGTERM 1.2 s after the start, about when the first step is solved:
#     status 143 and the line;
#  6. on one process, SIGTERM 20 ms after the start, while the launcher
#     loads the libraries (it blocks the stop signals until the program's
#     handlers are in place): status 143 and the line.
# Usage: sigint_stop.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
settings=(--set "Grid/Number of cells=128, 64" --set "Solver/Load steps=8"
          --set "Body 1/Material/von Mises/Yield stress=1e9")
# exec: a run started with & is then the process $! (not a subshell).
run() { exec "${launcher[@]}" "$impm" "$scene" "${settings[@]}" "$@"; }
# The processes of the run $1 (itself on one process, the ranks under mpiexec).
ranks() { if [ ${#launcher[@]} -gt 0 ]; then pgrep -P "$1" | sort -n; else echo "$1"; fi; }
# wait_rows N PID: until steps.csv has N rows after its header.
wait_rows() {
  for _ in $(seq 1200); do
    [ -f results/steps.csv ] && [ "$(($(wc -l < results/steps.csv) - 1))" -ge "$1" ] && return
    kill -0 "$2" 2> /dev/null || return
    sleep 0.02
  done
}
# stopped LOG STATUS EXPECTED SIGNAL: the status and the one line.
stopped() {
  [ "$2" -eq "$3" ] || { cat "$1"; fail "the run sent $4 ended with status $2, not $3"; }
  [ "$(grep -c "^Stopped by $4" "$1")" -eq 1 ] || { cat "$1"; fail "no line 'Stopped by $4'"; }
  grep -qE "Stacktrace|An error occurred|MPI_ABORT|^Error" "$1" && { cat "$1"; fail "an error or a raw report"; }
  true
}

(run > full.txt 2>&1) || { cat full.txt; fail "the uninterrupted run failed"; }
summary full.txt > full_summary.txt

# 2. SIGINT to every process during a step.
rm -rf results
run > part1.txt 2>&1 &
pid=$!
wait_rows 1 $pid
sleep 0.1
pids=$(ranks $pid)
kill -INT $pids
wait $pid
stopped part1.txt $? 130 SIGINT
grep -qE "^Stopped by SIGINT (in load step [0-9]+, abandoned after [0-9]+ Newton iterations|after load step [0-9]+); the checkpoint after load step [1-9][0-9]* holds the last converged state: continue with impm SCENE --resume.$" part1.txt ||
  { cat part1.txt; fail "the line does not name the step and the checkpoint"; }

# 3. Resumed, then SIGTERM to one process.
rows=$(($(wc -l < results/steps.csv) - 1))
run --resume > part2.txt 2>&1 &
pid=$!
wait_rows $((rows + 1)) $pid
pids=$(ranks $pid)
kill -TERM $(echo "$pids" | tail -1)
wait $pid
stopped part2.txt $? 143 SIGTERM
grep -q "damaged" part2.txt && { cat part2.txt; fail "the checkpoint written at SIGINT did not verify"; }

# 4. Resumed to the end.
(run --resume > part3.txt 2>&1) || { cat part3.txt; fail "the resumed run failed"; }
grep -q "damaged" part3.txt && { cat part3.txt; fail "the checkpoint written at SIGTERM did not verify"; }
summary part3.txt > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the run resumed after the signals ends in another state"

# 5. SIGTERM before the first step converged.
rm -rf results
run > early.txt 2>&1 &
pid=$!
sleep 1.2
kill -TERM $(ranks $pid)
wait $pid
stopped early.txt $? 143 SIGTERM
# 6. One process: SIGTERM 20 ms after the start, while the launcher loads
# the libraries (the signals wait, blocked, until the handlers are in
# place; before, such a signal ended the run without a word).
if [ ${#launcher[@]} -eq 0 ]; then
  rm -rf results
  run > loading.txt 2>&1 &
  pid=$!
  sleep 0.02
  kill -TERM $pid
  wait $pid
  stopped loading.txt $? 143 SIGTERM
fi
cat part1.txt part2.txt early.txt
echo "sigint_stop: SIGINT and SIGTERM abandoned the step, saved the last converged state and stopped; the resumed run ends in the uninterrupted state"
