#!/usr/bin/env bash
# Error of the column (eq. 13 of the paper) under h-refinement, for GIMP and
# standard MPM with 2x2 and 3x3 points per cell, and the average rate.
# Usage: scripts/column_convergence.sh [build/impm] > table.md
set -euo pipefail
impm=${1:-build/impm}
impm=$(realpath "$impm")
scene=$(realpath "$(dirname "$0")/../prm/column_compaction.prm")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cells="4 8 16 32 64 128"
echo "| basis | points per cell | $(echo $cells | sed 's/ / | /g') | average rate |"
echo "|---|---|$(for c in $cells; do printf -- '---|'; done)---|"
for basis in "GIMP" "standard MPM"; do
  for n in 2 3; do
    row="| $basis | ${n}x${n} |"
    first="" last=""
    for c in $cells; do
      width=$(awk "BEGIN{print 50/$c}")
      "$impm" "$scene" --set "Grid/Number of cells=1, $c" \
        --set "Grid/Upper corner=$width, 50" \
        --set "Body 1/Upper corner=$width, 50" \
        --set "Body 1/Points per cell direction=$n" \
        --set "Material points/Basis=$basis" \
        --set "Output/Interval=0" > log.txt
      error=$(sed -n 's/.*"error_sigma_zz": \([^,]*\),/\1/p' output/summary.json)
      row="$row $(printf '%.3e' "$error") |"
      [ -z "$first" ] && first=$error
      last=$error
    done
    rate=$(awk "BEGIN{printf \"%.2f\", log($first/$last)/log(2)/5}")
    echo "$row $rate |"
  done
done
