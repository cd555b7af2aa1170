#!/usr/bin/env bash
# summary.json is valid JSON whatever the scene's name: a name with a
# quote, a backslash, the two characters \n (a newline's escape, which a
# writer by hand might pass through as one) and a tab is written escaped
# (nlohmann::json), python3's json module reads the file (python3 -m
# json.tool) and gives the name back unchanged; the number of processes,
# the total mass (64,000 kg: the block of 8 x 8 m at 1000 kg/m^3, per m
# of thickness) and the condition estimate are numbers; IMPM's version, its
# revision and deal.II's version are those `impm --version` prints.
# Usage: summary_json.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
name=$(printf 'a "quoted" name\\with a backslash, \\n as text\tand a tab')
"${launcher[@]}" "$impm" "$scene" --set "Scene name=$name" > log.txt 2>&1 ||
  fail "the run failed"
/usr/bin/python3 -m json.tool results/summary.json > /dev/null 2> json_error.txt ||
  { cat json_error.txt results/summary.json; fail "summary.json is not valid JSON"; }
version=$("$impm" --version) || fail "impm --version failed"
/usr/bin/python3 - "$name" "$version" << 'PYTHON' || fail "summary.json does not give the scene's name back"
import json, sys
with open("results/summary.json") as f:
    summary = json.load(f)
assert summary["scene"] == sys.argv[1], (summary["scene"], sys.argv[1])
assert summary["processes"] >= 1
assert abs(summary["total_mass"] - 64000) < 1e-6, summary["total_mass"]
assert summary["worst_condition_estimate"] > 0
assert isinstance(summary["wall_time_per_phase"], dict)
expected = "IMPM %s (revision %s), built against deal.II %s" % (
    summary["impm_version"], summary["impm_revision"], summary["deal_ii_version"])
assert expected == sys.argv[2], (expected, sys.argv[2])
PYTHON
echo "summary_json: summary.json is valid JSON with the name given back"
