#!/usr/bin/env bash
# The whole accuracy-cost study: runs, figures, tables and renders in
# doc/benchmarks/.  Usage: scripts/run_study.sh [build/impm]
#
#   1. column: 4 ... 256 cells x {2x2, 3x3} x {GIMP, standard MPM}, 5
#      interleaved repetitions
#   2. column, 16 cells, 2x2: every point's final vertical stress (Figure 1b)
#   3. formulation comparison: column, 64 cells, 2x2, GIMP, previously
#      converged vs updated Lagrangian, 5 interleaved repetitions; the same
#      on the collapse (h = 0.5 m, 6x6, 3 repetitions); then one Testing run
#      of each column case (16 significant digits) for the equality check;
#      then build/impm-formulation-kernels, the per-point cost of each form
#   4. collapse: h = 1, 0.5, 0.25 m x {3x3, 6x6}, point files of the initial
#      and final state (kept in $STUDY_WORK, default build/study/)
#   5. doc/scripts/plot_study.py (figures; tables into doc/benchmarks/accuracy_cost.md,
#      the machine into doc/benchmarks/README.md)
#   6. scripts/render_collapse.py (ParaView under xvfb-run, else matplotlib)
#
# Runs impm one job at a time.  Needs /usr/bin/python3 with numpy,
# matplotlib and vtk (python3-vtk9); for the renders paraview,
# python3-paraview and xvfb.  A failed run is reported and marked in the CSV;
# the study goes on and the script exits 1 at the end.
set -uo pipefail
start=$(date +%s.%N)
root=$(cd "$(dirname "$0")/.." && pwd)
impm=$(realpath "${1:-$root/build/impm}")
py=/usr/bin/python3
out=$root/doc/benchmarks
work=${STUDY_WORK:-$root/build/study}
study="$py $root/scripts/study.py"
column=$root/prm/column_compaction.prm
collapse=$root/prm/collapse.prm
status=0

[ -x "$impm" ] || { echo "run_study.sh: no executable $impm" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work" "$out"

elapsed() { awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN{printf "%.0f", b - a}'; }
stage() { printf '\n== %s (%s s)\n' "$1" "$(elapsed)"; }

{
  echo "date:       $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "nproc:      $(nproc)"
  echo "cpu:        $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
  echo "memory:     $(free -g | awk '/^Mem:/{print $2}') GiB"
  echo "os:         $(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "compiler:   $(c++ --version | head -1)"
  echo "build type: $(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$root/build/CMakeCache.txt" 2>/dev/null)"
  echo "deal.II:    $(dpkg-query -W -f '${Version}' libdeal.ii-dev 2>/dev/null)"
  echo "impm:       $(realpath --relative-to="$PWD" "$impm" 2>/dev/null || basename "$impm"), built $(date -u -r "$impm" '+%Y-%m-%d %H:%M UTC')"
  echo "commit:     $(git -C "$root" rev-parse --short HEAD 2>/dev/null)$(git -C "$root" diff --quiet HEAD -- source include 2>/dev/null || echo ' (sources modified in the work tree)')"
  echo "processes:  1 (serial runs, one at a time)"
  echo "load avg:   $(cut -d' ' -f1-3 /proc/loadavg) at the start"
} > "$out/machine.txt"
cat "$out/machine.txt"

stage "column: cells x points per cell x basis, 5 interleaved repetitions"
$study "$column" --column-cells 4,8,16,32,64,128,256 \
  --set "Material points/Basis=GIMP|standard MPM" \
  --set "Body 1/Points per cell direction=2|3" \
  --set Output/Interval=0 --repeat 5 --interleave \
  --out "$out/column.csv" --impm "$impm" || status=1

stage "column, 16 cells, 2x2: final points (Figure 1b)"
$study "$column" --column-cells 16 \
  --set "Material points/Basis=GIMP|standard MPM" \
  --set "Body 1/Points per cell direction=2" --set Output/Interval=0 \
  --points-out "$out/column_points_16.csv" \
  --out "$work/column_points_16_runs.csv" --impm "$impm" || status=1

stage "formulation comparison: timing, 5 repetitions (interleaved)"
$study "$column" --column-cells 64 \
  --set "Solver/Formulation=previously converged|updated Lagrangian" \
  --set "Material points/Basis=GIMP" --set "Body 1/Points per cell direction=2" \
  --set Output/Interval=0 --repeat 5 --interleave \
  --out "$out/formulation.csv" --impm "$impm" || status=1

stage "formulation comparison on a larger problem: collapse, h = 0.5 m, 6x6, 3 repetitions"
$study "$collapse" \
  --set "Solver/Formulation=previously converged|updated Lagrangian" \
  --set "Body 1/Points per cell direction=6" --set Output/Interval=0 \
  --set "Solver/Estimate condition number=false" --repeat 3 --interleave \
  --out "$out/formulation_collapse.csv" --impm "$impm" || status=1

stage "formulation comparison: final points (Testing printout)"
$study "$column" --column-cells 64 \
  --set "Solver/Formulation=previously converged|updated Lagrangian" \
  --set "Material points/Basis=GIMP" --set "Body 1/Points per cell direction=2" \
  --set Output/Interval=0 --set "Testing/Significant digits=16" \
  --points-out "$out/formulation_points.csv" --keep "$work/formulation" \
  --out "$work/formulation_testing.csv" --impm "$impm" || status=1

stage "formulation kernels: per-point cost of each form"
kernels=$(dirname "$impm")/impm-formulation-kernels
if [ -x "$kernels" ]; then
  "$kernels" > "$out/formulation_kernels.md" || status=1
  cat "$out/formulation_kernels.md"
else
  echo "run_study.sh: no $kernels (cmake --build build builds it)" >&2
  status=1
fi

stage "collapse: h = 1, 0.5, 0.25 m x 3x3, 6x6"
$study "$collapse" \
  --set "Grid/Number of cells=16, 8|32, 16|64, 32" \
  --set "Body 1/Points per cell direction=3|6" \
  --set Output/Interval=1000 --reference-finest \
  --keep "$work/collapse" --out "$out/collapse.csv" --impm "$impm" || status=1

echo "load avg:   $(cut -d' ' -f1-3 /proc/loadavg) after the runs" >> "$out/machine.txt"

stage "figures and tables"
$py "$root/doc/scripts/plot_study.py" --data "$out" \
  --formulation-runs "$work/formulation" --page "$out/accuracy_cost.md" \
  --page "$out/README.md" > "$work/tables.md" || status=1
echo "tables: $work/tables.md"

stage "collapse renders"
$py "$root/scripts/render_collapse.py" --runs "$work/collapse" --out "$out" || status=1

printf '\nrun_study.sh: total time %s s (%s)\n' "$(elapsed)" \
  "$([ $status = 0 ] && echo 'all steps succeeded' || echo 'SOME STEPS FAILED, see above')"
exit $status
