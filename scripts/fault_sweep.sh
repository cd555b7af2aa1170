#!/usr/bin/env bash
# The faults around a run, swept (issue 31's must-show; the suite's tests
# checkpoint_damage, disk_full and output_lock take a few cases of each, this
# script takes them all). On the scene tests/collapse_h1_4steps.prm (or the
# one given), on one process or on N:
#
#  A. damaged checkpoints: the run is stopped after step 2 with a checkpoint
#     after every step; then each file of checkpoint/ is truncated to half,
#     zeroed, replaced by random bytes, and has 8 bytes flipped at each of
#     10 offsets spread over it (13 damages per file), and --resume is run,
#     once without the previous checkpoint and once with it;
#  B. a full disk at every kind of write: the output directory on a tmpfs of
#     4 kB, 8 kB, ... up to the size the whole run needs, with point files
#     (VTU, then HDF5) and a checkpoint after every step, so that the disk
#     fills in turn at the lock, the run file, the CSV rows, the point
#     history, each point and grid file, each checkpoint file and the
#     summary;
#  C. two runs started in one directory 0, 0.3, 0.7 and 1.2 s apart;
#  D. resumes with a changed scene.
#
# Every run is classified: an abort or a backtrace (a signal, "Abort",
# "terminate called", deal.II's exception text, ...), a hang (no exit in
# 120 s), a refusal in one line ("Error: ..." once, non-zero exit), an
# unclear refusal (non-zero exit, not one such line), a run that ends with
# exit status 0 and the uninterrupted run's answer, or one that ends with
# exit status 0 and ANOTHER answer (the worst). After a full disk, a left
# *.tmp file, a CSV ending in a partial row or a point file VTK cannot read
# counts as a damaged file. The totals go to the last lines; the exit status
# is 1 if any run aborted, hung, refused unclearly, left a damaged file or
# gave another answer.
#
# Usage: scripts/fault_sweep.sh IMPM [NPROC [SCENE [PARTS]]]
# PARTS: the letters of the parts to run (default ABCD).
# Part B needs root (mount -t tmpfs); without it, it is skipped and says so.
# Runs for about 5 minutes on one process, 10 on two (2-core machine).
set -u
impm=$(realpath "$1")
nproc=${2:-1}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=$(realpath "${3:-$here/../tests/collapse_h1_4steps.prm}")
parts=${4:-ABCD}
launcher=()
if [ "$nproc" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PMIX_MCA_gds=hash
  launcher=(mpiexec -np "$nproc" --mca btl self,tcp)
fi
work=$(mktemp -d)
mounted=""
cleanup() {
  [ -n "$mounted" ] && umount "$mounted" 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"

declare -A count
bad=0
# The summary lines of a test-mode printout (as tests/script_helpers.sh).
summary() { grep -v "^step \|^Stopped\|checkpoint\|^Note: " "$1"; }

# classify PART LABEL STATUS LOG [REFERENCE_SUMMARY]: count the outcome of a
# run; print the bad ones.
classify() {
  local part=$1 label=$2 status=$3 log=$4 reference=${5:-reference.txt}
  local outcome
  if [ "$status" -eq 124 ]; then
    outcome=hang
  elif grep -qE "Abort|MPI_ABORT|[Bb]acktrace|Stacktrace|terminate called|An error occurred in line|Segmentation|core dumped" "$log" ||
    { [ "$status" -gt 128 ] && [ ${#launcher[@]} -eq 0 ]; }; then
    outcome=abort
  elif [ "$status" -ne 0 ]; then
    if [ "$(grep -c '^Error: ' "$log")" -eq 1 ]; then
      outcome=refused
    else
      outcome=unclear
    fi
  elif summary "$log" > "$log.summary" &&
    numdiff -q -a 1e-6 -r 1e-8 -s ' \t\n=,:;<>[](){}^' "$reference" "$log.summary" > /dev/null 2>&1; then
    outcome=same_answer
  else
    outcome=OTHER_ANSWER
  fi
  count[$part.$outcome]=$((${count[$part.$outcome]:-0} + 1))
  case $outcome in
    refused | same_answer) ;;
    *)
      bad=$((bad + 1))
      echo "  $part $label: $outcome (exit $status)"
      sed 's/^/      | /' "$log" | head -6
      ;;
  esac
}

run() { timeout 120 "${launcher[@]}" "$impm" "$scene" "$@"; }

echo "fault_sweep: $(basename "$scene") on $nproc process(es)"
run > reference_log.txt 2>&1 || { cat reference_log.txt; exit 1; }
summary reference_log.txt > reference.txt

# ---------------------------------------------------------------- A.
checkpointing=(--set "Checkpoint/Interval=1")
run "${checkpointing[@]}" --stop-after-step 2 > part1.txt 2>&1
mv results pristine
damage() { /usr/bin/python3 "$here/../tests/damage_file.py" "$1" "$2"; }
files=$(cd pristine/checkpoint && ls)
n_a=0
[[ $parts == *A* ]] || files=""
for file in $files; do
  for mode in truncate zero random flip0 flip1 flip2 flip3 flip4 flip5 flip6 flip7 flip8 flip9; do
    for previous in without with; do
      rm -rf results && cp -a pristine results
      [ $previous = without ] && rm -rf results/checkpoint.old
      damage "results/checkpoint/$file" $mode
      run "${checkpointing[@]}" --resume > out.txt 2>&1
      status=$?
      classify "A_$previous" "$file $mode, $previous the previous checkpoint" $status out.txt
      # A resume must say that it fell back to the previous checkpoint.
      if [ $status -eq 0 ] && ! grep -q "^Note: the newest checkpoint is damaged: .*checkpoint/$file" out.txt; then
        echo "  A $file $mode, $previous the previous checkpoint: resumed without naming the damaged file"
        bad=$((bad + 1))
      fi
      n_a=$((n_a + 1))
    done
  done
done
[[ $parts == *A* ]] && echo "A. $n_a resumes from damaged checkpoints ($(echo $files | wc -w) files x 13 damages x with/without the previous one):" \
  "without it refused ${count[A_without.refused]:-0}, resumed ${count[A_without.same_answer]:-0};" \
  "with it refused ${count[A_with.refused]:-0}, resumed from it to the same answer ${count[A_with.same_answer]:-0}"

# ---------------------------------------------------------------- B.
# damaged_files DIRECTORY: a *.tmp left, a CSV ending without a newline or
# with a row of another length, a point file VTK cannot read.
damaged_files() {
  local directory=$1 problems=""
  [ -n "$(find "$directory" -name '*.tmp' 2> /dev/null)" ] && problems="a .tmp file left"
  for csv in "$directory"/*.csv; do
    [ -s "$csv" ] || continue
    [ "$(tail -c1 "$csv" | od -An -c | tr -d ' ')" = '\n' ] || problems="$problems; $(basename "$csv") ends in a partial row"
    awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$csv" || problems="$problems; $(basename "$csv") has a row of another length"
  done
  if ls "$directory"/*.vtu "$directory"/*.pvtu "$directory"/*.pvd > /dev/null 2>&1; then
    /usr/bin/python3 "$here/../tests/check_point_files.py" "$directory" > check.txt 2>&1 ||
      problems="$problems; $(head -1 check.txt)"
  fi
  echo "${problems#; }"
}
if [[ $parts != *B* ]]; then
  :
elif [ "$(id -u)" -eq 0 ] && mkdir -p disk && mount -t tmpfs -o size=4k tmpfs disk 2> /dev/null; then
  mounted=$work/disk
  umount disk
  mounted=""
  refused_before=0
  same_before=0
  for format in vtu hdf5; do
    output=(--set "Output/Interval=1" --set "Output/Format=$format"
      --set "Output/Grid fields=all" --set "Point history/Positions=1, 1"
      "${checkpointing[@]}")
    run "${output[@]}" --set "Output directory=whole_$format" > whole.txt 2>&1 ||
      { cat whole.txt; exit 1; }
    needed=$(du -sk --apparent-size whole_$format | cut -f1)
    # Up in 4 kB steps until two runs in a row complete (tmpfs counts
    # whole pages per file, and a checkpoint needs room for the next one
    # beside it and its estimate's margin before it is written).
    n_b=0
    n_complete=0
    declare -A named=()
    for ((size = 4; size <= 4 * needed && n_complete < 2; size += 4)); do
      mount -t tmpfs -o size=${size}k tmpfs disk && mounted=$work/disk
      run "${output[@]}" --set "Output directory=disk/results" > out.txt 2>&1
      status=$?
      classify B "$format, ${size} kB" $status out.txt
      problems=$(damaged_files disk/results)
      if [ -n "$problems" ]; then
        bad=$((bad + 1))
        count[B.damaged_file]=$((${count[B.damaged_file]:-0} + 1))
        echo "  B $format, ${size} kB: $problems"
      fi
      [ $status -eq 0 ] && n_complete=$((n_complete + 1)) || n_complete=0
      if [ $status -ne 0 ]; then
        file=$(sed -n "s/^Error: .*\(disk\/results\/[^ ':]*\).*/\1/p" out.txt | head -1)
        file=${file#disk/results/}
        [ -z "$file" ] && file="($(sed -n 's/^Error: \(\S* \S* \S*\).*/\1/p' out.txt | head -1 | tr ' ' '_'))"
        file=$(echo "$file" | sed 's/_[0-9][0-9]*\././; s/[0-9][0-9]*\.\(vtu\|h5\|xdmf\)/N.\1/; s/\.tmp$//')
        named[$file]=1
      fi
      umount disk
      mounted=""
      n_b=$((n_b + 1))
    done
    echo "B. $format: $n_b runs on a tmpfs of 4 to $((size - 4)) kB (the run's files take $needed kB):" \
      "refused $((${count[B.refused]:-0} - refused_before)), ended with the same answer $((${count[B.same_answer]:-0} - same_before));" \
      "the refusals named: ${!named[*]}"
    refused_before=${count[B.refused]:-0}
    same_before=${count[B.same_answer]:-0}
    unset named
  done
else
  echo "B. skipped: mounting a tmpfs needs root (tests/disk_full uses a file-size limit instead)"
fi

# ---------------------------------------------------------------- C.
# 400 steps: about 2.5 s, so that every start below falls inside the first.
long=(--set "Solver/Load steps=400")
[[ $parts == *C* ]] && delays="0 0.3 0.7 1.2" || delays=""
[ -n "$delays" ] && { run "${long[@]}" > long_log.txt 2>&1 || { cat long_log.txt; exit 1; }; }
summary long_log.txt > long_reference.txt 2> /dev/null
for delay in $delays; do
  rm -rf results
  run "${long[@]}" > first.txt 2>&1 &
  first=$!
  sleep $delay
  run "${long[@]}" > second.txt 2>&1
  second_status=$?
  wait $first
  first_status=$?
  classify C "delay $delay s, the first run" $first_status first.txt long_reference.txt
  classify C "delay $delay s, the second run" $second_status second.txt long_reference.txt
  completed=0
  [ $first_status -eq 0 ] && completed=$((completed + 1))
  [ $second_status -eq 0 ] && completed=$((completed + 1))
  if [ $second_status -ne 0 ] && ! grep -qE "^Error: .*(held|locked|in use)" second.txt; then
    echo "  C delay $delay s: the second run's refusal does not name the lock"
    bad=$((bad + 1))
  fi
  echo "C. delay $delay s: first run exit $first_status, second exit $second_status" \
    "($(grep -h '^Error: ' first.txt second.txt | cut -c1-100 | head -1))"
  [ $completed -ge 1 ] || { echo "  C delay $delay s: neither run completed"; bad=$((bad + 1)); }
done

# ---------------------------------------------------------------- D.
# Entries that change the answer must be refused; those that may change on a
# restart (output, checkpoint, testing, load steps) are accepted, and with
# the output or checkpoint changed the answer is the uninterrupted run's.
changes=("Body 1/Material/von Mises/Young's modulus=2e6" "Grid/Upper corner=16, 9"
  "Body 1/Points per cell direction=2" "Gravity/Acceleration=0, -9.81"
  "Solver/Tolerance=1e-8" "Material points/Basis=standard MPM"
  "Output/Interval=2" "Checkpoint/Interval=3")
[[ $parts == *D* ]] || changes=()
for change in "${changes[@]}"; do
  rm -rf results && cp -a pristine results
  run --set "$change" --resume > out.txt 2>&1
  classify D "$change" $? out.txt
  echo "D. $change: $(grep -q '^Error: ' out.txt && echo refused || echo accepted)"
done

echo "totals (process count $nproc):"
for key in $(echo "${!count[@]}" | tr ' ' '\n' | sort); do
  echo "  $key ${count[$key]}"
done
n_abort=0
for key in "${!count[@]}"; do
  case $key in *.abort) n_abort=$((n_abort + count[$key])) ;; esac
done
echo "fault_sweep: $bad bad outcomes (aborts $n_abort; hangs, unclear refusals, damaged files and other answers in the lines above)"
[ $bad -eq 0 ]
