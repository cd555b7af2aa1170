#!/usr/bin/env bash
# A pressure pulse in a long elastic column (tests/pressure_pulse.prm), on
# MPIEXEC N processes if given, run 9 s (the pulse reaches the base at 5-6
# s) with
#  1. the absorbing base: the energy left in the column at 9 s against
#     that of run 2 at 9 s (the reflected fraction; both lose the same to
#     the discretisation on the way) below 5 % (it is 0.6 %), and the
#     energy the dashpots took within 5 % of what reached the base;
#  2. a fixed base (the body from y = 0 on a roller face, no dashpots):
#     all of the wave reflected: the energy kept over the 4 s across the
#     reflection (5 to 9 s: 96.1 %) at least what is kept over the 4 s
#     before it (1 to 5 s: 92.8 %; the grid's dispersion and the mapping
#     between points and nodes lose energy on the way, most of it from
#     the pulse's shortest waves, early);
# and the energy the pulse brings in within 6 % of p0^2 T 3 / (8 rho c) =
# 3.75e-4 J/m (it is 4.4 % above: the lumped-mass grid's impedance at 10
# cells a wavelength is lower than rho c).
# Usage: pressure_pulse.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=absorbing" > log.txt 2>&1 ||
  fail "the column with an absorbing base failed"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=fixed" \
  --set "Absorbing boundary/Enabled=false" --set "Grid/Condition y-=roller" \
  --set "Body 1/Lower corner=0, 0" --set "Body 1/Upper corner=1, 50" > log.txt 2>&1 ||
  fail "the column with a fixed base failed"
/usr/bin/python3 - <<'PY' || fail "the pressure pulse"
import csv
def rows(name):
    return [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
def energy_at(rs, t):
    return min(rs, key=lambda r: abs(float(r["time"]) - t))
absorbing, fixed = rows("absorbing"), rows("fixed")
incident = max(float(r["total_energy"]) for r in absorbing if float(r["time"]) <= 1.5)
theory = 0.1 ** 2 / 10 * 3 / 8
at_base = float(energy_at(absorbing, 5.0)["total_energy"])
left = float(absorbing[-1]["total_energy"])
reflected = left / float(fixed[-1]["total_energy"])
absorbed = float(absorbing[-1]["absorbed_energy"])
kept = float(fixed[-1]["total_energy"]) / float(energy_at(fixed, 5.0)["total_energy"])
travel = float(energy_at(fixed, 5.0)["total_energy"]) / float(energy_at(fixed, 1.0)["total_energy"])
checks = [
    ("energy brought in within 6 %% of p0^2 T 3/(8 rho c) = %.4e J/m" % theory,
     abs(incident / theory - 1) < 0.06, "%.4e, %+.1f %%" % (incident, 100 * (incident / theory - 1))),
    ("reflected by the absorbing base below 5 %", reflected < 0.05, "%.2f %%" % (100 * reflected)),
    ("taken by the dashpots within 5 % of what reached the base", abs(absorbed / at_base - 1) < 0.05,
     "%.4e against %.4e" % (absorbed, at_base)),
    ("kept over the 4 s across the fixed base's reflection at least as much as over the 4 s before it",
     kept >= travel, "%.2f %% against %.2f %%" % (100 * kept, 100 * travel)),
    ("every step converged, 450 of each", len(absorbing) == 450 and len(fixed) == 450, "%d, %d" % (len(absorbing), len(fixed))),
]
for text, ok, figure in checks:
    print("%s: %s (%s)" % (text, "yes" if ok else "NO", figure))
raise SystemExit(0 if all(ok for _, ok, _ in checks) else 1)
PY
echo "pressure_pulse: passed"
