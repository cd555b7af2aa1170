#!/usr/bin/env bash
# Runs every scene in prm/ (each shortened where its header says it is long)
# and checks that it completes, conserves mass, keeps every load step
# converged, and that its reactions balance its loads.
# Usage: prm_scenes.sh IMPM PRM_DIRECTORY
set -u
impm=$1
scenes=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
status=0
for scene in "$scenes"/*.prm; do
  name=$(basename "$scene" .prm)
  extra=()
  # The collapse on the coarse grid (h = 1 m) keeps the suite fast.
  [ "$name" = collapse ] && extra=(--set "Grid/Number of cells=16, 8")
  [ "$name" = collapse_3d ] && extra=(--set "Grid/Number of cells=8, 8, 4")
  # The million-point benchmark at h = 1 m with 2x2 points per cell: the scene
  # file, not the size, is what the suite checks.
  [ "$name" = collapse_million ] && extra=(--set "Grid/Number of cells=16, 8"
    --set "Body 1/Points per cell direction=2")
  # The 3D benchmark likewise at h = 2 m with 2x2x2 points per cell.
  [ "$name" = collapse_3d_benchmark ] && extra=(--set "Grid/Number of cells=8, 8, 4"
    --set "Body 1/Points per cell direction=2")
  # The Cam-clay collapse's first second (tests/collapse_cam_clay runs it
  # whole).
  [ "$name" = collapse_cam_clay ] && extra=(--set "Time/End time=1" --set "Solver/Load steps=20")
  # The factor of safety's scene once at its own strength (F = 1); its
  # search is tested by strength_reduction_slope.
  [ "$name" = slope_factor_of_safety ] && extra=(--set "Strength reduction/Enabled=false")
  if ! "$impm" "$scene" "${extra[@]}" --set Testing/Enabled=true \
         --set Output/Interval=0 --set "Output directory=$name" > "$name.txt" 2>&1; then
    echo "FAILED: $name did not complete"; tail -5 "$name.txt"; status=1; continue
  fi
  initial=$(sed -n 's/^total mass: \(\S*\) (initial \(\S*\))$/\2/p' "$name.txt")
  final=$(sed -n 's/^total mass: \(\S*\) (initial \(\S*\))$/\1/p' "$name.txt")
  [ -n "$final" ] && [ "$final" = "$initial" ] || { echo "FAILED: $name mass $initial -> $final"; status=1; }
  # A failed check ends its line in "NO", or says "NO (" with its value
  # (the tangent check).
  if grep -qE 'NO$|NO \(' "$name.txt"; then
    echo "FAILED: $name: $(grep -E 'NO$|NO \(' "$name.txt")"; status=1
  fi
  [ -s "$name/summary.json" ] || { echo "FAILED: $name wrote no summary.json"; status=1; }
  echo "$name: $(grep -c '^step' "$name.txt") load steps, $(grep -c ': step cut$' "$name.txt") cut, complete"
done
exit $status
