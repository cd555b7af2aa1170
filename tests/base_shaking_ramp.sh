#!/usr/bin/env bash
# A base's shaking at the right time in each step (issue 33): the block of
# tests/base_shaking_ramp.prm, shaken with a_g = t, slides in the base's
# frame by exactly -t^3/6. At t = 1 s, with 10, 20 and 40 steps:
#  * generalised-alpha (spectral radius 0.8): second order, the error
#    falling by at least 3.5 per halving and below 1e-3 of the exact
#    displacement at 40 steps (measured -9.2e-4, -2.3e-4, -5.8e-5 m); when
#    its start residual took the load of the step's end it was first order
#    (-2.3e-2, -1.1e-2, -5.6e-3 m);
#  * Newmark's trapezoidal rule: the same (-8.3e-4, -2.1e-4, -5.2e-5 m);
#  * explicit MUSL at 0.005 and 0.0025 s: within 1e-4 of it (4.2e-6 and
#    1.0e-6 m; -2.5e-3 and -1.3e-3 m with the end's load).
# Usage: base_shaking_ramp.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
cp "$(dirname "$scene")/base_shaking_ramp.txt" .
error() { # error NAME [--set ...]: the displacement at 1 s less -1/6, m
  local name=$1
  shift
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" "$@" > log.txt 2>&1 ||
    fail "the run $name failed"
  /usr/bin/python3 -c "
import csv
row = list(csv.DictReader(open('$name/point_history.csv')))[-1]
assert abs(float(row['time']) - 1) < 1e-9
print('%.6e' % (float(row['displacement_x']) + 1 / 6))"
}
for integrator in generalised-alpha Newmark; do
  errors=()
  for n in 10 20 40; do
    errors+=("$(error "${integrator}_$n" --set "Inertia/Integrator=$integrator" \
      --set "Solver/Load steps=$n")")
  done
  /usr/bin/python3 - "$integrator" "${errors[@]}" <<'PY' || fail "$1 is not second order in a base's shaking"
import sys
name, e = sys.argv[1], [abs(float(x)) for x in sys.argv[2:]]
ok = e[0] / e[1] > 3.5 and e[1] / e[2] > 3.5 and e[2] < 1e-3 / 6
print("%s: errors %.2e, %.2e, %.2e m at 10, 20, 40 steps, falling by %.2f and %.2f: second order: %s"
      % (name, e[0], e[1], e[2], e[0] / e[1], e[1] / e[2], "yes" if ok else "NO"))
sys.exit(0 if ok else 1)
PY
done
for dt in 0.005 0.0025; do
  e=$(error "explicit_$dt" --set "Inertia/Integrator=explicit MUSL" --set "Time/Time step=$dt")
  /usr/bin/python3 -c "
import sys
e = abs(float('$e'))
print('explicit MUSL at $dt s: error %.2e m, below 1e-4 of 1/6 m: %s' % (e, 'yes' if e < 1e-4 / 6 else 'NO'))
sys.exit(0 if e < 1e-4 / 6 else 1)" || fail "the explicit step's base load is not that of its start"
done
echo "base_shaking_ramp: passed"
