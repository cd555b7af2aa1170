# Sourced by the script tests: IMPM and the scene from the arguments, an
# optional launcher ("MPIEXEC N" after them), a scratch directory to work
# in, removed at the end, and fail() that prints the log and stops.
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
