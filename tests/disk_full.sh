#!/usr/bin/env bash
# A full disk, imitated by a file-size limit (ulimit -f: a write past it
# fails with "File too large"): the run must stop within the time-out with
# a non-zero exit and one error line naming the file and the cause, and leave
# only complete files under final names: steps.csv and newton.csv end with
# whole rows, every point file reads with VTK's XML readers, no *.tmp file
# and no summary.json is left. Checkpoints and HDF5 files too (cases 4, 5).
# On two processes, also: one process alone cannot write (the others must
# stop with its message, not wait for it).
# On two processes mpiexec runs each process under the limit through bash,
# with Open MPI's shared-memory transport off (its segment file would exceed
# the limit before the program starts) and PMIx's hash store (likewise).
# Usage: disk_full.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export PMIX_MCA_gds=hash

# limited KILOBYTES ARGUMENTS...: run the scene under the limit.
limited() {
  local limit=$1
  shift
  if [ ${#launcher[@]} -gt 0 ]; then
    timeout 120 "${launcher[0]}" --mca btl self,tcp -np "${launcher[2]}" \
      bash -c 'ulimit -f "$0"; exec "$@"' "$limit" "$impm" "$scene" "$@"
  else
    (ulimit -f "$limit"; exec timeout 120 "$impm" "$scene" "$@")
  fi
}

check_stop() {
  local status=$1 file_pattern=$2
  [ "$status" -eq 124 ] && fail "no exit within 120 s (a hang)"
  [ "$status" -eq 0 ] && fail "the run did not stop"
  [ "$(grep -c '^Error: ' log.txt)" -eq 1 ] || fail "not exactly one error line"
  grep -qE "^Error: .*Writing the file results/$file_pattern failed \(File too large\)" log.txt ||
    fail "the error does not name the file and the cause"
  grep -q "An error occurred in line" log.txt && fail "deal.II's exception text was printed"
  [ -e results/summary.json ] && fail "a summary was written for a failed run"
  for csv in results/steps.csv results/newton.csv; do
    [ -s "$csv" ] || fail "$csv is missing or empty"
    [ "$(tail -c 1 "$csv" | od -An -c | tr -d ' ')" = '\n' ] || fail "$csv ends in half a row"
    columns=$(head -1 "$csv" | tr ',' '\n' | wc -l)
    awk -F, -v n="$columns" 'NF != n { exit 1 }' "$csv" || fail "$csv has an incomplete row"
  done
  /usr/bin/python3 "$here/check_point_files.py" results > check.txt || { cat check.txt; fail "a point file is incomplete"; }
}

settings=(--set "Solver/Load steps=40" --set "Testing/Enabled=false" --overwrite)

# 1. The log files outgrow a 1 kB limit (no point files).
limited 1 "${settings[@]}" --set "Output/Interval=0" > log.txt 2>&1
check_stop $? "(steps|newton)\.csv"
[ "$(wc -l < results/steps.csv)" -gt 2 ] || fail "steps.csv lost the steps before the failure"

# 2. The point files outgrow a 20 kB limit after some steps (a process's
#    piece holds about 19-21 kB at first on two processes, 33-38 kB on one,
#    and grows as the points spread).
limit=20
[ ${#launcher[@]} -eq 0 ] && limit=36
limited $limit "${settings[@]}" --set "Output/Interval=1" > log.txt 2>&1
check_stop $? "points_[0-9]+\.[0-9]+\.vtu"
ls results/points_00001.pvtu > /dev/null 2>&1 || fail "no point files were kept before the failure"
# 3. On two processes: only process 1 cannot write (a directory stands where
#    its first piece's temporary file goes); both stop with its message.
if [ ${#launcher[@]} -gt 0 ]; then
  rm -rf results && mkdir -p results/points_00000.0001.vtu.tmp
  timeout 120 "${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Output/Interval=1" > log.txt 2>&1
  status=$?
  [ $status -eq 124 ] && fail "no exit within 120 s when one process failed (a hang)"
  [ $status -eq 0 ] && fail "the run did not stop when one process could not write"
  [ "$(grep -c '^Error: ' log.txt)" -eq 1 ] || fail "not exactly one error line"
  grep -q "^Error: process 1: Cannot write the file results/points_00000.0001.vtu (Is a directory)\.$" log.txt ||
    fail "the error does not name the process, the file and the cause"
  grep -q "MPI_ABORT" log.txt && fail "the communicator was aborted instead of stopping together"
fi
# 4. Checkpoints: at a limit of 30 blocks of 1,024 bytes the first is
#    refused before it starts (its points' data, 159 kB, and 16 bytes per
#    cell: 161 kB estimated), nothing of it left (before the estimate, its
#    grid save was cut at the limit, which MPI-IO does not report, and
#    refused after it); at 170 blocks (174 kB, as the message says in
#    decimal units) the first (159 kB) is written and the next refused
#    before it starts (the last one's size, with a tenth more, does not
#    fit), the first kept and still complete.
check_checkpoint() {
  local status=$1 pattern=$2
  [ "$status" -eq 124 ] && fail "no exit within 120 s (a hang)"
  [ "$status" -eq 0 ] && fail "the run did not stop"
  [ "$(grep -c '^Error: ' log.txt)" -eq 1 ] || fail "not exactly one error line"
  grep -qE "^Error: (process [0-9]+: )?$pattern" log.txt || { cat log.txt; fail "the error does not say what failed"; }
  [ -e results/checkpoint.tmp ] && fail "a partial checkpoint was left"
  grep -q "An error occurred in line" log.txt && fail "deal.II's exception text was printed"
  return 0
}
checkpoints=("${settings[@]}" --set "Output/Interval=0" --set "Checkpoint/Interval=1")
limited 30 "${checkpoints[@]}" > log.txt 2>&1
check_checkpoint $? "Not writing the checkpoint: a file of about 161 kB exceeds this process's file-size limit of 30\.7 kB \(ulimit -f\); no checkpoint has been written\.$"
[ -e results/checkpoint ] && fail "a checkpoint was published"
limited 170 "${checkpoints[@]}" > log.txt 2>&1
check_checkpoint $? "Not writing the checkpoint: a file of about [0-9.]+ kB exceeds this process's file-size limit of 174 kB \(ulimit -f\); the last checkpoint is kept\.$"
[ -e results/checkpoint/manifest.txt ] || fail "the first checkpoint was not kept"
grep -q "^control.converged steps = 1$" results/checkpoint/state.txt ||
  fail "the kept checkpoint is not the first step's"
# 5. HDF5 point files (one file for all processes, written by HDF5 through
#    MPI-IO): their size is known before they are written and checked, so
#    a full disk leaves neither HDF5's error report nor a .tmp file.
limited 20 "${settings[@]}" --set "Output/Interval=1" --set "Output/Format=hdf5" > log.txt 2>&1
check_checkpoint $? "Not writing the point file results/points_00000\.h5: a file of about [0-9.]+ kB exceeds this process's file-size limit of 20.5 kB \(ulimit -f\)$"
grep -q "HDF5-DIAG" log.txt && fail "HDF5's error report was printed"
ls results/*.h5.tmp > /dev/null 2>&1 && fail "a .tmp file was left"
echo "disk_full: the runs stopped with one clear line and complete files"
