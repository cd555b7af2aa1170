#!/usr/bin/env bash
# Why a footing's load falls after its peak (issue 34; doc/hard_cases.md,
# "A footing's load after its peak"). The rough footing of
# tests/footing_after_peak.prm (half-width 0.5 m on a weightless Tresca
# layer, c = 10 kPa, Prandtl's load (2 + pi) c B/2 = 25.708 kN/m) is pressed
# 0.24 h into the layer through the grid's top face, four ways:
#  1. standard MPM, h = B/4: the load falls 8.6 % from its peak;
#  2. the same with 'Material points/Move points = false' (each point held
#     where it was seeded; all else as in 1): it stands within 0.1 % of its
#     peak. So the fall comes from the points' motion through the grid,
#     not from the material's response or the change of geometry;
#  3. the same as 1 at h = B/8, pressed 30 mm (again 0.24 h): it falls as
#     much per fraction of a cell as 1 does (7.5 % against 8.6 %), while at
#     the same 30 mm 1 has fallen 4.5 %: the fall follows the settlement in
#     cells, not in metres, so it is the discretisation's;
#  4. GIMP, h = B/4: it falls less (5.2 %): standard MPM's quadrature
#     drifts as the points move within their cells (GIMP integrates over
#     each point's moving domain); what remains is the top face's own part,
#     the soil leaving the grid face on which the footing's displacement is
#     imposed (a rigid footing in contact, which follows the soil, rises
#     with GIMP: measured in doc/hard_cases.md, too long for a test).
# Usage: footing_after_peak.sh IMPM SCENE
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() {
  local name=$1
  shift
  "$impm" "$scene" --set "Output directory=$name" "$@" > log.txt 2>&1 ||
    fail "the footing '$name' failed"
}
run moving
run held --set "Material points/Move points=false"
run moving_fine --set "Grid/Number of cells=40, 16" --set "Grid/Displacement y+=0, -0.03"
run gimp --set "Material points/Basis=GIMP"
/usr/bin/python3 - <<'PY' || fail "the footing's load after its peak"
import csv
prandtl = (2 + 3.141592653589793) * 1e4 * 0.5
def curve(name, settlement, h):
    rows = [r for r in csv.DictReader(open(name + "/steps.csv")) if r["converged"] == "1"]
    points = [(float(r["load_factor"]) * settlement / h, -float(r["reaction_y+_y"])) for r in rows]
    peak = max(f for _, f in points)
    return points, peak
def at(points, cells):
    return min(points, key=lambda p: abs(p[0] - cells))[1]
moving, peak_moving = curve("moving", 0.06, 0.25)
held, peak_held = curve("held", 0.06, 0.25)
fine, peak_fine = curve("moving_fine", 0.03, 0.125)
gimp, peak_gimp = curve("gimp", 0.06, 0.25)
after_peak_held = [f for s, f in held if s >= 0.05]
fall = {name: 1 - points[-1][1] / peak for name, points, peak in
        [("moving", moving, peak_moving), ("fine", fine, peak_fine), ("gimp", gimp, peak_gimp)]}
fall_30mm = 1 - at(moving, 0.12) / peak_moving
for name, peak, points in [("standard MPM, h = B/4", peak_moving, moving),
                           ("points held, h = B/4", peak_held, held),
                           ("standard MPM, h = B/8", peak_fine, fine),
                           ("GIMP, h = B/4", peak_gimp, gimp)]:
    print("%-24s peak %.4f of Prandtl's, at 0.24 h %.4f of the peak" % (name, peak / prandtl, points[-1][1] / peak))
checks = [
    ("points held: the load stands within 0.1 % of its peak from 0.05 h on",
     max(abs(f / peak_held - 1) for f in after_peak_held) < 1e-3,
     "%.5f to %.5f" % (min(after_peak_held) / peak_held, max(after_peak_held) / peak_held)),
    ("points moving: it falls more than 5 % by 0.24 h", fall["moving"] > 0.05, "%.2f %%" % (100 * fall["moving"])),
    ("h = B/8 falls within 1.5 % of h = B/4 at the same settlement in cells (0.24 h)",
     abs(fall["fine"] - fall["moving"]) < 0.015, "%.2f %% against %.2f %%" % (100 * fall["fine"], 100 * fall["moving"])),
    ("... and by more than 2 % more than h = B/4 at the same settlement in metres (30 mm)",
     fall["fine"] - fall_30mm > 0.02, "%.2f %% against %.2f %%" % (100 * fall["fine"], 100 * fall_30mm)),
    ("GIMP falls at least 2 % less than standard MPM by 0.24 h",
     fall["moving"] - fall["gimp"] > 0.02, "%.2f %% against %.2f %%" % (100 * fall["gimp"], 100 * fall["moving"])),
    ("every run reaches 0.24 h", all(abs(p[-1][0] - 0.24) < 1e-9 for p in [moving, held, fine, gimp]), ""),
]
failed = 0
for text, ok, figure in checks:
    print("%s: %s (%s)" % ("ok" if ok else "FAILED", text, figure))
    failed += not ok
raise SystemExit(failed)
PY
