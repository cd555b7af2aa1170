#!/usr/bin/env bash
# Interleaved runs of two impm executables on the collapse with 6x6 points per
# cell (9216 points, h = 0.5 m), printing the assembly and stress-update phase
# times of each run and the medians: the check that a change to the code
# structure does not slow the kernels down.
# Usage: scripts/compare_phase_times.sh OLD_IMPM NEW_IMPM [RUNS=5]
set -eu
old=$1
new=$2
runs=${3:-5}
scene=$(cd "$(dirname "$0")/.." && pwd)/prm/collapse.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for i in $(seq "$runs"); do
  for version in old new; do
    exe=$old
    [ "$version" = new ] && exe=$new
    "$exe" "$scene" --set "Body 1/Points per cell direction=6" \
      --set "Output directory=$work/$version" --set "Output/Interval=0" > /dev/null
    python3 -c "
import json; s = json.load(open('$work/$version/summary.json'))
p = s['wall_time_per_phase']
print('$version', p['assembly'], p['stress update'])" >> "$work/times.txt"
  done
done
python3 - "$work/times.txt" <<'PY'
import statistics, sys
times = {"old": ([], []), "new": ([], [])}
for line in open(sys.argv[1]):
    version, assembly, stress = line.split()
    times[version][0].append(float(assembly))
    times[version][1].append(float(stress))
    print(line.strip())
for k, name in ((0, "assembly"), (1, "stress update")):
    old, new = (statistics.median(times[v][k]) for v in ("old", "new"))
    print("%s: median old %.4f s, new %.4f s, new/old %.4f" % (name, old, new, new / old))
PY
