# Sourced by the studies that time repeated runs (inertia_accuracy_cost.sh,
# implicit_explicit_study.sh): run NAME SCENE ARGS... runs "$impm" on SCENE
# with its output in directory NAME and its terminal in NAME.log, stops the
# study if the run fails, and keeps the smallest wall time of NAME's runs
# in best[NAME]. The caller sets impm.
declare -A best
run() {
  local name=$1 scene=$2
  shift 2
  rm -rf "$name"
  local start end t
  start=$(date +%s.%N)
  "$impm" "$scene" --set "Output directory=$name" "$@" > "$name.log" 2>&1 ||
    { echo "$name failed"; tail -3 "$name.log"; exit 1; }
  end=$(date +%s.%N)
  t=$(echo "$end - $start" | bc)
  if [ -z "${best[$name]:-}" ] || [ "$(echo "$t < ${best[$name]}" | bc)" = 1 ]; then best[$name]=$t; fi
}
