#!/usr/bin/env bash
# The vibrating bar (issue 33, tests/vibrating_bar.prm) against its
# analytical solution (tests/vibrating_bar_check.py), on MPIEXEC N
# processes if given. Over two periods (20 s) at 100 steps a period:
#  1. trapezoidal rule, GIMP, v0 = 0.01 m/s (strains of 0.1 %, where the
#     linear solution holds): the tip's displacement within 1 % of its
#     amplitude at every step of the first period, the period within 0.5 %
#     of 4L/c (it is 0.11 % long), the total energy within 2e-3 at every
#     step (the mapping between points and nodes loses 2.2e-4 a period);
#  2. v0 = 0.1 m/s (the benchmark's amplitude, strains of 1 %): the period
#     and the energy as above; the displacement within 2.5 % only, because
#     at 1 % strain the finite-strain bar is stiffer in compression than
#     in tension (its half periods differ by about 0.5 %: the difference
#     from the linear solution at the zero crossings, 2.2 % here, falls to
#     0.6 % at v0 = 0.01, the part left by the discretisation);
#  3. the same with standard MPM (1.2 %);
#  4. generalised-alpha with spectral radius 1 (no algorithmic damping),
#     v0 = 0.01: as case 1;
#  5. explicit central differences at Courant number 0.5 (0.05 s, 400
#     steps), MUSL at v0 = 0.1 and USL at v0 = 0.01, as cases 2 and 1
#     (displacement 2.1 % and 0.4 %, period 0.05 % long); the energy within
#     2.5e-2 only: the kinetic energy of the end-of-step velocity and the
#     strain energy of the end-of-step displacement are half a step apart
#     in the central difference rule, so their sum oscillates by up to
#     1.9e-2 at this step (at the end of two periods it is 1.6e-3 to
#     6.5e-3 off);
#  6. a time step of 5 s, half the period (4 steps): the trapezoidal rule
#     is unconditionally stable: every step converges, the energy never
#     grows (1e-3) and loses less than 1 % (0.68 %: the mapping's loss
#     grows with the step; the period is not resolved, no displacement
#     check);
#  7. generalised-alpha's energy decay against the theory of its
#     amplification matrix (tests/generalised_alpha_decay.py): 10 periods
#     with the trapezoidal rule and with spectral radii 0.5 and 0;
#  8. the consistent mass (Inertia/Mass = consistent), v0 = 0.01: as case
#     1 over two periods, and over ten periods the total energy within
#     3e-4 of the initial at every step (measured 1.1e-4; the lumped mass
#     loses 2.3e-3 in ten periods and fails this). Its relative residual
#     stalls near 2e-9 where the bar's velocity peaks (internal and
#     inertial forces both near zero, the mass terms cancelling), so its
#     runs ask for 1e-8;
#  9. the issue's energy claim at its amplitude: the consistent mass at
#     v0 = 0.1 m/s, 400 steps a period, over 100 periods (1,000 s, 40,000
#     steps, about 30 s; one process only): the total energy within 1e-3
#     of the initial at every step (measured 7.7e-4, lost linearly in time;
#     1.3e-3 at 200 steps a period and 2.3e-3 at 100 fail it: the 1 %
#     strain makes the bar nonlinear, where the trapezoidal rule's energy
#     error falls with the step; doc/benchmarks/inertia.md).
# Usage: vibrating_bar.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
run() { # run NAME V0 [--set ...]: the bar in directory NAME
  local name=$1 v0=$2
  shift 2
  rm -rf "$name"
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" \
    --set "Inertia/Initial velocity=$v0*sin(pi*x/50); 0" "$@" > log.txt 2>&1 ||
    fail "the run $name failed"
}
two_periods=(--set "Time/End time=20" --set "Solver/Load steps=200")
for case in "trapezoidal 0.01 0.01" "trapezoidal 0.1 0.025" "standard_mpm 0.1 0.025" \
            "generalised_alpha 0.01 0.01" "explicit_MUSL 0.1 0.025" "explicit_USL 0.01 0.01" \
            "consistent 0.01 0.01"; do
  set -- $case
  options=("${two_periods[@]}")
  energy=2e-3
  [ "$1" = standard_mpm ] && options+=(--set "Material points/Basis=standard MPM")
  [ "$1" = consistent ] && options+=(--set "Inertia/Mass=consistent" --set "Solver/Tolerance=1e-8")
  [ "$1" = generalised_alpha ] &&
    options+=(--set "Inertia/Integrator=generalised-alpha" --set "Inertia/Spectral radius=1")
  if [ "${1%_*}" = explicit ]; then
    options+=(--set "Inertia/Integrator=explicit ${1#*_}" --set "Time/Time step=0.05")
    energy=2.5e-2
  fi
  run "$1_$2" "$2" "${options[@]}"
  echo "$1, v0 = $2 m/s:"
  /usr/bin/python3 "$here/vibrating_bar_check.py" "$1_$2" 20 "$2" "$3" "$energy" ||
    fail "the bar ($1, v0 = $2 m/s) differs from the analytical solution"
done
run large_step 0.01 --set "Time/End time=20" --set "Solver/Load steps=4"
/usr/bin/python3 - large_step <<'PY' || fail "the bar with a time step of half a period"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/steps.csv")))
exact = 0.5 * 0.01 ** 2 * 25 / 2
energies = [float(r["total_energy"]) / exact for r in rows]
ok = (all(r["converged"] == "1" for r in rows) and len(rows) == 4 and
      max(energies) < 1 + 1e-3 and min(energies) > 0.99)
print("time step of half a period: 4 steps, all converged, the energy never above"
      " 1 + 1e-3 of the initial, lost below 1 %%: %s (from %.4f to %.4f)"
      % ("yes" if ok else "NO", min(energies), max(energies)))
sys.exit(0 if ok else 1)
PY
ten_periods=(--set "Time/End time=100" --set "Solver/Load steps=1000")
run decay_trapezoidal 0.01 "${ten_periods[@]}"
for rho in 0.5 0; do
  run "decay_$rho" 0.01 "${ten_periods[@]}" --set "Inertia/Integrator=generalised-alpha" \
    --set "Inertia/Spectral radius=$rho"
done
/usr/bin/python3 "$here/generalised_alpha_decay.py" 100 decay_trapezoidal decay_0.5 decay_0 ||
  fail "generalised-alpha's energy decay differs from its theory"
run consistent_ten 0.01 "${ten_periods[@]}" --set "Inertia/Mass=consistent" \
  --set "Solver/Tolerance=1e-8"
/usr/bin/python3 - consistent_ten <<'PY' || fail "the consistent mass's energy over ten periods"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + "/steps.csv")) if r["converged"] == "1"]
exact = 0.5 * 0.01 ** 2 * 25 / 2
deviation = max(abs(float(r["total_energy"]) / exact - 1) for r in rows)
ok = float(rows[-1]["time"]) > 100 - 1e-9 and deviation < 3e-4
print("consistent mass, ten periods: the total energy within 3e-4 at every step: %s"
      % ("yes" if ok else "NO (%.2e)" % deviation))
sys.exit(0 if ok else 1)
PY
if [ ${#launcher[@]} = 0 ]; then
  run consistent_hundred 0.1 --set "Time/End time=1000" --set "Solver/Load steps=40000" \
    --set "Inertia/Mass=consistent" --set "Solver/Tolerance=1e-9" --set "Output/Interval=0"
  /usr/bin/python3 - consistent_hundred <<'PY' || fail "the consistent mass's energy over 100 periods"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + "/steps.csv")) if r["converged"] == "1"]
exact = 0.5 * 0.1 ** 2 * 25 / 2
deviation = max(abs(float(r["total_energy"]) / exact - 1) for r in rows)
ok = float(rows[-1]["time"]) > 1000 - 1e-9 and len(rows) == 40000 and deviation < 1e-3
print("consistent mass, v0 = 0.1 m/s, 400 steps a period, 100 periods: the total energy"
      " within 1e-3 at every step: %s" % ("yes" if ok else "NO (%.2e)" % deviation))
sys.exit(0 if ok else 1)
PY
fi
echo "vibrating_bar: passed"
