#!/usr/bin/env bash
# Axisymmetry against the 3D quarter model: the elastic cylinder under its
# own weight and a top pressure (tests/axisymmetric_cylinder.prm, meridian
# plane) and its quarter in 3D (tests/axisymmetric_cylinder_3d.prm), on
# MPIEXEC N processes if given. Checks:
#  * the axisymmetric run's mass and base reaction exact (rho g pi a^2 H +
#    p pi a^2: the ring's 2 pi r in volumes, masses and the traction);
#  * at five probes (the top centre, the top, middle and bottom of the side,
#    the middle of the body) the axial and radial displacements within 0.5 %
#    of the largest displacement, and the axial stress within 0.5 % of
#    rho g H + p, of the 3D model's (the 3D radial displacement projected on
#    the probe's radial direction);
#  * the 3D model's base reaction equals its own load: its points' weight
#    (their staircase cross-section is 0.96 % larger than the quarter
#    circle) and the pressure on the exact quarter circle (the top's
#    lattice cells cut by the circle; before, its staircase too); the ratio
#    to the axisymmetric load is printed, not a discrepancy.
# Usage: axisymmetric_cylinder.sh IMPM TESTS_DIR [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$tests/axisymmetric_cylinder.prm" \
  --set "Output directory=ax" > ax.txt 2>&1 || { cp ax.txt log.txt; fail "the axisymmetric run"; }
"${launcher[@]}" "$impm" "$tests/axisymmetric_cylinder_3d.prm" \
  --set "Output directory=3d" > 3d.txt 2>&1 || { cp 3d.txt log.txt; fail "the 3D quarter run"; }
/usr/bin/python3 - <<'PY' || fail "axisymmetric against 3D"
import math, re
def read(name):
    text = open(name).read()
    probes = []
    for line in text.splitlines():
        m = re.match(r"point \d+: X = ([^,]+), u = ([^,]+), sigma_vertical = ([-0-9.]+)", line)
        if m:
            probes.append(([float(v) for v in m.group(1).split()],
                           [float(v) for v in m.group(2).split()], float(m.group(3))))
    # The base: face y- in the plane, z- in 3D (the last one printed).
    reaction = float(re.findall(r"final reaction on face ([yz])-, component \1: ([-0-9.]+)", text)[-1][1])
    mass = float(re.search(r"total mass: ([-0-9.e+]+)", text).group(1))
    return probes, reaction, mass
ax, ax_reaction, ax_mass = read("ax.txt")
q3, q3_reaction, q3_mass = read("3d.txt")
L, S = 0.125, 1e4
rho, g, p, a, H = 2000., 10., 1e4, 1., 2.
ok = True
def check(what, value, reference, tolerance):
    global ok
    good = abs(value - reference) <= tolerance
    ok = ok and good
    print(f"{what}: {value:.6g} against {reference:.6g} ({'ok' if good else 'FAILED'})")
check("axisymmetric mass", ax_mass, rho * math.pi * a * a * H, 1e-8 * ax_mass)
load = rho * g * math.pi * a * a * H + p * math.pi * a * a
check("axisymmetric base reaction (N)", ax_reaction * S * L, load, 1e-8 * load)
# The 3D reaction is in S L^2 for a quarter: its own weight and pressure.
q3_load = q3_mass * g + p * math.pi * a * a / 4
check("3D quarter base reaction (N)", q3_reaction * S * L * L, q3_load, 1e-8 * q3_load)
print(f"3D quarter load / axisymmetric load / 4: {4 * q3_load / load:.4f}")
u_scale = max(abs(c) for _, u, _ in ax for c in u) * L
for (X, u, s), (X3, u3, s3) in zip(ax, q3):
    radial = [X3[0] / math.hypot(X3[0], X3[1]), X3[1] / math.hypot(X3[0], X3[1])]
    u3_r = u3[0] * radial[0] + u3[1] * radial[1]
    name = f"probe r = {X[0]:.5f}, z = {X[1]:.5f}"
    check(name + ": u_z / largest u", u[1] * L / u_scale, u3[2] * L / u_scale, 0.005)
    check(name + ": u_r / largest u", u[0] * L / u_scale, u3_r * L / u_scale, 0.005)
    check(name + ": sigma_zz / (rho g H + p)", s * S / (rho * g * H + p), s3 * S / (rho * g * H + p), 0.005)
raise SystemExit(0 if ok else 1)
PY
