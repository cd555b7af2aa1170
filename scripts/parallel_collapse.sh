#!/usr/bin/env bash
# The collapse at h = 0.25 m with 6x6 points per cell (36,864 points) on 1
# and 2 processes with each linear solver, configurations interleaved and
# repeated; prints wall time, Newton iterations, cuts and the phases of each
# run, then the median wall time of each configuration and the speed-up of
# 2 processes over 1.
# Usage: scripts/parallel_collapse.sh IMPM [REPETITIONS=2] [SOLVERS="direct;GMRES with AMG"]
set -eu
impm=$1
repetitions=${2:-2}
IFS=';' read -r -a solvers <<< "${3:-direct;GMRES with AMG}"
scene=$(cd "$(dirname "$0")/.." && pwd)/prm/collapse.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
for repetition in $(seq "$repetitions"); do
  for solver in "${solvers[@]}"; do
    for processes in 1 2; do
      out="$work/run"
      rm -rf "$out"
      mpirun -np "$processes" "$impm" "$scene" --set "Grid/Number of cells=64, 32" \
        --set "Body 1/Points per cell direction=6" --set "Output/Interval=0" \
        --set "Solver/Linear solver=$solver" --set "Output directory=$out" > /dev/null
      python3 - "$out/summary.json" "$solver" "$processes" >> "$work/runs.txt" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
phases = " ".join("%s=%.2f" % (k.replace(" ", "_"), v) for k, v in s["wall_time_per_phase"].items())
print("%s|%s|%.2f|%d|%d|%s" % (sys.argv[2], sys.argv[3], s["wall_time"],
      s["newton_iterations"], s["load_step_cuts"], phases))
PY
      tail -1 "$work/runs.txt"
    done
  done
done
python3 - "$work/runs.txt" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    solver, processes, wall, *_ = line.split("|")
    runs.setdefault((solver, int(processes)), []).append(float(wall))
for solver in dict.fromkeys(k[0] for k in runs):
    one, two = (statistics.median(runs[(solver, p)]) for p in (1, 2))
    print("%s: median 1 process %.2f s, 2 processes %.2f s, speed-up %.2f"
          % (solver, one, two, one / two))
PY
