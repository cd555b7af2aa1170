#!/usr/bin/env bash
# 'Initial stress release' (tests/initial_stress_release.prm: an elastic
# block beside a free face, geostatic start with K0 = 0.6, gravity at once),
# on MPIEXEC N processes if given:
#  1. released over 4 load steps: the symmetry line's horizontal reaction
#     is (1 - load factor) K0 gamma H^2 / 2 = (1 - lambda) 192 kN/m (by
#     hand: at lambda = 0 the supports carry the initial stress's thrust,
#     at 1 none, as the roller base takes no horizontal force), the base
#     carries the weight 640 kN/m at every step, the reactions balance, and
#     the displacements grow in proportion to the load factor (an elastic
#     block, strains of 1e-5: the release starts from equilibrium and is
#     linear in lambda);
#  2. without the release (the imbalance applied in step 1) and
#  3. released in one step: the same final displacements as 1 (the release
#     leaves nothing at lambda = 1);
#  4. stopped after step 2 and resumed: steps.csv as an uninterrupted run's.
# Usage: initial_stress_release.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run() {
  local name=$1
  shift
  "${launcher[@]}" "$impm" "$scene" --set "Output directory=$name" "$@" > "$name.txt" 2>&1 ||
    { cp "$name.txt" log.txt; fail "the run '$name' failed"; }
  grep -q "reactions balance the load to 1e-8 in every step: yes" "$name.txt" ||
    { cp "$name.txt" log.txt; fail "the reactions of '$name' do not balance the load"; }
}
run released --set "Testing/Enabled=true"
run at_once --set "Testing/Enabled=true" --set "Initial stress release/Enabled=false"
run one_step --set "Testing/Enabled=true" --set "Solver/Load steps=1"
# 4. stopped after step 2 and resumed: the same steps.csv as 1 (the points
#    carry their initial stresses through the checkpoint).
"${launcher[@]}" "$impm" "$scene" --set "Output directory=resumed" --set "Checkpoint/Interval=1" \
  --stop-after-step 2 > stopped.txt 2>&1 || { cp stopped.txt log.txt; fail "the run to resume failed"; }
"${launcher[@]}" "$impm" "$scene" --set "Output directory=resumed" --set "Checkpoint/Interval=1" \
  --resume > resumed.txt 2>&1 || { cp resumed.txt log.txt; fail "the resumed run failed"; }
"${launcher[@]}" "$impm" "$scene" --set "Output directory=whole" > whole.txt 2>&1 ||
  { cp whole.txt log.txt; fail "the run to compare with failed"; }
untimed whole/steps.csv > whole.csv
untimed resumed/steps.csv > resumed.csv
compare whole.csv resumed.csv "the resumed release differs from the uninterrupted one"
/usr/bin/python3 - <<'PY' || fail "the initial stress release"
import csv, glob
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

def displacements(directory, step):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName("%s/points_%05d.pvtu" % (directory, step))
    reader.Update()
    data = reader.GetOutput().GetPointData()
    initial = vtk_to_numpy(data.GetArray("initial_position"))
    u = vtk_to_numpy(data.GetArray("displacement"))
    order = np.lexsort((initial[:, 0], initial[:, 1]))
    return u[order]

rows = [r for r in csv.DictReader(open("released/steps.csv")) if r["converged"] == "1"]
thrust = 0.6 * 1000 * 10 * 8 ** 2 / 2
weight = 1000 * 10 * 8 * 8
final = displacements("released", 4)
scale = np.abs(final).max()
worst_thrust = max(abs(float(r["reaction_x-_x"]) - (1 - float(r["load_factor"])) * thrust) / thrust for r in rows)
worst_weight = max(abs(float(r["reaction_y-_y"]) - weight) / weight for r in rows)
worst_linear = max(np.abs(displacements("released", k) - k / 4 * final).max() / scale for k in (1, 2, 3))
at_once = np.abs(displacements("at_once", 4) - final).max() / scale
one_step = np.abs(displacements("one_step", 1) - final).max() / scale
print("largest displacement %.4e m" % scale)
checks = [
    ("4 steps, each converged", len(rows) == 4, "%d" % len(rows)),
    ("symmetry line's reaction (1 - lambda) 192 kN/m within 1e-4", worst_thrust < 1e-4, "%.2e" % worst_thrust),
    ("base reaction 640 kN/m within 1e-6 at every step", worst_weight < 1e-6, "%.2e" % worst_weight),
    ("displacements lambda u(1) within 1e-3 of the largest", worst_linear < 1e-3, "%.2e" % worst_linear),
    ("without the release, the same end within 1e-4", at_once < 1e-4, "%.2e" % at_once),
    ("released in one step, the same end within 1e-4", one_step < 1e-4, "%.2e" % one_step),
]
failed = 0
for text, ok, figure in checks:
    print("%s: %s (%s)" % ("ok" if ok else "FAILED", text, figure))
    failed += not ok
raise SystemExit(failed)
PY
