#!/usr/bin/env bash
# The figures of doc/benchmarks/factor_of_safety.md: the factor of safety of
# Griffiths and Lane's slope (prm/slope_factor_of_safety.prm) and of a
# steeper one, by strength reduction on two grids and with four displacement
# limits, against Bishop's simplified method (scripts/bishop_simplified.py),
# with the number of trials and the wall time of each search.
# Usage: scripts/factor_of_safety_study.sh IMPM [WORK_DIRECTORY]
# About 25 minutes on one core of the reference machine.
set -euo pipefail
impm=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=${2:-/tmp/factor_of_safety_study}
mkdir -p "$work" && cd "$work"
scene=$root/prm/slope_factor_of_safety.prm
steep=(--set "Body 1/Vertices=0, 0; 22, 0; 12, 10; 0, 10"
       --set "Body 1/Material/Mohr-Coulomb/Cohesion=2e4")

echo "Bishop's simplified method (independent script):"
echo -n "  2:1, c/(gamma H) = 0.05: "
python3 "$root/scripts/bishop_simplified.py" --surface "0,10; 12,10; 32,0; 60,0" \
  --base 0 --left 0 --unit-weight 20e3 --cohesion 10e3 --friction 20 | head -1
echo -n "  1:1, c/(gamma H) = 0.10: "
python3 "$root/scripts/bishop_simplified.py" --surface "0,10; 12,10; 22,0; 60,0" \
  --base 0 --left 0 --unit-weight 20e3 --cohesion 20e3 --friction 20 | head -1

# search NAME ARGS...: one strength reduction; its last line and trial count.
search() {
  local name=$1
  shift
  "$impm" "$scene" --set "Output directory=$work/$name" "$@" > "$name.log" 2>&1 ||
    { echo "  $name: failed"; tail -2 "$name.log"; return; }
  echo "  $name: $(tail -1 "$name.log")"
}

echo "Strength reduction, failure displacement 0.1 m (1 % of H), tolerance 0.01:"
for slope in gentle steep; do
  extra=()
  [ $slope = steep ] && extra=("${steep[@]}")
  for cells in "80, 24" "160, 48"; do
    search "${slope}_${cells/, /x}" "${extra[@]}" --set "Grid/Number of cells=$cells" \
      --set "Strength reduction/Tolerance=0.01"
  done
done

echo "The displacement limit, gentle slope, h = 0.5 m, tolerance 0.01:"
for limit in 0.05 0.1 0.2 0.5 0; do
  search "limit_$limit" --set "Strength reduction/Failure displacement=$limit" \
    --set "Strength reduction/Tolerance=0.01"
done

echo "The tolerance (trials and time), gentle slope, h = 0.5 m:"
for tolerance in 0.1 0.03 0.01 0.003; do
  search "tolerance_$tolerance" --set "Strength reduction/Tolerance=$tolerance"
done
