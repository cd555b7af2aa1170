#!/usr/bin/env bash
# Implicit against explicit dynamics on the same scenes: error against wall
# time (doc/benchmarks/accuracy_cost.md, "Implicit against explicit").
# Usage: scripts/implicit_explicit_study.sh [IMPM] [REPEATS] [FIGURES_DIRECTORY]
#  1. The vibrating bar (tests/vibrating_bar.prm, v0 = 0.01 m/s, two
#     periods, GIMP): the trapezoidal rule at 25-400 steps a period,
#     generalised-alpha (spectral radius 0.8) at 25-200, explicit central
#     differences (MUSL) at Courant numbers 0.5, 0.25 and 0.125 (200, 400
#     and 800 steps a period) and USL at 0.5. Error: the largest difference
#     of the tip's displacement from the analytical solution over the first
#     period, of the amplitude.
#  2. The paper's collapse with inertia (tests/collapse_h1.prm, gravity at
#     once, mass damping 2 1/s, 8 s): generalised-alpha (0.8) at time steps
#     of 0.1 to 0.0125 s, explicit MUSL at 0.0125 (Courant number 0.46),
#     0.00625 and 0.003125 s, against a reference run (generalised-alpha at
#     0.0015625 s, 5,120 steps). Error: the largest difference of the
#     kinetic energy from the reference's at the same times, of the
#     reference's peak (the motion); and the larger of the run-out's and
#     the height's difference from the reference's, of the reference's
#     (the final state, at rest).
# Each configuration runs REPEATS times (3 by default), the repeats
# interleaved; the smallest wall time counts. Writes implicit_explicit.csv
# and the two figures to FIGURES_DIRECTORY (doc/benchmarks by default).
set -e
impm=${1:-build/impm}
repeats=${2:-3}
here=$(cd "$(dirname "$0")/.." && pwd)
figures=$(cd "${3:-$here/doc/benchmarks}" && pwd)
impm=$(cd "$(dirname "$impm")" && pwd)/$(basename "$impm")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
bar=$here/tests/vibrating_bar.prm
collapse=$here/tests/collapse_h1.prm
source "$here/scripts/best_wall_time.sh"
# NAME:integrator:steps a period or time step:extra entries
bar_cases=(trapezoidal_25:Newmark:25 trapezoidal_50:Newmark:50
           trapezoidal_100:Newmark:100 trapezoidal_200:Newmark:200
           trapezoidal_400:Newmark:400
           alpha_25:generalised-alpha:25 alpha_50:generalised-alpha:50
           alpha_100:generalised-alpha:100 alpha_200:generalised-alpha:200
           musl_200:explicit\ MUSL:200:0.5 musl_400:explicit\ MUSL:400:0.25
           musl_800:explicit\ MUSL:800:0.125 usl_200:explicit\ USL:200:0.5)
collapse_cases=(alpha_0.1:generalised-alpha:0.1 alpha_0.05:generalised-alpha:0.05
                alpha_0.025:generalised-alpha:0.025 alpha_0.0125:generalised-alpha:0.0125
                musl_0.0125:explicit\ MUSL:0.0125 musl_0.00625:explicit\ MUSL:0.00625
                musl_0.003125:explicit\ MUSL:0.003125)
collapse_common=(--set "Gravity/Ramped=false" --set "Time/End time=8" --set "Inertia/Enabled=true"
                 --set "Inertia/Mass damping=2" --set "Output/Interval=0")
run_bar() {
  IFS=: read -r name integrator per_period courant <<< "$1"
  local options=(--set "Time/End time=20" --set "Inertia/Initial velocity=0.01*sin(pi*x/50); 0"
                 --set "Inertia/Integrator=$integrator" --set "Solver/Load steps=$((2 * per_period))")
  [ "$integrator" = generalised-alpha ] && options+=(--set "Inertia/Spectral radius=0.8")
  [ -n "$courant" ] && options+=(--set "Inertia/Courant number=$courant")
  run "bar_$name" "$bar" "${options[@]}"
}
run_collapse() {
  IFS=: read -r name integrator step <<< "$1"
  local options=("${collapse_common[@]}" --set "Inertia/Integrator=$integrator" --set "Time/Time step=$step")
  [ "$integrator" = generalised-alpha ] && options+=(--set "Inertia/Spectral radius=0.8")
  run "collapse_$name" "$collapse" "${options[@]}"
}
run_collapse reference:generalised-alpha:0.0015625
for ((r = 0; r < repeats; ++r)); do
  for case in "${bar_cases[@]}"; do run_bar "$case"; done
  for case in "${collapse_cases[@]}"; do run_collapse "$case"; done
done
{
  echo "scene,case,integrator,steps,error,final_error,wall_seconds"
  for case in "${bar_cases[@]}"; do
    IFS=: read -r name integrator _ <<< "$case"
    /usr/bin/python3 - "bar_$name" "$integrator" "${best[bar_$name]}" <<'PY'
import csv, math, sys
name, integrator, wall = sys.argv[1], sys.argv[2], float(sys.argv[3])
rows = list(csv.DictReader(open(name + "/point_history.csv")))
steps = [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
omega = math.pi * 10 / 50
amplitude = 0.01 / omega * math.sin(math.pi * float(rows[0]["x"]) / 50)
error = max(abs(float(r["displacement_x"]) - amplitude * math.sin(omega * float(r["time"])))
            for r in rows if float(r["time"]) <= 10 + 1e-9) / amplitude
print("bar,%s,%s,%d,%.4e,,%.3f" % (name[4:], integrator, len(steps), error, wall))
PY
  done
  final() { # LOG AXIS: the final upper extent of the points along AXIS
    grep -o "extent in $2: .*final \[[^,]*, [^]]*" "$1" | sed 's/.*, //'
  }
  reference_x=$(final collapse_reference.log x)
  reference_y=$(final collapse_reference.log y)
  for case in "${collapse_cases[@]}"; do
    IFS=: read -r name integrator _ <<< "$case"
    /usr/bin/python3 - "collapse_$name" "$integrator" "${best[collapse_$name]}" \
      "$(final "collapse_$name.log" x)" "$(final "collapse_$name.log" y)" "$reference_x" "$reference_y" <<'PY'
import csv, sys
name, integrator, wall = sys.argv[1], sys.argv[2], float(sys.argv[3])
x, y, rx, ry = map(float, sys.argv[4:8])
def history(directory):
    rows = [r for r in csv.DictReader(open(directory + "/steps.csv")) if r["converged"] == "1"]
    return {round(float(r["time"]), 9): float(r["kinetic_energy"]) for r in rows}
run, reference = history(name), history("collapse_reference")
peak = max(reference.values())
kinetic = max(abs(e - reference[t]) for t, e in run.items() if t in reference) / peak
final = max(abs(x - rx) / rx, abs(y - ry) / ry)
print("collapse,%s,%s,%d,%.4e,%.4e,%.3f" % (name[9:], integrator, len(run), kinetic, final, wall))
PY
  done
} > implicit_explicit.csv
cat implicit_explicit.csv
echo "reference collapse: run-out $(final collapse_reference.log x) m, height $(final collapse_reference.log y) m, wall ${best[collapse_reference]} s"
cp implicit_explicit.csv "$figures/implicit_explicit.csv"
/usr/bin/python3 - "$figures" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open("implicit_explicit.csv")))
integrators = (("Newmark", "o", "Newmark (trapezoidal)"), ("generalised-alpha", "s", "generalised-alpha (0.8)"),
               ("explicit MUSL", "^", "explicit MUSL"), ("explicit USL", "v", "explicit USL"))
def panel(axes, scene, column, ylabel, title):
    for integrator, marker, label in integrators:
        points = [r for r in rows if r["scene"] == scene and r["integrator"] == integrator]
        if not points:
            continue
        points.sort(key=lambda r: int(r["steps"]))
        axes.loglog([float(r["wall_seconds"]) for r in points], [float(r[column]) for r in points],
                    marker=marker, label=label)
        for r in points:
            axes.annotate(r["steps"], (float(r["wall_seconds"]), float(r[column])),
                          textcoords="offset points", xytext=(4, 3), fontsize=7)
    axes.set_xlabel("wall time, s (one process; labels: steps)")
    axes.set_ylabel(ylabel, fontsize=9)
    axes.set_title(title, fontsize=9)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=7)
figure, axes = plt.subplots(figsize=(6.4, 4.4))
panel(axes, "bar", "error", "tip displacement error over the first period / amplitude",
      "Vibrating bar (v0 = 0.01 m/s, two periods, 108 points)")
figure.tight_layout()
figure.savefig(sys.argv[1] + "/implicit_explicit_bar.png", dpi=100)
figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
panel(left, "collapse", "error", "kinetic energy: largest difference / reference's peak",
      "Collapse with inertia: the motion (576 points, 8 s)")
panel(right, "collapse", "final_error", "run-out and height at rest: larger difference",
      "Collapse with inertia: the final state")
figure.tight_layout()
figure.savefig(sys.argv[1] + "/implicit_explicit_collapse.png", dpi=100)
PY
echo "figures: $figures/implicit_explicit_bar.png, $figures/implicit_explicit_collapse.png"
