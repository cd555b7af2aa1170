#!/usr/bin/env bash
# What keeping the AMG hierarchy over a load step saves: the 2D collapse at
# h = 0.25 m with 6x6 points per cell (36,864 points, GMRES with AMG) and
# the 3D quarter collapse (prm/collapse_3d.prm, h = 1 m), each with the
# given 'Solver/AMG reuse factor's on 1 and 2 processes, configurations
# interleaved and repeated. Prints per run the wall time, Newton
# iterations, cuts, the linear solve, assembly and setup phases, the GMRES
# iterations per solve and the hierarchies built, then the median linear
# solve and wall time of each configuration.
# Usage: scripts/amg_reuse.sh IMPM [REPETITIONS=2] [FACTORS="0 2"]
set -eu
impm=$1
repetitions=${2:-2}
read -r -a factors <<< "${3:-0 2}"
prm=$(cd "$(dirname "$0")/.." && pwd)/prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
for repetition in $(seq "$repetitions"); do
  for scene in 2d 3d; do
    for factor in "${factors[@]}"; do
      for processes in 1 2; do
        out="$work/run"
        rm -rf "$out"
        if [ "$scene" = 2d ]; then
          settings=("$prm/collapse.prm" --set "Grid/Number of cells=64, 32"
                    --set "Body 1/Points per cell direction=6"
                    --set "Solver/Linear solver=GMRES with AMG")
        else
          settings=("$prm/collapse_3d.prm")
        fi
        mpirun -np "$processes" "$impm" "${settings[@]}" --set "Output/Interval=0" \
          --set "Solver/AMG reuse factor=$factor" --set "Output directory=$out" > "$work/log.txt"
        built=$(sed -n 's/^AMG hierarchy built for \([0-9]* of [0-9]*\) .*/\1/p' "$work/log.txt")
        python3 - "$out" "$scene" "$factor" "$processes" "$built" >> "$work/runs.txt" <<'PY'
import csv, json, sys
out, scene, factor, processes, built = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
its = [int(r["linear_iterations"]) for r in csv.DictReader(open(out + "/newton.csv"))
       if r["linear_iterations"]]
p = s["wall_time_per_phase"]
print("%s|%s|%s|%.2f|%.2f|%d|%d|%.2f|%.2f|%.1f|%d|%s" % (
    scene, factor, processes, s["wall_time"], p["linear solve"], s["newton_iterations"],
    s["load_step_cuts"], p["assembly"], p["system setup"], sum(its) / len(its), max(its), built))
PY
        tail -1 "$work/runs.txt"
      done
    done
  done
done
python3 - "$work/runs.txt" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    scene, factor, processes, wall, linear, *_ = line.split("|")
    runs.setdefault((scene, factor, processes), []).append((float(wall), float(linear)))
print("scene | reuse factor | processes | median wall (s) | median linear solve (s)")
for key, values in sorted(runs.items()):
    print("%s | %s | %s | %.2f | %.2f" % (key + (statistics.median(v[0] for v in values),
                                            statistics.median(v[1] for v in values))))
PY
