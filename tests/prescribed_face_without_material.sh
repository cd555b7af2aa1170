#!/usr/bin/env bash
# A prescribed grid face that no material point reaches moves nothing: the
# run says so once on standard error, on MPIEXEC N processes if given. The
# block of SCENE (tests/effect_prescribed_displacement.prm, 1 m x 1 m in
# cells of 0.25 m, its top face pushed down 0.1 m) cut to 0.5 m high leaves
# the top row of cells empty: the warning names face y+ from load factor 0
# (once, over 4 load steps), and the face's reaction is zero in every step.
# The block as it is (its top in the cells along the face) gets no warning.
# Usage: prescribed_face_without_material.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
run=(--set "Testing/Enabled=false" --set "Solver/Load steps=4" --overwrite)

"${launcher[@]}" "$impm" "$scene" "${run[@]}" > out.txt 2> err.txt ||
  { cp err.txt log.txt; fail "the block reaching the face failed"; }
grep -q "Warning" err.txt && { cp err.txt log.txt; fail "a warning for a face the block reaches"; }

"${launcher[@]}" "$impm" "$scene" "${run[@]}" --set "Body 1/Upper corner=1, 0.5" > out.txt 2> err.txt ||
  { cp err.txt log.txt; fail "the lower block failed"; }
[ "$(grep -c "^Warning" err.txt)" -eq 1 ] ||
  { cp err.txt log.txt; fail "not one warning for the face no point reaches"; }
grep -q "^Warning: from load factor 0 on, no material point reaches the prescribed grid face y+ (no material lies in the cells along it): its displacement moves nothing, and its reaction is zero." err.txt ||
  { cp err.txt log.txt; fail "the warning does not name face y+ from load factor 0"; }
/usr/bin/python3 - results/steps.csv <<'PY' || fail "the face's reaction is not zero"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 4 and all(float(r["reaction_y+_y"]) == 0. for r in rows), rows
PY
echo "prescribed_face_without_material: passed"
