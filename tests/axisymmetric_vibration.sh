#!/usr/bin/env bash
# Inertia in axisymmetry against analytical solutions
# (tests/axisymmetric_vibration_check.py), on MPIEXEC N processes if given:
# a solid cylinder vibrating along its axis in uniaxial strain
# (tests/axisymmetric_bar.prm: the masses' and energies' 2 pi r) and the
# first radial mode of a free solid cylinder (tests/axisymmetric_radial_mode.prm:
# the hoop stress and strain in the dynamics; in plane strain the same scene
# is 120 % of its amplitude off). Each case checks the displacement of two
# points over the first period, the period within 0.5 %, no motion in the
# other direction, the first step's energy against the exact one and the
# energy at every step:
#  1. the bar, the trapezoidal rule, GIMP, 200 steps a period:
#     displacement within 1 % (0.49 % measured), period 0.09 % long,
#     first-step energy within 1e-6 (1.1e-8), energy within 2e-3 (3.1e-4);
#  2. the bar, explicit MUSL, GIMP, 0.02 s (Courant number 0.46): 0.34 %,
#     0.05 %; the energy within 2.5e-2 (7.3e-3: the kinetic and strain
#     energies are half a step apart, as in tests/vibrating_bar.sh case 5;
#     the first step's kinetic energy is checked);
#  3. the bar, explicit USL, standard MPM: as case 2;
#  4. the radial mode, the trapezoidal rule, GIMP, 100 steps a period:
#     displacement within 1 % (0.49 % and 0.55 %), period 0.07-0.09 %
#     long, first-step energy within 1e-4 (1.5e-5: the points' quadrature
#     of J1^2 r), energy within 2e-3 (5.9e-4);
#  5. the radial mode, explicit MUSL, GIMP, 0.0025 s: 0.20 % and 0.15 %,
#     period within 0.02 %; energy within 5e-2 (3.2e-2, half a step apart);
#  6. the radial mode, explicit USL, standard MPM: as case 5 (0.13 %, 0.10 %);
#  7. the radial mode, explicit MUSL, GIMP, with APIC ('Inertia/Velocity
#     update'): as case 5 (0.12 % and 0.09 %, period within 0.015 %,
#     energy 3.2e-2).
# Usage: axisymmetric_vibration.sh IMPM TESTS_DIR [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() { # run NAME SCENE MODE DISPLACEMENT_LIMIT ENERGY_LIMIT FIRST_STEP_ENERGY FIRST_STEP_TOLERANCE [--set ...]
  local name=$1 scene=$2 mode=$3 limit=$4 energy=$5 first=$6 tolerance=$7
  shift 7
  "${launcher[@]}" "$impm" "$tests/$scene.prm" --set "Output directory=$name" "$@" \
    > log.txt 2>&1 || fail "the run $name failed"
  echo "case $name:"
  /usr/bin/python3 "$tests/axisymmetric_vibration_check.py" "$name" "$mode" "$limit" \
    "$energy" "$first" "$tolerance" || fail "case $name"
}
run bar_trapezoidal axisymmetric_bar axial 0.01 2e-3 total_energy 1e-6
run bar_explicit_musl axisymmetric_bar axial 0.01 2.5e-2 kinetic_energy 1e-6 \
  --set "Inertia/Integrator=explicit MUSL" --set "Time/Time step=0.02"
run bar_explicit_usl_standard axisymmetric_bar axial 0.01 2.5e-2 kinetic_energy 1e-6 \
  --set "Inertia/Integrator=explicit USL" --set "Time/Time step=0.02" \
  --set "Material points/Basis=standard MPM"
run radial_trapezoidal axisymmetric_radial_mode radial 0.01 2e-3 total_energy 1e-4
run radial_explicit_musl axisymmetric_radial_mode radial 0.01 5e-2 kinetic_energy 1e-4 \
  --set "Inertia/Integrator=explicit MUSL" --set "Time/Time step=0.0025"
run radial_explicit_usl_standard axisymmetric_radial_mode radial 0.01 5e-2 kinetic_energy 1e-4 \
  --set "Inertia/Integrator=explicit USL" --set "Time/Time step=0.0025" \
  --set "Material points/Basis=standard MPM"
run radial_explicit_apic axisymmetric_radial_mode radial 0.01 5e-2 kinetic_energy 1e-4 \
  --set "Inertia/Integrator=explicit MUSL" --set "Time/Time step=0.0025" \
  --set "Inertia/Velocity update=APIC"
echo "all cases passed"
