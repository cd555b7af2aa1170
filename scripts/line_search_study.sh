#!/usr/bin/env bash
# 'Solver/Line search' against full Newton steps on the scenes of prm/ that
# run in seconds and on the granular collapse at aspect ratio 7 (three
# grids), the two settings one after the other for each scene
# (doc/benchmarks/line_search.md). Prints per run the load steps, cuts,
# Newton iterations, line-search residuals and wall time, and for the pair
# the largest relative difference of the last converged step's answers
# (steps.csv's energies, reactions and measures; not its times, step
# counts or residuals).
# Usage: scripts/line_search_study.sh [IMPM]
impm=${1:-build/impm}
impm=$(cd "$(dirname "$impm")" && pwd)/$(basename "$impm")
prm=$(cd "$(dirname "$0")/.." && pwd)/prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
granular=(--set "Body 1/Upper corner=1, 7" --set "Body 1/Material/Mohr-Coulomb/Friction angle=35.26"
  --set "Grid/Upper corner=12.6, 7.25" --set "Output/Interval=0")
run_pair() {
  local label=$1 scene=$2
  shift 2
  for search in false true; do
    start=$(date +%s.%N)
    "$impm" "$prm/$scene" --set "Output directory=${label}_$search" \
      --set "Solver/Line search=$search" "$@" > "${label}_$search.txt" 2>&1 ||
      echo "$label, line search $search: failed: $(grep -m1 '^Error' "${label}_$search.txt" | cut -c1-160)"
    end=$(date +%s.%N)
    echo "$start $end" > "${label}_$search.time"
  done
  /usr/bin/python3 - "$label" <<'PY'
import csv, re, sys
label = sys.argv[1]
def last(name):
    try:
        rows = [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
    except OSError:
        return None
    return rows[-1] if rows else None
cells = []
for search in ("false", "true"):
    name = "%s_%s" % (label, search)
    text = open(name + ".txt").read()
    m = re.search(r"(\d+) load steps \((\d+) cuts?\), (\d+) Newton iterations(?: \(and (\d+) line-search residuals\))?", text)
    start, end = map(float, open(name + ".time").read().split())
    if m:
        cells.append("%s/%s/%s/%s %.1f s" % (m.group(1), m.group(2), m.group(3), m.group(4) or 0, end - start))
    else:
        cells.append("failed %.1f s" % (end - start))
a, b = last(label + "_false"), last(label + "_true")
difference = "-"
if a and b and a["load_factor"] == b["load_factor"]:
    skip = re.compile(r"^(step|load_factor|load_increment|time|converged|newton_iterations|relative_residual|system_dofs)$|^time_")
    keys = [k for k in a if not skip.search(k) and k in b]
    # Against the largest answer of the step (a reaction of 1e-6 N beside
    # a weight of 6.4e5 N is round-off, not an answer).
    largest = max([abs(float(a[k])) for k in keys] + [1e-300])
    worst = 0.0
    for key in keys:
        x, y = float(a[key]), float(b[key])
        scale = max(abs(x), abs(y), 1e-6 * largest)
        worst = max(worst, abs(x - y) / scale)
    difference = "%.1e" % worst
elif a and b:
    difference = "ended at %s / %s" % (a["load_factor"], b["load_factor"])
print("| %s | %s | %s | %s |" % (label, cells[0], cells[1], difference))
PY
}
echo "| scene | full steps: steps/cuts/iterations/line-search, time | line search | answers differ by |"
echo "|---|---|---|---|"
for scene in collapse strip_footing strip_footing_mohr_coulomb strip_footing_rigid strip_footing_force \
  strip_footing_cam_clay rigid_plate wheel_rolling pipe_penetration slope_mohr_coulomb \
  collapse_cam_clay granular_column_collapse circular_footing_tresca two_bodies cantilever; do
  run_pair "$scene" "$scene.prm"
done
run_pair "granular_a7_h0.1" granular_column_collapse.prm "${granular[@]}" \
  --set "Grid/Number of cells=126, 73" --set "Time/End time=0.1" --set "Solver/Load steps=10"
run_pair "granular_a7_h0.05" granular_column_collapse.prm "${granular[@]}" \
  --set "Grid/Number of cells=252, 145" --set "Time/End time=0.05" --set "Solver/Load steps=10"
run_pair "granular_a7_h0.025" granular_column_collapse.prm "${granular[@]}" \
  --set "Grid/Number of cells=504, 290" --set "Time/End time=0.0125" --set "Solver/Load steps=5"
