#!/usr/bin/env bash
# The output directory locked for the run. A run (A) is started and, once
# it holds the lock, stopped with SIGSTOP (its rank 0, whose process id the
# lock file names); then
#  1. a second run of the same scene in the same directory (B), and one
#     with --overwrite, are refused with one line naming A (its process id)
#     and a non-zero exit status, and leave A's files alone;
#  2. --resume while A runs is refused likewise;
#  3. A, continued (SIGCONT), ends normally, with the state of a run alone;
#  4. on one process: a run killed with SIGKILL leaves no lock behind (the
#     next run in the directory proceeds).
# Usage: output_lock.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
settings=(--set "Solver/Load steps=12")

"$impm" "$scene" "${settings[@]}" > alone.txt 2>&1 || fail "the run alone failed"
summary alone.txt > alone_summary.txt
rm -rf results

"${launcher[@]}" "$impm" "$scene" "${settings[@]}" > a.txt 2>&1 &
a=$!
holder=""
for _ in $(seq 600); do
  holder=$(sed -n 's/.*, pid \([0-9]*\) on .*/\1/p' results/impm.lock 2> /dev/null)
  [ -n "$holder" ] && break
  kill -0 $a 2> /dev/null || break
  sleep 0.05
done
[ -n "$holder" ] || { cat a.txt; fail "run A wrote no lock file naming its process"; }
kill -STOP "$holder" || fail "run A ended before it could be stopped"
trap 'kill -CONT "$holder" 2> /dev/null; rm -rf "$work"' EXIT

# refused CASE: the last run (out.txt) refused with one line naming A.
refused() {
  [ "$status" -ne 0 ] || { kill -CONT "$holder"; cat out.txt; fail "$1: a second run in the directory was not refused"; }
  [ "$(grep -c '^Error: ' out.txt)" -eq 1 ] || { kill -CONT "$holder"; cat out.txt; fail "$1: not one line 'Error: '"; }
  grep -qE "^Error: The output directory 'results' is in use by another run \(scene 'collapse_h1_4steps', pid $holder on [^ ]+, started [0-9-]+ [0-9:]+ UTC\)" out.txt ||
    { kill -CONT "$holder"; cat out.txt; fail "$1: the error does not name run A"; }
}
timeout 60 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" > out.txt 2>&1
status=$?
refused "the same scene"
timeout 60 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --overwrite > out.txt 2>&1
status=$?
refused "--overwrite"
[ -f results/impm-run.txt ] || { kill -CONT "$holder"; fail "a refused run removed A's files"; }
timeout 60 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --resume > out.txt 2>&1
status=$?
refused "--resume"

kill -CONT "$holder"
wait $a || { cat a.txt; fail "run A failed after the refused runs"; }
summary a.txt > a_summary.txt
compare alone_summary.txt a_summary.txt "run A ends in another state than the run alone"

if [ ${#launcher[@]} -eq 0 ]; then
  "$impm" "$scene" "${settings[@]}" > killed.txt 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    [ -s results/impm.lock ] && break
    sleep 0.05
  done
  kill -KILL $pid
  wait $pid 2> /dev/null
  "$impm" "$scene" "${settings[@]}" > after.txt 2>&1 ||
    { cat after.txt; fail "the run after a killed one was refused"; }
fi
echo "output_lock: a second run in a directory in use is refused, naming the first"
