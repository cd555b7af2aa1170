#!/usr/bin/env bash
# What the point files' compression ('Output/Compression') costs: for each
# scene below and each level, the run's 'output' phase (TimerOutput), the
# size of its output directory and the number of files, the three levels
# interleaved and each run three times (the smallest phase time kept).
# Usage: scripts/output_compression_study.sh build/impm [REPEATS]
# Prints a Markdown table (doc/benchmarks/start_and_progress.md, "Writing
# the files"). About 2 minutes.
set -euo pipefail
impm=$(realpath "$1")
repeats=${2:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# name|scene|overrides (';'-separated)
scenes=(
  "2D collapse, 36,864 points, 10 steps|$root/prm/collapse.prm|Grid/Number of cells=64, 32;Body 1/Points per cell direction=6;Solver/Load steps=10;Output/Interval=1"
  "3D collapse, 16x16x8 cells, 10 steps|$root/prm/collapse_3d.prm|Solver/Load steps=10;Output/Interval=1"
  "axisymmetric plate, 25,600 points, 10 explicit steps, grid fields|$root/prm/circular_plate_axisymmetric.prm|Inertia/Enabled=true;Inertia/Integrator=explicit USL;Time/End time=0.005;Time/Time step=0.0005;Output/Interval=1;Output/Grid fields=all"
)
levels=("best speed" "best compression" "none")

declare -A phase size files total
for entry in "${scenes[@]}"; do
  IFS='|' read -r name scene overrides <<< "$entry"
  args=()
  IFS=';' read -ra sets <<< "$overrides"
  for s in "${sets[@]}"; do args+=(--set "$s"); done
  for r in $(seq "$repeats"); do
    for level in "${levels[@]}"; do
      rm -rf out
      "$impm" "$scene" "${args[@]}" --set "Output/Compression=$level" \
        --set "Output directory=out" > run.log 2>&1 ||
        { echo "$name, $level: the run failed"; tail -2 run.log; exit 1; }
      t=$(awk -F'|' '$2 ~ /^ output / {gsub(/[ s]/, "", $4); print $4}' run.log)
      key="$name|$level"
      if [ -z "${phase[$key]:-}" ] || [ "$(echo "$t < ${phase[$key]}" | bc)" = 1 ]; then
        phase[$key]=$t
        total[$key]=$(grep -o 'wall time [0-9.]* m\?s' run.log | tail -1 |
          awk '{print ($4 == "ms" ? $3 / 1000 : $3)}')
      fi
      size[$key]=$(du -sk out | cut -f1)
      files[$key]=$(find out -name '*.vtu' | wc -l)
    done
  done
done

echo "| scene | compression | output phase (s) | run (s) | VTU files | output size (MB) |"
echo "|---|---|---|---|---|---|"
for entry in "${scenes[@]}"; do
  IFS='|' read -r name scene overrides <<< "$entry"
  for level in "${levels[@]}"; do
    key="$name|$level"
    printf "| %s | %s | %s | %s | %s | %.1f |\n" "$name" "$level" "${phase[$key]}" \
      "${total[$key]}" "${files[$key]}" "$(echo "${size[$key]} / 1024" | bc -l)"
  done
done
