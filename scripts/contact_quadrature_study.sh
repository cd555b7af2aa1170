#!/usr/bin/env bash
# What the Gauss points per face of the rigid contact cost and buy: the
# pipe of prm/pipe_penetration.prm pushed 0.6 m (120 steps; with the faces'
# centres alone it does not reach 1 m) with 'Face quadrature points' = 1 to
# 4, each configuration run REPS times, interleaved. Prints the final
# vertical force on the pipe, the probes in contact, the accepted steps,
# the cuts, the Newton iterations and the wall time (summary.json).
# Usage: scripts/contact_quadrature_study.sh [IMPM] [REPS] > table.csv
impm=$(realpath "${1:-build/impm}")
reps=${2:-2}
scene=$(cd "$(dirname "$0")/.." && pwd)/prm/pipe_penetration.prm
work=$(mktemp -d)
cd "$work" || exit 1
echo "face_points,rep,force_y,contacts,steps,cuts,newton_iterations,wall_time_s"
for rep in $(seq 1 "$reps"); do
  for points in 1 2 3 4; do
    "$impm" "$scene" --overwrite --set "Output/Interval=0" \
      --set "Rigid body 1/Displacement=0, -0.6" --set "Solver/Load steps=120" \
      --set "Rigid body 1/Face quadrature points=$points" \
      --set "Testing/Enabled=true" > out.txt 2>&1 || { echo "$points,$rep,failed"; continue; }
    force=$(sed -n 's/^final force on Rigid body 1: x \S* y \(\S*\),.* \([0-9]*\) probes in contact.*/\1,\2/p' out.txt)
    steps=$(grep -c '^step .*iterations' out.txt)
    cuts=$(sed -n 's/.*load-step cuts: \([0-9]*\).*/\1/p' out.txt)
    iterations=$(sed -n 's/.*total Newton iterations: \([0-9]*\).*/\1/p' out.txt)
    wall=$(sed -n 's/.*"wall_time": \([0-9.e+-]*\),.*/\1/p' output/summary.json)
    echo "$points,$rep,$force,$steps,$cuts,$iterations,$wall"
  done
done
rm -rf "$work"
