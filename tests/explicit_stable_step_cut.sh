#!/usr/bin/env bash
# The explicit step against the stable step as the points' state changes.
#
# 1. A stretched point keeps its speed of sound. The bar of
#    tests/vibrating_bar.prm (E = 100 Pa, rho0 = 1, h = 1 m) on a 40 m grid,
#    stretched from x = 0 by the initial velocity 0.3 x, explicit MUSL at
#    0.09 s (Courant number 0.9 of the stable step 0.1 s) for 3 s. A point's
#    mass and its Hencky (Kirchhoff) stiffness both go with its initial
#    volume, so its speed of sound is sqrt(E / rho0) at any J: no step is
#    refused, although J passes 1.235, where the current density's
#    sqrt(E J / rho0) (the rule before 2026-11-29) put the stable step below
#    0.09 s and cut the run's steps.
# 2. A stiffening point lowers it. The Modified Cam-clay column of
#    tests/cam_clay_column.prm with p_ref = 100 Pa and G = 200 kPa (P-wave
#    modulus 0.272 MPa at p_ref: the scene's check allows 0.08 s at Courant
#    number 0.99), starting geostatic at p' up to about 100 kPa, where its
#    bulk modulus p'/kappa* is 5 MPa: the stable step there is 0.018 s.
#    Before 2026-11-29 every step used the reference pressure's modulus, the
#    run took 0.07 s and blew up (a point thrown off the grid at t = 0.53 s).
#    Now each step's limit comes from each point's stress, the first step is
#    cut to it and the run follows it to 3 s; its strain energy equals that
#    of a run at 0.005 s within 0.5 %.
# tests/check_explicit_stable_step_cut.py checks both from the point files
# alone: every step taken within h / sqrt(M / rho0) of its start state
# (Courant number 1, where a step is refused), every refusal above it and
# the attempt after it the Courant number C times it, the end time reached;
# the bar's stress against E ln(J) / J.
# Usage: explicit_stable_step_cut.sh IMPM SCENE [MPIEXEC N]
scene=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$scene" --set "Output directory=bar" \
  --set "Grid/Upper corner=40, 1" --set "Grid/Number of cells=40, 1" \
  --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Courant number=0.9" \
  --set "Time/End time=3" --set "Time/Time step=0.09" \
  --set "Solver/Minimum load step=0.05" --set "Inertia/Initial velocity=0.3*x; 0" \
  --set "Output/Interval=1" > log.txt 2>&1 || fail "the stretched bar stopped"
mv log.txt bar.txt
clay=(--set "Testing/Enabled=false" --set "Inertia/Enabled=true"
  --set "Body 1/Material/Modified Cam-clay/Reference pressure=100"
  --set "Body 1/Material/Modified Cam-clay/Shear modulus=2e5"
  --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Courant number=0.99"
  --set "Time/End time=3")
"${launcher[@]}" "$impm" "$here/cam_clay_column.prm" "${clay[@]}" \
  --set "Time/Time step=0.07" --set "Output directory=clay" \
  --set "Output/Interval=1" > log.txt 2>&1 || fail "the Cam-clay column stopped"
mv log.txt clay.txt
"${launcher[@]}" "$impm" "$here/cam_clay_column.prm" "${clay[@]}" \
  --set "Time/Time step=0.005" --set "Output directory=clay_fine" \
  > log.txt 2>&1 || fail "the Cam-clay column at 0.005 s stopped"
/usr/bin/python3 "$here/check_explicit_stable_step_cut.py" bar bar.txt clay clay.txt \
  clay_fine/steps.csv || fail "the explicit steps and the stable step disagree"
echo "explicit_stable_step_cut: passed"
