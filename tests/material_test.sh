#!/usr/bin/env bash
# The material test without a grid ('Material test' in a scene): each
# scene tests/material_test_*.prm drives one point along a path, and
# tests/check_material_test.py checks the CSV it writes against a closed
# form, a hand result or scripts/cam_clay_drained.py (each scene's comment
# says which):
#   Cam-clay undrained triaxial  p'/p'0 = (M^2/(M^2+eta^2))^Lambda, 0.5 %
#   Cam-clay drained triaxial    scripts/cam_clay_drained.py, 0.5 %
#   von Mises simple shear       q = 2 sqrt(3) G asinh(gamma/2), then
#                                sqrt(3/2) rho_y
#   Mohr-Coulomb drained         peak q = 2 sin(phi)/(1 - sin(phi)) sigma_3
#   triaxial (and extension)     + 2 c cos(phi)/(1 - sin(phi)) (Kirchhoff)
#   Mohr-Coulomb simple shear    steady tau = sigma_n sin(phi) + c cos(phi)
#                                on the horizontal plane (psi = 0)
#   Hencky oedometer, cyclic     linear in the logarithmic strain
#   Mohr-Coulomb with a tension cut-off, softening to a residual cohesion
#   of 1 kPa, drained triaxial to an axial strain of 5 in 100 steps of 5 %
#   (its return fails in such steps: each is taken in sub-steps): the
#   last row's q at the residual strength, 2 sin(phi)/(1 - sin(phi))
#   tau_3 + 2 c_r cos(phi)/(1 - sin(phi)) in Kirchhoff stress (written as
#   Cauchy's, over J), to 1e-9, and the run in 400 steps ends the same
#   (until 2026-11-29 the 100-step run stopped with an "Internal error")
# Usage: material_test.sh IMPM TESTS_DIRECTORY
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
repository=$(cd "$tests/.." && pwd)
check() { python3 "$tests/check_material_test.py" "$1" "$2" "$repository" || fail "$1"; }
run() { "$impm" "$@" > log.txt 2>&1 || fail "impm $*"; cat log.txt; }

run "$tests/material_test_cam_clay_undrained.prm"
check cam_clay_undrained cam_clay_undrained.csv
run "$tests/material_test_cam_clay_drained.prm"
check cam_clay_drained cam_clay_drained.csv
run "$tests/material_test_von_mises_shear.prm"
check von_mises_shear von_mises_shear.csv
run "$tests/material_test_mohr_coulomb_triaxial.prm"
check mohr_coulomb_compression mohr_coulomb_triaxial.csv
run "$tests/material_test_mohr_coulomb_triaxial.prm" \
  --set "Material test/Path=drained triaxial extension" \
  --set "Material test/File=mohr_coulomb_extension.csv"
check mohr_coulomb_extension mohr_coulomb_extension.csv
run "$tests/material_test_mohr_coulomb_triaxial.prm" \
  --set "Material test/Path=simple shear" --set "Material test/Strain=1" \
  --set "Material test/File=mohr_coulomb_shear.csv"
check mohr_coulomb_shear mohr_coulomb_shear.csv
run "$tests/material_test_hencky_oedometer.prm"
check hencky_oedometer hencky_oedometer.csv
run "$tests/material_test_hencky_oedometer.prm" \
  --set "Material test/Path=cyclic" --set "Material test/Cyclic path=simple shear" \
  --set "Material test/Strain=0.01" --set "Material test/Number of steps=8" \
  --set "Material test/Number of cycles=3" --set "Material test/File=hencky_cyclic.csv"
check hencky_cyclic hencky_cyclic.csv
softening=(--set "Body 1/Material/Mohr-Coulomb/Tension cut-off=true"
  --set "Body 1/Material/Mohr-Coulomb/Tensile strength=1000"
  --set "Body 1/Material/Mohr-Coulomb/Hardening modulus=-1e5"
  --set "Body 1/Material/Mohr-Coulomb/Residual cohesion=1000"
  --set "Material test/Strain=5" --set "Material test/Initial vertical stress=1e4"
  --set "Material test/K0=0.5")
run "$tests/material_test_mohr_coulomb_triaxial.prm" "${softening[@]}" \
  --set "Material test/Number of steps=100" --set "Material test/File=softening_100.csv"
run "$tests/material_test_mohr_coulomb_triaxial.prm" "${softening[@]}" \
  --set "Material test/Number of steps=400" --set "Material test/File=softening_400.csv"
/usr/bin/python3 - softening_100.csv softening_400.csv <<'PY' || fail "softening Mohr-Coulomb in large steps"
import csv, math, sys
coarse = list(csv.DictReader(open(sys.argv[1])))[-1]
fine = list(csv.DictReader(open(sys.argv[2])))[-1]
s = math.sin(math.radians(30.))
J = math.exp(-float(coarse["volumetric_strain"]))
expected = (2 * s / (1 - s) * 5000. * J + 2 * 1000. * math.cos(math.radians(30.)) / (1 - s)) / J
q, q_fine = float(coarse["q"]), float(fine["q"])
print("softening Mohr-Coulomb, 100 steps of 5 %%: q = %.6f Pa at the residual strength %.6f; 400 steps: %.6f"
      % (q, expected, q_fine))
sys.exit(0 if abs(q / expected - 1) < 1e-9 and abs(q / q_fine - 1) < 1e-9 else 1)
PY
# The state fields and the void ratio are columns (Cam-clay: e = (1 + e0) J - 1).
head -1 cam_clay_drained.csv | grep -q ",void_ratio,preconsolidation_pressure$" ||
  fail "cam_clay_drained.csv lacks the void ratio and the state: $(head -1 cam_clay_drained.csv)"
head -1 von_mises_shear.csv | grep -q "shear_stress,plastic_multiplier$" ||
  fail "von_mises_shear.csv: $(head -1 von_mises_shear.csv)"
echo "material_test: passed"
