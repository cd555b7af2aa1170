#!/usr/bin/env bash
# The iterative solver under refinement: the collapse (prm/collapse.prm,
# GIMP, 2x2 points per cell) with 'GMRES with AMG' at h = 1, 0.5, 0.25 and
# 0.125 m over the first 24 of its 40 load steps (gravity 6 of 10 kN/m^3, the
# same increments), which take the body from elastic to well into plastic
# flow. Every solve builds its own AMG hierarchy ('AMG reuse factor' 0), so
# the counts measure ML, not how long a kept hierarchy serves. Prints, per grid, the system size, the linear solves and the GMRES
# iterations per solve (mean and largest), and checks that
#  * every accepted load step converged to the scene's 1e-9 and the run
#    reached the full load (at h = 0.25 and 0.125 m the step control cuts
#    steps that would move a point by more than a cell; the cuts are
#    printed);
#  * the mean and the largest iterations per solve at h = 0.125 m are at
#    most twice those at the coarsest grid on which ML builds more than one
#    level (deal.II sets ML's coarse size to 2000 rows, so the systems of
#    h = 1 and 0.5 m are solved by the coarse direct solve in 1 iteration).
# Usage: iterative_solver_refinement.sh IMPM PRM_DIRECTORY [MPIEXEC N]
scenes=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
for cells in "16, 8" "32, 16" "64, 32" "128, 64"; do
  name=h${cells%%,*}
  "${launcher[@]}" "$impm" "$scenes/collapse.prm" \
    --set "Grid/Number of cells=$cells" \
    --set "Body 1/Points per cell direction=2" \
    --set "Gravity/Acceleration=0, -6" --set "Solver/Load steps=24" \
    --set "Solver/Linear solver=GMRES with AMG" --set "Solver/AMG reuse factor=0" \
    --set "Solver/Estimate condition number=false" \
    --set "Output/Interval=0" --set "Output directory=$name" > log.txt 2>&1 ||
    fail "the run at $cells cells failed"
done
python3 - <<'PY' || fail "see above"
import csv, sys
failed = False
rows = []
for n, h in ((16, 1.0), (32, 0.5), (64, 0.25), (128, 0.125)):
    steps = list(csv.DictReader(open("h%d/steps.csv" % n)))
    newton = list(csv.DictReader(open("h%d/newton.csv" % n)))
    iterations = [int(r["linear_iterations"]) for r in newton
                  if r["linear_iterations"] not in ("", "0")]
    accepted = [s for s in steps if s["converged"] == "1"]
    converged = all(float(s["relative_residual"]) <= 1e-9 for s in accepted)
    complete = abs(float(accepted[-1]["load_factor"]) - 1) < 1e-12
    if not converged or not complete:
        print("h = %g m: converged to 1e-9: %s, full load reached: %s"
              % (h, converged, complete))
        failed = True
    print("h = %-5g m: %d load steps, %d not accepted" % (h, len(accepted), len(steps) - len(accepted)))
    mean = sum(iterations) / len(iterations)
    rows.append((h, int(steps[-1]["system_dofs"]), len(iterations), mean, max(iterations)))
    print("h = %-5g m: %6d DoFs, %3d linear solves, GMRES iterations per solve: "
          "mean %5.1f, largest %3d" % rows[-1])
multilevel = [r for r in rows if r[1] > 2000]
coarsest, finest = multilevel[0], multilevel[-1]
for what, index in (("mean", 3), ("largest", 4)):
    ratio = finest[index] / coarsest[index]
    print("%s iterations, h = %g m over h = %g m: %.2f (at most 2)"
          % (what, finest[0], coarsest[0], ratio))
    failed |= ratio > 2
sys.exit(1 if failed else 0)
PY
echo "iterative_solver_refinement: iterations per solve within a factor of 2"
