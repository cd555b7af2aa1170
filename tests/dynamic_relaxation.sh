#!/usr/bin/env bash
# Dynamic relaxation with local non-viscous damping (Inertia/Local damping,
# explicit only): the elastic column of column_gimp_elastic_8.prm (finite
# strain, rho g H / E = 4 %) under its full weight from the first step,
# explicit MUSL at 0.02 s (Courant number 0.36) for 30 s, about 17 of its
# periods (4H/c = 1.79 s). With a local damping of 0.8 it comes to rest in
# the static state: the printed points' displacement and vertical stress
# within 2e-4 of the quasi-static run's (measured 1e-4), its kinetic energy
# at the end below 1e-6 of its strain energy. Without damping it is still
# vibrating at the end (its kinetic energy 40 % of the strain energy,
# measured), which the same checks refuse.
# Usage: dynamic_relaxation.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
dynamic=(--set "Gravity/Ramped=false" --set "Time/End time=30" --set "Time/Time step=0.02"
         --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL")
"${launcher[@]}" "$impm" "$scene" --set "Output directory=static" > static.txt 2>&1 ||
  fail "the quasi-static run failed"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=damped" "${dynamic[@]}" \
  --set "Inertia/Local damping=0.8" > damped.txt 2>&1 || fail "the damped run failed"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=free" "${dynamic[@]}" \
  > free.txt 2>&1 || fail "the undamped run failed"
/usr/bin/python3 - static.txt damped.txt free.txt <<'PY' || fail "dynamic relaxation"
import re, sys
def state(name):
    text = open(name).read()
    points = [tuple(float(v) for v in m) for m in
              re.findall(r"^point \d+: X = \S+ \S+, u = (\S+) (\S+), sigma_vertical = ([^,]+),", text, re.M)]
    energies = re.findall(r"^step +\d+ .* Ek (\S+)  Es (\S+)", text, re.M)
    return points, energies[-1] if energies else None
static, _ = state(sys.argv[1])
ok = True
for name, expect in ((sys.argv[2], True), (sys.argv[3], False)):
    points, (kinetic, strain) = state(name)
    difference = max(abs(a - b) / max(abs(b), 1e-12)
                     for p, q in zip(points, static) for a, b in zip(p[1:], q[1:]))
    at_rest = difference < 2e-4 and float(kinetic) < 1e-6 * float(strain)
    print("%s: at rest in the static state: %s" % (name.split(".")[0], "yes" if at_rest else "no"))
    ok = ok and at_rest == expect
sys.exit(0 if ok else 1)
PY
echo "dynamic_relaxation: passed"
