#!/usr/bin/env bash
# An elastic layer on a shaken base (tests/shaken_layer.prm), on MPIEXEC N
# processes if given: the base's acceleration a half-sine pulse of 0.1
# m/s^2 for 1 s in x, then 60 s of free vibration in 1200 steps. The
# period of the surface's displacement (relative to the base) from its
# downward zero crossings after the first is the layer's fundamental
# period: the frequency within 2 % of Vs / 4H = 0.17678 Hz (it is 0.04 %
# low). Every step converges.
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
echo "shaken_layer: passed"
