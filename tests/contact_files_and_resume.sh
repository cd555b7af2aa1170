#!/usr/bin/env bash
# Rigid bodies in the output and in checkpoints (issue 13), on the block of
# contact_block_sticking.prm (a Coulomb floor and a plate, 3 steps; the
# faces on the floor store their friction tractions in their points, and
# most of them stick, so the next step starts from those tractions):
#  1. the uninterrupted run with point files every step: the .pvd names,
#     for each output step, the points (part 0) and each rigid body's
#     surface (parts 1 and 2), every file is readable by VTK's XML readers,
#     and the plate's surface at full load lies 1.5 mm right of its start
#     (x from 0.0015 to 0.5015 m);
#  2. stopped after step 1 with a checkpoint there and resumed (on MPIEXEC
#     N processes if given): the same final summary (forces on both bodies,
#     extents) and steps.csv as the uninterrupted run, so the friction
#     tractions came through the checkpoint;
#  3. the same with HDF5 point files, stopped and resumed: the bodies'
#     surfaces form their own series, points_parts.pvd, with both bodies at
#     each of the 4 output steps of points.xdmf, the plate's at full load
#     where it was moved;
#  4. a body pushed by a force (tests/contact_plate_force_driven.prm, its
#     displacement an unknown) stopped after step 4 and resumed: the same
#     summary (the plate's final displacement among it) and steps.csv
#     (rigid_1_displacement_y in every step) as its uninterrupted run, and
#     the plate's surface at full load where the unknown put it (y from
#     0.750002 to 1.000002 m);
#  5. the Winkler springs' layer stopped after step 1 and resumed: the same
#     summary (the springs' face displacements came through the checkpoint).
# Usage: contact_files_and_resume.sh IMPM SCENE [MPIEXEC N]
# (SCENE: tests/contact_block_sticking.prm)
scene=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/script_helpers.sh" "$@"
settings=(--set "Output/Interval=1")
# spans FILE AXIS LOW HIGH TOLERANCE: the VTU file's points span [LOW, HIGH]
# along axis AXIS (0, 1, 2) within TOLERANCE, as VTK's reader sees them.
spans() {
  /usr/bin/python3 - "$@" <<'PYTHON'
import sys, vtk
name, axis, low, high, tolerance = sys.argv[1], int(sys.argv[2]), *map(float, sys.argv[3:6])
reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(name)
reader.Update()
bounds = reader.GetOutput().GetBounds()
assert abs(bounds[2 * axis] - low) < tolerance and abs(bounds[2 * axis + 1] - high) < tolerance, bounds
PYTHON
}

# 1. The uninterrupted run and its files.
"$impm" "$scene" "${settings[@]}" > full.txt 2>&1 || fail "the uninterrupted run failed"
summary full.txt > full_summary.txt
untimed results/steps.csv > full_steps.csv
/usr/bin/python3 "$here/check_point_files.py" results > check.txt || { cat check.txt; fail "a point or body file is incomplete"; }
n_points=$(grep -c 'part="0" file="points_' results/points.pvd)
[ "$(grep -c 'part="1" file="rigid_1_' results/points.pvd)" -eq "$n_points" ] || fail "the floor is not in every output step"
[ "$(grep -c 'part="2" file="rigid_2_' results/points.pvd)" -eq "$n_points" ] || fail "the plate is not in every output step"
spans results/rigid_2_00003.vtu 0 0.0015 0.5015 1e-12 ||
  fail "the plate's surface is not where it was moved"

# 2. Stopped after step 1 and resumed.
rm -rf results
"$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=1" \
  --stop-after-step 1 > part1.txt 2>&1 || fail "the first part failed"
"${launcher[@]}" "$impm" "$scene" "${settings[@]}" --set "Checkpoint/Interval=1" \
  --resume > part2.txt 2>&1 || fail "the resumed run failed"
grep -q "^step   2 " part2.txt || fail "the resumed run did not start at step 2"
summary part2.txt > resumed_summary.txt
compare full_summary.txt resumed_summary.txt "the resumed run ends in another state"
untimed results/steps.csv > resumed_steps.csv
compare full_steps.csv resumed_steps.csv "steps.csv of the resumed run differs"
# 3. HDF5 point files: the bodies in a series of their own.
rm -rf results
h5=("${settings[@]}" --set "Output/Format=hdf5" --set "Checkpoint/Interval=1")
"$impm" "$scene" "${h5[@]}" --stop-after-step 1 > h5_part1.txt 2>&1 || fail "the first HDF5 part failed"
"${launcher[@]}" "$impm" "$scene" "${h5[@]}" --resume > h5_part2.txt 2>&1 || fail "the resumed HDF5 run failed"
n_steps=$(grep -c '<Time ' results/points.xdmf)
[ "$n_steps" -eq 4 ] || fail "points.xdmf has $n_steps output steps, not 4"
for body in 1 2; do
  [ "$(grep -c "file=\"rigid_${body}_" results/points_parts.pvd)" -eq "$n_steps" ] ||
    fail "Rigid body $body is not in every step of points_parts.pvd"
done
grep -q 'timestep="1" group="" part="1" file="rigid_2_00003.vtu"' results/points_parts.pvd ||
  fail "points_parts.pvd does not end with the plate at full load"
# 4. A body pushed by a force: its displacement through the checkpoint.
rm -rf results
pushed=("$here/contact_plate_force_driven.prm" --set "Testing/Check tangent=false"
        --set "Output/Interval=10")
"$impm" "${pushed[@]}" > pushed_full.txt 2>&1 || fail "the pushed plate's run failed"
grep -q "^final displacement of Rigid body 1 (force-driven): y -1.99998" pushed_full.txt ||
  fail "the pushed plate's run does not report its displacement"
summary pushed_full.txt > pushed_full_summary.txt
untimed results/steps.csv > pushed_full_steps.csv
rm -rf results
"$impm" "${pushed[@]}" --set "Checkpoint/Interval=1" --stop-after-step 4 \
  > pushed_part1.txt 2>&1 || fail "the pushed plate's first part failed"
"${launcher[@]}" "$impm" "${pushed[@]}" --set "Checkpoint/Interval=1" --resume \
  > pushed_part2.txt 2>&1 || fail "the pushed plate's resumed run failed"
summary pushed_part2.txt > pushed_resumed_summary.txt
compare pushed_full_summary.txt pushed_resumed_summary.txt "the resumed pushed plate ends in another state"
untimed results/steps.csv > pushed_resumed_steps.csv
compare pushed_full_steps.csv pushed_resumed_steps.csv "steps.csv of the resumed pushed plate differs"
spans results/rigid_1_00010.vtu 1 0.750002 1.000002 1e-6 ||
  fail "the pushed plate's surface is not where its unknown put it"
# 5. Winkler springs (tests/winkler_springs_layer.prm, 2 steps): the
#    springs' face displacements through the checkpoint (lost, the second
#    step's springs would start unstretched and carry half the weight).
rm -rf results
springs=("$here/winkler_springs_layer.prm")
"$impm" "${springs[@]}" > springs_full.txt 2>&1 || fail "the springs' run failed"
summary springs_full.txt > springs_full_summary.txt
rm -rf results
"$impm" "${springs[@]}" --set "Checkpoint/Interval=1" --stop-after-step 1 \
  > springs_part1.txt 2>&1 || fail "the springs' first part failed"
"${launcher[@]}" "$impm" "${springs[@]}" --set "Checkpoint/Interval=1" --resume \
  > springs_part2.txt 2>&1 || fail "the springs' resumed run failed"
summary springs_part2.txt > springs_resumed_summary.txt
compare springs_full_summary.txt springs_resumed_summary.txt "the resumed springs end in another state"
echo "contact_files_and_resume: passed"
