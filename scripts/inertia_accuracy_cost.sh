#!/usr/bin/env bash
# Inertia: what accuracy costs in time (doc/benchmarks/inertia.md).
# Usage: scripts/inertia_accuracy_cost.sh [IMPM] [REPEATS]
#  1. The vibrating bar (tests/vibrating_bar.prm, v0 = 0.01 m/s, two
#     periods): the implicit trapezoidal rule at 25, 50, 100 and 200 steps a
#     period and the explicit central difference rule (MUSL) at Courant
#     numbers 0.5 and 0.25 (200 and 400 steps a period), the runs of each
#     repeat interleaved: the largest tip displacement error over the first
#     period (of the amplitude), the period's error, the total energy's
#     largest difference, and the wall time (the smallest of the repeats).
#  1b. The bar over ten periods: the trapezoidal rule's energy loss at 50,
#     100 and 200 steps a period, generalised-alpha's beyond it at spectral
#     radii 1, 0.8, 0.5 and 0 (100 steps a period), mass damping's decay.
#  2. The paper's collapse with inertia (tests/collapse_h1.prm, gravity at
#     once, mass damping 2 1/s, 8 s): generalised-alpha (160 steps) and
#     explicit MUSL (640 steps, the stable step at Courant number 0.5 is
#     0.0136 s): run-out, height and wall time.
#  3. The explicit loop's cost per point and step on the collapse at
#     h = 0.25 m (9,216 points, 200 steps of 3 ms) with its phases.
impm=${1:-build/impm}
repeats=${2:-3}
impm=$(cd "$(dirname "$impm")" && pwd)/$(basename "$impm")
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
bar=$here/tests/vibrating_bar.prm
collapse=$here/tests/collapse_h1.prm
source "$here/scripts/best_wall_time.sh"
bar_cases=("trapezoidal_25:--set|Solver/Load steps=50"
           "trapezoidal_50:--set|Solver/Load steps=100"
           "trapezoidal_100:--set|Solver/Load steps=200"
           "trapezoidal_200:--set|Solver/Load steps=400"
           "explicit_C0.5:--set|Time/Time step=0.05|--set|Inertia/Integrator=explicit MUSL"
           "explicit_C0.25:--set|Time/Time step=0.025|--set|Inertia/Integrator=explicit MUSL|--set|Inertia/Courant number=0.25")
for ((r = 0; r < repeats; ++r)); do
  for case in "${bar_cases[@]}"; do
    name=${case%%:*}
    IFS='|' read -r -a options <<< "${case#*:}"
    run "$name" "$bar" --set "Time/End time=20" --set "Inertia/Initial velocity=0.01*sin(pi*x/50); 0" "${options[@]}"
  done
  run collapse_implicit "$collapse" --set "Gravity/Ramped=false" --set "Time/End time=8" \
    --set "Time/Time step=0.05" --set "Inertia/Enabled=true" --set "Inertia/Integrator=generalised-alpha" \
    --set "Inertia/Mass damping=2"
  run collapse_explicit "$collapse" --set "Gravity/Ramped=false" --set "Time/End time=8" \
    --set "Time/Time step=0.0125" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" \
    --set "Inertia/Mass damping=2"
done
echo "1. vibrating bar, v0 = 0.01 m/s, two periods"
printf "%-18s %10s %12s %12s %12s %9s %5s\n" case steps/period "u error" "period err" "energy diff" "wall s" cuts
for case in "${bar_cases[@]}"; do
  name=${case%%:*}
  /usr/bin/python3 - "$name" "${best[$name]}" <<'PY'
import csv, math, sys
name, wall = sys.argv[1], float(sys.argv[2])
rows = list(csv.DictReader(open(name + "/point_history.csv")))
attempts = list(csv.DictReader(open(name + "/steps.csv")))
steps = [r for r in attempts if r["converged"] == "1"]
omega = math.pi * 10 / 50
amp = 0.01 / omega * math.sin(math.pi * float(rows[0]["x"]) / 50)
t = [float(r["time"]) for r in rows]; u = [float(r["displacement_x"]) for r in rows]
err = max(abs(ui - amp * math.sin(omega * ti)) for ti, ui in zip(t, u) if ti <= 10 + 1e-9) / amp
c = [t[k-1] + (t[k]-t[k-1]) * u[k-1] / (u[k-1] - u[k]) for k in range(1, len(u)) if u[k-1] > 0 >= u[k]]
period = (c[-1] - c[0]) / (len(c) - 1)
e0 = 0.5 * 0.01 ** 2 * 25 / 2
de = max(abs(float(r["total_energy"]) - e0) for r in steps) / e0
print("%-18s %10d %12.2e %12.2e %12.2e %9.3f %5d" % (name, round(len(steps) / 2), err, period / 10 - 1, de, wall, len(attempts) - len(steps)))
PY
done
echo
echo "1b. vibrating bar, v0 = 0.01 m/s, ten periods: the total energy's loss a period"
echo "    (the slope over the second half) and its loss at the end"
ten=(--set "Time/End time=100" --set "Inertia/Initial velocity=0.01*sin(pi*x/50); 0")
run ten_trapezoidal_50 "$bar" "${ten[@]}" --set "Solver/Load steps=500"
run ten_trapezoidal_100 "$bar" "${ten[@]}" --set "Solver/Load steps=1000"
run ten_trapezoidal_200 "$bar" "${ten[@]}" --set "Solver/Load steps=2000"
for rho in 1 0.8 0.5 0; do
  run "ten_alpha_$rho" "$bar" "${ten[@]}" --set "Solver/Load steps=1000" \
    --set "Inertia/Integrator=generalised-alpha" --set "Inertia/Spectral radius=$rho"
done
run ten_damped "$bar" "${ten[@]}" --set "Solver/Load steps=1000" --set "Inertia/Mass damping=0.01"
/usr/bin/python3 - <<'PY'
import csv, math
def series(name):
    rows = [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
    return [float(r["time"]) for r in rows], [float(r["total_energy"]) for r in rows], [float(r["kinetic_energy"]) for r in rows]
e0 = 0.5 * 0.01 ** 2 * 25 / 2
def slope(name):
    t, e, _ = series(name)
    h = len(t) // 2
    return (e[h] - e[-1]) / e0 / ((t[-1] - t[h]) / 10)
for n in (50, 100, 200):
    t, e, _ = series("ten_trapezoidal_%d" % n)
    print("trapezoidal, %3d steps a period: %.2e a period, %.2e at 100 s" % (n, slope("ten_trapezoidal_%d" % n), 1 - e[-1] / e0))
base = slope("ten_trapezoidal_100")
for rho in ("1", "0.8", "0.5", "0"):
    print("generalised-alpha, spectral radius %-3s: %.2e a period beyond the trapezoidal rule's" % (rho, slope("ten_alpha_" + rho) - base))
t, _, k = series("ten_damped")
peaks = [(t[i], k[i]) for i in range(1, len(k) - 1) if k[i] >= k[i - 1] and k[i] > k[i + 1]]
tp, kp = peaks[-1]
print("mass damping 0.01 1/s: kinetic energy at its last peak (t = %.1f s) %.3f of the initial, exp(-0.01 t) = %.3f"
      % (tp, kp / e0, math.exp(-0.01 * tp)))
PY
echo
echo "2. collapse with inertia (8 s, mass damping 2 1/s)"
for name in collapse_implicit collapse_explicit; do
  steps=$(($(wc -l < "$name/steps.csv") - 1))
  printf "%-18s %5d steps  run-out %s m  height %s m  wall %.3f s\n" "$name" "$steps" \
    "$(grep -o "extent in x: .*final \[[^,]*, [^]]*" "$name.log" | sed 's/.*, //')" \
    "$(grep -o "extent in y: .*final \[[^,]*, [^]]*" "$name.log" | sed 's/.*, //')" "${best[$name]}"
done
echo
echo "3. explicit loop cost, collapse at h = 0.25 m (9,216 points, 200 steps)"
run big "$collapse" --set "Grid/Number of cells=64, 32" --set "Gravity/Ramped=false" \
  --set "Time/End time=0.6" --set "Time/Time step=0.003" --set "Inertia/Enabled=true" \
  --set "Inertia/Integrator=explicit MUSL" --set "Testing/Enabled=false"
total=$(grep "Total wallclock" big.log | awk -F'|' '{print $3}' | tr -d ' s')
echo "total $total s: $(echo "scale=3; $total * 1000000 / 9216 / 200" | bc) us per point and step"
grep -E "^\| (assembly|basis evaluation|point update|stress update|system setup) " big.log
