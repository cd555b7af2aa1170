#!/usr/bin/env bash
# 'Inertia/FLIP reference step': the PIC share of the points' velocity
# update damps the same per second at any time step. The vibrating bar of
# tests/vibrating_bar.prm started in its third mode (v0 = 0.1 m/s, energy
# 0.0625 J), FLIP fraction 0.5 given for 0.05 s steps, 10 s:
#  1. explicit MUSL at 0.01 s and 0.005 s: the energy left (2.65e-2 and
#     2.58e-2 J measured, 58-59 % lost) within 4 % of each other;
#  2. implicit (trapezoidal) at 0.025 s and 0.0125 s, extrapolated in the
#     step to first order (2 E(dt/2) - E(dt); the implicit energy falls
#     with the step as dt, measured 0.0320, 0.0287, 0.0269 J at 0.05,
#     0.025, 0.0125 s), against the explicit runs extrapolated alike: within
#     2 % (0.02512 and 0.02501 J measured): the two integrators damp the
#     same;
#  3. at 0.01 s the referenced run equals one with the fraction per step
#     0.5^(0.01/0.05) given directly (steps.csv to numdiff's tolerance);
#  4. without the reference the fraction 0.5 in every step: the explicit
#     runs at 0.01 s and 0.005 s keep 2.3e-3 and 9.1e-5 J, more than 10
#     times apart (what the reference mends);
#  5. the start-up report names the fraction "per 0.05 s".
# Usage: flip_reference_step.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() { # run NAME [--set ...]: the bar in directory NAME, 10 s
  local name=$1
  shift
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" \
    --set "Inertia/Initial velocity=0.1*sin(3*pi*x/50); 0" \
    --set "Inertia/FLIP fraction=0.5" "$@" > log.txt 2>&1 || fail "the run $name failed"
}
explicit=(--set "Inertia/Integrator=explicit MUSL")
reference=(--set "Inertia/FLIP reference step=0.05")
run explicit_10 "${explicit[@]}" "${reference[@]}" --set "Time/Time step=0.01"
grep -q "FLIP fraction 0.5 per 0.05 s" log.txt || fail "the start-up report does not name the reference step"
run explicit_5 "${explicit[@]}" "${reference[@]}" --set "Time/Time step=0.005"
run implicit_25 "${reference[@]}" --set "Solver/Load steps=400"
run implicit_12 "${reference[@]}" --set "Solver/Load steps=800"
run explicit_10_direct "${explicit[@]}" --set "Time/Time step=0.01" \
  --set "Inertia/FLIP fraction=0.8705505632961241"
run explicit_10_per_step "${explicit[@]}" --set "Time/Time step=0.01"
run explicit_5_per_step "${explicit[@]}" --set "Time/Time step=0.005"
untimed explicit_10/steps.csv > referenced.csv
untimed explicit_10_direct/steps.csv > direct.csv
compare referenced.csv direct.csv \
  "the referenced fraction is not 0.5^(dt/0.05)"
/usr/bin/python3 - <<'PY' || fail "the PIC share's damping depends on the time step"
import csv
def energy(name):
    rows = list(csv.DictReader(open(name + "/steps.csv")))
    assert abs(float(rows[-1]["time"]) - 10.) < 1e-9, name
    return float(rows[-1]["total_energy"])
e10, e5 = energy("explicit_10"), energy("explicit_5")
i25, i12 = energy("implicit_25"), energy("implicit_12")
p10, p5 = energy("explicit_10_per_step"), energy("explicit_5_per_step")
initial = 0.5 * 25 * 0.1 ** 2 * 0.5
explicit_limit, implicit_limit = 2 * e5 - e10, 2 * i12 - i25
print(f"explicit, 0.01 s and 0.005 s: {e10:.4e} and {e5:.4e} J left of {initial:.4e} "
      f"(differ by {abs(e10 / e5 - 1):.2%})")
print(f"extrapolated in the step: explicit {explicit_limit:.4e} J, implicit {implicit_limit:.4e} J "
      f"(differ by {abs(implicit_limit / explicit_limit - 1):.2%})")
print(f"without the reference: {p10:.3e} and {p5:.3e} J ({p10 / p5:.0f} times)")
assert e5 < 0.67 * initial, "less than a third of the energy lost: the test would not see the damping"
assert abs(e10 / e5 - 1) < 0.04
assert abs(implicit_limit / explicit_limit - 1) < 0.02
assert p10 / p5 > 10
PY
echo "flip_reference_step: passed"
