#!/usr/bin/env bash
# summary.json is valid JSON whatever the scene's name: a name with a
# quote, a backslash and a tab is written escaped, python3's json module
# reads the file (python3 -m json.tool) and gives the name back unchanged.
# Usage: summary_json.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
name=$(printf 'a "quoted" name\\with a backslash\tand a tab')
"${launcher[@]}" "$impm" "$scene" --set "Scene name=$name" > log.txt 2>&1 ||
  fail "the run failed"
/usr/bin/python3 -m json.tool results/summary.json > /dev/null 2> json_error.txt ||
  { cat json_error.txt results/summary.json; fail "summary.json is not valid JSON"; }
/usr/bin/python3 - "$name" << 'PYTHON' || fail "summary.json does not give the scene's name back"
import json, sys
with open("results/summary.json") as f:
    summary = json.load(f)
assert summary["scene"] == sys.argv[1], (summary["scene"], sys.argv[1])
assert summary["processes"] >= 1
PYTHON
echo "summary_json: summary.json is valid JSON with the name given back"
