#!/bin/bash
# The strip footings with and without F-bar under refinement (issue 12):
# the von Mises footing on a stiff layer (prm/strip_footing.prm with
# E = 100 MPa and 0.02 m settlement, Prandtl 36.36 kN) and the Mohr-Coulomb
# footing (prm/strip_footing_mohr_coulomb.prm, Prandtl 74.2 kN). One run at
# a time; prints one line per run (cells, F-bar, seconds, steps, Newton
# iterations, final load in kN) and draws the von Mises curves. 'mc-pressures'
# runs the Mohr-Coulomb footing with F-bar's cell pressure unknowns (standard
# MPM and GIMP) and without F-bar (standard MPM), 6 mm in 24 steps, with the
# direct solver, at h = B/4, B/8 and B/16, prints the peak load too, and
# draws those curves; 'mc-pressures-finest' the standard-MPM run at B/32
# (about 10 minutes).
# Usage: scripts/footing_study.sh build/impm OUTDIR [vm|mc|mc-pressures|mc-pressures-finest|all]
set -e
impm=$(realpath "$1")
out=$2
which=${3:-all}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
run() { # name prm cells f-bar extra...
  local name=$1 prm=$2 cells=$3 fbar=$4
  shift 4
  local start=$(date +%s.%N)
  "$impm" "$prm" --set "Grid/Number of cells=$cells" \
    --set "Material points/F-bar=$fbar" --set "Output/Interval=0" \
    --set "Output directory=$out/$name" "$@" > "$out/$name.log" 2>&1 || true
  local end=$(date +%s.%N)
  awk -F, -v n="$name" -v t="$(echo "$end - $start" | bc)" \
    'NR > 1 && $4 == 1 {steps++; it += $5; load = -$13 / 1000}
     NR > 1 {all_it += $5}
     NR > 1 && $4 == 1 && -$13 / 1000 > peak {peak = -$13 / 1000}
     END {printf "%-28s %7.1f s  %4d steps  %5d Newton iterations  %8.2f kN (peak %.2f kN)\n", n, t, steps, all_it, load, peak}' \
    "$out/$name/steps.csv"
}
if [ "$which" = vm ] || [ "$which" = all ]; then
  for cells in "20, 8" "40, 16" "80, 32"; do
    for fbar in false true; do
      run "vm_${cells/, /x}_fbar_$fbar" "$root/prm/strip_footing.prm" "$cells" $fbar \
        --set "Body 1/Material/von Mises/Young's modulus=1e8" \
        --set "Grid/Displacement y+=0, -0.02"
    done
  done
  /usr/bin/python3 "$root/doc/scripts/footing_curves.py" "$out/footing_von_mises.png" 36.36 0.02 \
    "h = 0.25 m, F-bar off=$out/vm_20x8_fbar_false/steps.csv" \
    "h = 0.25 m, F-bar on=$out/vm_20x8_fbar_true/steps.csv" \
    "h = 0.125 m, F-bar off=$out/vm_40x16_fbar_false/steps.csv" \
    "h = 0.125 m, F-bar on=$out/vm_40x16_fbar_true/steps.csv" \
    "h = 0.0625 m, F-bar off=$out/vm_80x32_fbar_false/steps.csv" \
    "h = 0.0625 m, F-bar on=$out/vm_80x32_fbar_true/steps.csv"
fi
if [ "$which" = mc ] || [ "$which" = all ]; then
  for cells in "20, 9" "40, 18" "80, 36"; do
    run "mc_${cells/, /x}_fbar_true" "$root/prm/strip_footing_mohr_coulomb.prm" "$cells" true
  done
fi
mc_pressures() { # name cells basis f-bar pressures
  run "$1" "$root/prm/strip_footing_mohr_coulomb.prm" "$2" "$4" \
    --set "Material points/Basis=$3" --set "Material points/Cell pressure unknowns=$5" \
    --set "Grid/Displacement y+=0, -0.006" --set "Solver/Load steps=24" \
    --set "Solver/Linear solver=direct"
}
if [ "$which" = mc-pressures ] || [ "$which" = all ]; then
  for cells in "20, 9" "40, 18" "80, 36"; do
    c=${cells/, /x}
    mc_pressures "mcp_${c}_smpm_pressures" "$cells" "standard MPM" true true
    mc_pressures "mcp_${c}_gimp_pressures" "$cells" GIMP true true
    mc_pressures "mcp_${c}_smpm_none" "$cells" "standard MPM" false false
  done
  /usr/bin/python3 "$root/doc/scripts/footing_curves.py" "$out/footing_mohr_coulomb_pressures.png" 74.17 0.006 \
    "h = 0.25 m, cell pressures=$out/mcp_20x9_smpm_pressures/steps.csv" \
    "h = 0.25 m, no F-bar=$out/mcp_20x9_smpm_none/steps.csv" \
    "h = 0.125 m, cell pressures=$out/mcp_40x18_smpm_pressures/steps.csv" \
    "h = 0.125 m, no F-bar=$out/mcp_40x18_smpm_none/steps.csv" \
    "h = 0.0625 m, cell pressures=$out/mcp_80x36_smpm_pressures/steps.csv" \
    "h = 0.0625 m, no F-bar=$out/mcp_80x36_smpm_none/steps.csv"
fi
if [ "$which" = mc-pressures-finest ]; then
  run "mcp_160x72_smpm_pressures" "$root/prm/strip_footing_mohr_coulomb.prm" "160, 72" true \
    --set "Material points/Basis=standard MPM" --set "Material points/Cell pressure unknowns=true" \
    --set "Grid/Displacement y+=0, -0.005" --set "Solver/Load steps=20" \
    --set "Solver/Linear solver=direct"
fi
