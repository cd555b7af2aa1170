#!/usr/bin/env bash
# The geostatic start under shapes that are not flat layers
# (tests/geostatic_overburden.prm: a slope, a box on its crest with a named
# surface level above its top, a disc on its bench), on MPIEXEC N processes
# if given:
#  1. every point's start stress equals the overburden an independent
#     script finds (tests/check_geostatic_overburden.py): the weight of
#     every body above the point, the box's from its named surface;
#  2. the start-up report says which overburden each body takes;
#  3. the check can fail: with the box's surface level removed the box
#     starts from its own 2 m, not the 3 m to the named surface, and the
#     script reports it.
# Usage: geostatic_overburden.sh IMPM SCENE [MPIEXEC N]
scene=$2
checker=$(cd "$(dirname "$0")" && pwd)/check_geostatic_overburden.py
source "$(dirname "$0")/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$scene" > run.txt 2>&1 || { cp run.txt log.txt; fail "the run failed"; }
/usr/bin/python3 "$checker" results/points_00000.pvtu || fail "the start's stresses"
grep -q "Body 1: polygon with 6 vertices.*geostatic start: K0 = 0.6, under the bodies above" run.txt ||
  { cp run.txt log.txt; fail "the report does not say Body 1 starts under the bodies above"; }
grep -q "Body 2: box.*geostatic start: K0 = 0.5, surface at 13 m" run.txt ||
  { cp run.txt log.txt; fail "the report does not name Body 2's surface"; }
"${launcher[@]}" "$impm" "$scene" --set "Output directory=unnamed" --set "Body 2/Surface level=" \
  > unnamed.txt 2>&1 || { cp unnamed.txt log.txt; fail "the run without a named surface failed"; }
if /usr/bin/python3 "$checker" unnamed/points_00000.pvtu > unnamed_check.txt; then
  fail "the check passed a box that starts 1 m short of its named surface"
fi
grep -q FAILED unnamed_check.txt || fail "the check of the unnamed surface did not report"
echo "geostatic_overburden: passed"
