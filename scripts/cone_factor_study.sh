#!/usr/bin/env bash
# The cone factor of deep penetration (doc/benchmarks/axisymmetry.md, "The
# cone factor"): prm/cone_factor_axisymmetric.prm at the rigidity indices
# and grids given as I_R:NX (I_r = G/s_u, E = 2 (1 + nu) I_r s_u; NX cells
# across the 2 m grid, NX = 80 is the scene's h = R/4; default 50:80 100:80
# 200:80). Each run is kept in OUTPUT_DIRECTORY/cone_factor_runs/ and not
# repeated while its steps.csv is there. Prints per run N_kt = F/(pi R^2
# s_u) averaged over the converged steps from 1 R of push on (to 3 R, or to
# where a run stopped), its smallest and largest step value, Lu et al.'s
# (2004) 3.4 + 1.6 ln I_r for a smooth cone, the difference and the wall
# time; writes the histories to cone_factor.csv and the figure
# cone_factor.png in OUTPUT_DIRECTORY (default: the working directory).
# Usage: scripts/cone_factor_study.sh [IMPM] [OUTPUT_DIRECTORY] [I_R:NX ...]
impm=${1:-build/impm}
target=$(realpath "${2:-.}")
shift $(($# < 2 ? $# : 2))
runs=("$@")
[ ${#runs[@]} -eq 0 ] && runs=(50:80 100:80 200:80)
impm=$(cd "$(dirname "$impm")" && pwd)/$(basename "$impm")
scene=$(cd "$(dirname "$0")/.." && pwd)/prm/cone_factor_axisymmetric.prm
mkdir -p "$target/cone_factor_runs"
cd "$target/cone_factor_runs"
for run in "${runs[@]}"; do
  ir=${run%%:*}
  nx=${run##*:}
  ny=$((nx * 21 / 20))
  out=ir${ir}_${nx}
  [ -f $out/steps.csv ] && [ -f $out.wall ] && continue
  rm -f $out.stopped
  E=$(/usr/bin/python3 -c "print(2 * 1.49 * $ir * 1e4)")
  start=$(date +%s.%N)
  "$impm" "$scene" --set "Output directory=$out" --set "Output/Interval=0" \
    --set "Body 1/Material/Mohr-Coulomb/Young's modulus=$E" \
    --set "Grid/Number of cells=$nx, $ny" --overwrite > $out.txt 2>&1 ||
    echo "stopped" > $out.stopped
  end=$(date +%s.%N)
  /usr/bin/python3 -c "print($end - $start)" > $out.wall
done
/usr/bin/python3 - "$target" "${runs[@]}" <<'PY'
import csv, math, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
target, runs = sys.argv[1], sys.argv[2:]
R, su, push = 0.1, 1e4, 0.3
figure, axes = plt.subplots(figsize=(7, 4.2))
rows = []
drawn = set()  # Lu's value drawn once per rigidity, in its first run's colour
print("%-5s %-6s %-7s %-12s %-6s %-8s %-9s %s" % ("I_r", "h", "N_kt", "range", "Lu", "diff",
                                                 "wall", "to"))
for run in runs:
    ir, nx = (int(v) for v in run.split(":"))
    name = "ir%d_%d" % (ir, nx)
    steps = [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
    wall = float(open(name + ".wall").read())
    stopped = os.path.exists(name + ".stopped")
    d = [float(r["load_factor"]) * push for r in steps]
    n = [float(r["rigid_1_force_y"]) / (math.pi * R * R * su) for r in steps]
    settled = [v for x, v in zip(d, n) if x >= R - 1e-9]
    mean = sum(settled) / len(settled) if settled else float("nan")
    lu = 3.4 + 1.6 * math.log(ir)
    h = "R/%d" % round(nx / 20)
    print("%-5d %-6s %-7.2f %-12s %-6.2f %-8s %-9s %s" % (
        ir, h, mean, "%.2f-%.2f" % (min(settled), max(settled)) if settled else "-", lu,
        "%+.1f %%" % (100 * (mean / lu - 1)), "%.0f s" % wall,
        "%.2f R (stopped)" % (d[-1] / R) if stopped
        else "%.2f R" % (d[-1] / R)))
    for x, v in zip(d, n):
        rows.append((ir, h, x / R, v))
    label = "I_r = %d, h = %s: mean %.2f%s" % (ir, h, mean, ", stopped" if stopped else "")
    line, = axes.plot([x / R for x in d], n, label=label, lw=1.5 if nx == 80 else 1.0,
                      ls="-" if nx == 80 else "--")
    if ir not in drawn:
        axes.axhline(lu, color=line.get_color(), lw=0.8, ls=":")
        drawn.add(ir)
axes.set_xlabel("push beyond the start / R")
axes.set_ylabel("N_kt = F / (pi R^2 s_u)")
axes.set_title("Smooth cone pre-embedded 10 R deep; dotted: Lu et al. (2004)", fontsize=10)
axes.legend(fontsize=8, loc="lower right")
axes.set_ylim(0, None)
figure.tight_layout()
figure.savefig(target + "/cone_factor.png", dpi=110)
with open(target + "/cone_factor.csv", "w") as f:
    f.write("rigidity_index,cell_size,push_over_R,N_kt\n")
    for r in rows:
        f.write("%d,%s,%.6g,%.6g\n" % r)
PY
