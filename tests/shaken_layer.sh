#!/usr/bin/env bash
# An elastic layer on a shaken base (tests/shaken_layer.prm), on MPIEXEC N
# processes if given: the base's acceleration a half-sine pulse of 0.1
# m/s^2 for 1 s in x, then 60 s of free vibration in 1200 steps. The
# period of the surface's displacement (relative to the base) from its
# downward zero crossings after the first is the layer's fundamental
# period: the frequency within 2 % of Vs / 4H = 0.17678 Hz (it is 0.04 %
# low). Every step converges.
# Then two cycles of a 1 Hz sine of 0.1 m/s^2, which excite the third and
# fourth modes (0.88 and 1.24 Hz), 6 s with the trapezoidal rule at 0.01 s:
# against the exact relative displacement at y = 9.875 m (modal
# superposition of 60 modes, computed here), the largest difference over
# the 6 s is within 6 % of the largest displacement with the consistent
# mass (4.3 %; 20 linear elements with consistent mass, solved exactly in
# time, 3.5 %) and above 10 % with the lumped mass (16.4 %: the lumped
# mapping of the points' velocities to the nodes, not the time step,
# which does not change it; doc/benchmarks/inertia.md).
# Usage: shaken_layer.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
/usr/bin/python3 -c "
import math
with open('pulse.txt', 'w') as f:
    f.write('# time (s), acceleration x and y (m/s^2): a half-sine pulse of 1 s\n')
    for k in range(21):
        t = 0.05 * k
        f.write('%g, %.12g, 0\n' % (t, 0.1 * math.sin(math.pi * t)))
"
"${launcher[@]}" "$impm" "$scene" > log.txt 2>&1 || fail "the shaken layer failed"
/usr/bin/python3 - <<'PY' || fail "the shaken layer's frequency"
import csv, math
steps = list(csv.DictReader(open("results/steps.csv")))
rows = list(csv.DictReader(open("results/point_history.csv")))
t = [float(r["time"]) for r in rows]
u = [float(r["displacement_x"]) for r in rows]
crossings = [t[k - 1] + (t[k] - t[k - 1]) * u[k - 1] / (u[k - 1] - u[k])
             for k in range(1, len(u)) if u[k - 1] > 0 >= u[k]]
period = (crossings[-1] - crossings[1]) / (len(crossings) - 2)
exact = math.sqrt(50.0) / (4 * 10.0)
error = 1 / period / exact - 1
ok_steps = len(steps) == 1200 and all(r["converged"] == "1" for r in steps)
ok = abs(error) < 0.02
print("1200 steps, all converged: %s" % ("yes" if ok_steps else "NO"))
print("surface frequency from %d periods within 2 %% of Vs/4H = %.5f Hz: %s (%.5f Hz, %+.2f %%)"
      % (len(crossings) - 2, exact, "yes" if ok else "NO", 1 / period, 100 * error))
raise SystemExit(0 if ok and ok_steps else 1)
PY
/usr/bin/python3 -c "
import math
with open('sine.txt', 'w') as f:
    for k in range(1201):
        t = 0.005 * k
        f.write('%g %.12g 0\n' % (t, 0.1 * math.sin(2 * math.pi * t) if t < 2 else 0.))
"
for mass in consistent lumped; do
  "${launcher[@]}" "$impm" "$scene" --set "Inertia/Integrator=Newmark" \
    --set "Inertia/Mass=$mass" --set "Time/End time=6" \
    --set "Time/Time step=0.01" --set "Base shaking/Acceleration file=sine.txt" \
    --set "Output directory=sine_$mass" > log.txt 2>&1 || fail "the 1 Hz shaking ($mass mass) failed"
done
/usr/bin/python3 - <<'PY' || fail "the 1 Hz shaking against the modal solution"
import csv
import numpy as np
# The layer's modes (fixed base, free top): q_n'' + omega_n^2 q_n = -gamma_n a(t)
# with a = 0.1 sin(2 pi t) until t = 2 s, then 0; each mode in closed form
# from rest (the forced response), then free from its state at 2 s.
modes = np.arange(1, 61)
omega = (2 * modes - 1) * np.pi * np.sqrt(50.0) / 20.0
gamma = 4 / ((2 * modes - 1) * np.pi)
times = np.round(np.arange(0, 6 + 1e-9, 0.01), 6)
forcing = 2 * np.pi
amplitude = -0.1 * gamma / (omega ** 2 - forcing ** 2)
def forced(t):
    wt = np.outer(omega, t)
    return (amplitude[:, None] * (np.sin(forcing * t) - (forcing / omega)[:, None] * np.sin(wt)),
            amplitude[:, None] * forcing * (np.cos(forcing * t) - np.cos(wt)))
q_forced, _ = forced(times)
q_2, v_2 = forced(np.array([2.0]))
free = np.outer(omega, times - 2)
q_free = q_2 * np.cos(free) + v_2 / omega[:, None] * np.sin(free)
q = np.where(times < 2, q_forced, q_free)
exact = np.sin((2 * modes - 1) * np.pi * 9.875 / 20.0) @ q
error = {}
for mass in ("consistent", "lumped"):
    rows = [r for r in csv.DictReader(open("sine_%s/point_history.csv" % mass)) if r["point"] == "1"]
    u = dict((round(float(r["time"]), 6), float(r["displacement_x"])) for r in rows)
    error[mass] = np.abs(np.array([u[t] for t in times]) - exact).max() / np.abs(exact).max()
ok = error["consistent"] < 0.06 and error["lumped"] > 0.10
print("1 Hz shaking, largest difference from the modal solution: consistent mass %.1f %% (< 6 %%), lumped %.1f %% (> 10 %%): %s"
      % (100 * error["consistent"], 100 * error["lumped"], "yes" if ok else "NO"))
raise SystemExit(0 if ok else 1)
PY
echo "shaken_layer: passed"
