#!/usr/bin/env bash
# The error of the rigid plate benchmark (tests/contact_plate_compression)
# against the penalty factor: the points' vertical stress against the exact
# -0.372615 S of a rigid plate, the Newton iterations of the 10 steps and
# the run's wall time (summary.json).
# Usage: scripts/contact_penalty_study.sh [IMPM] > table.csv
impm=$(realpath "${1:-build/impm}")
scene=$(cd "$(dirname "$0")/.." && pwd)/tests/contact_plate_compression.prm
work=$(mktemp -d)
cd "$work" || exit 1
echo "penalty_factor,sigma_yy_over_S,relative_error,newton_iterations,wall_time_s"
for factor in 1 3 10 30 100 300 1000 10000; do
  "$impm" "$scene" --overwrite --set "Rigid body 1/Penalty factor=$factor" \
    --set "Testing/Check tangent=false" > out.txt 2>&1 || exit 1
  sigma=$(sed -n 's/^point 0:.*sigma_vertical = \([-0-9.]*\).*/\1/p' out.txt)
  iterations=$(sed -n 's/.*total Newton iterations: \([0-9]*\).*/\1/p' out.txt)
  wall=$(sed -n 's/.*"wall_time": \([0-9.e+-]*\),.*/\1/p' results/summary.json)
  python3 -c "print('$factor,$sigma,%.5f,$iterations,%.2f' % (abs($sigma / -0.372615 - 1), $wall))"
done
rm -rf "$work"
