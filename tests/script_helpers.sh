# Sourced by the script tests: IMPM and the scene from the arguments, an
# optional launcher ("MPIEXEC N" after them), a scratch directory to work
# in, removed at the end, fail() that prints the log and stops, and the
# comparisons the script tests share (compare, summary, untimed).
# Usage in a test: source script_helpers.sh "$@"  (IMPM SECOND [MPIEXEC N])
set -u
impm=$1
launcher=()
[ $# -ge 4 ] && launcher=("$3" -np "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() {
  echo "FAILED: $*"
  [ -f log.txt ] && cat log.txt
  exit 1
}
# compare A B MESSAGE: the numbers of two files equal at the suite's
# tolerances (numdiff), else fail with MESSAGE and the first differences.
compare() {
  numdiff -q -a 1e-6 -r 1e-8 -s ' \t\n=,:;<>[](){}^' "$1" "$2" > /dev/null ||
    { diff "$1" "$2" | head -20; fail "$3"; }
}
# The summary lines (not the per-step lines) of a test-mode printout.
summary() { grep -v "^step \|^Stopped\|checkpoint" "$1"; }
# A csv file without its time columns (wall times differ between runs).
untimed() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) keep[i] = ($i !~ /seconds|^time_/) }
           { line = ""; for (i = 1; i <= NF; ++i) if (keep[i]) line = line $i ",";
             print line }' "$1"
}
