#!/usr/bin/env bash
# Interleaved runs of two impm builds on one scene, on 1 and 2 processes:
# for each run the wall time, Newton iterations, linear iterations and the
# phases; then per build and process count the medians, the old/new ratio
# and the speed-up of 2 processes over 1. Extra arguments are passed to impm
# (e.g. --set "Grid/Number of cells=64, 32"). Then the medians per phase
# (above 0.01 s) and their old/new ratio.
# Usage: scripts/compare_builds.sh OLD_IMPM NEW_IMPM SCENE REPETITIONS [ARGS...]
set -eu
old=$1
new=$2
scene=$(realpath "$3")
repetitions=$4
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
for repetition in $(seq "$repetitions"); do
  for processes in 1 2; do
    for build in old new; do
      exe=$old
      [ "$build" = new ] && exe=$new
      out="$work/run"
      rm -rf "$out"
      mpirun -np "$processes" "$exe" "$scene" --set "Output/Interval=0" \
        --set "Output directory=$out" "$@" > /dev/null
      python3 - "$out" "$build" "$processes" >> "$work/runs.txt" <<'PY'
import csv, json, sys
out, build, processes = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
linear = sum(int(r["linear_iterations"] or 0)
             for r in csv.DictReader(open(out + "/newton.csv")))
phases = " ".join("%s=%.2f" % (k.replace(" ", "_"), v)
                  for k, v in s["wall_time_per_phase"].items())
print("%s|%s|%.2f|%d|%d|%s" % (build, processes, s["wall_time"],
      s["newton_iterations"], linear, phases))
PY
      tail -1 "$work/runs.txt"
    done
  done
done
python3 - "$work/runs.txt" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    build, processes, wall, *_ = line.split("|")
    runs.setdefault((build, int(processes)), []).append(float(wall))
median = {k: statistics.median(v) for k, v in runs.items()}
for p in (1, 2):
    print("%d process(es): old %.2f s, new %.2f s, old/new %.2f"
          % (p, median[("old", p)], median[("new", p)],
             median[("old", p)] / median[("new", p)]))
for b in ("old", "new"):
    print("%s: speed-up of 2 processes over 1: %.2f"
          % (b, median[(b, 1)] / median[(b, 2)]))
# Per phase: the medians of each build and their ratio.
phases = {}
for line in open(sys.argv[1]):
    build, processes, wall, newton, linear, times = line.strip().split("|")
    for entry in times.split():
        name, value = entry.rsplit("=", 1)
        phases.setdefault((name, int(processes)), {}).setdefault(
            build, []).append(float(value))
for (name, p), builds in sorted(phases.items()):
    old = statistics.median(builds.get("old", [0.]))
    new = statistics.median(builds.get("new", [0.]))
    if old > 0.01 or new > 0.01:
        print("  %d process(es) %-18s old %7.2f s  new %7.2f s  old/new %s"
              % (p, name, old, new, "%.3f" % (old / new) if new > 0 else "-"))
PY
