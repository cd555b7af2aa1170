#!/usr/bin/env bash
# An explicit run whose stable step falls below its time step mid-run, in
# more steps than 1/'Solver/Minimum load step': the step is cut and the run
# goes on. The bar of tests/vibrating_bar.prm (E = 100 Pa, rho0 = 1, h = 1 m)
# on a 40 m grid, stretched from x = 0 by the initial velocity 0.3 x, explicit
# MUSL at 0.09 s (Courant number 0.9 of the start's stable step 0.1 s) for
# 3 s (34 nominal steps), 'Minimum load step' 0.05 (above the nominal 1/34,
# as the default 1e-4 is in an explicit run of more than 10,000 steps).
# As points stretch their density falls and the stable step h / sqrt(E J /
# rho0) with it; from J = 1.235 it is below 0.09 s. Before the step control
# took 1/1024 of the nominal step as its floor where 'Minimum load step' is
# not below the nominal one, the first such refusal stopped the run ("would
# fall below 'Solver/Minimum load step' times 'Time/End time'"; the granular
# column at a = 7, explicit, at t = 1.2 s).
# tests/check_explicit_stable_step_cut.py checks from the point files alone
# that every step taken was within the stable step of its start and every
# refused one above it, that the run reached 3 s, and the stretched points'
# stress against E ln(J) / J. After a refusal the step goes to the Courant
# number's share of its start's stable step and grows no further than that:
# 39 steps with 2 refusals (with halving and doubling alone, 57 steps and
# 45 refusals, every other attempt).
# Usage: explicit_stable_step_cut.sh IMPM SCENE [MPIEXEC N]
scene=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=out" \
  --set "Grid/Upper corner=40, 1" --set "Grid/Number of cells=40, 1" \
  --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Courant number=0.9" \
  --set "Time/End time=3" --set "Time/Time step=0.09" \
  --set "Solver/Minimum load step=0.05" --set "Inertia/Initial velocity=0.3*x; 0" \
  --set "Output/Interval=1" > log.txt 2>&1 || fail "the stretched bar stopped"
/usr/bin/python3 "$here/check_explicit_stable_step_cut.py" out log.txt ||
  fail "the explicit steps and the stable step disagree"
echo "explicit_stable_step_cut: passed"
