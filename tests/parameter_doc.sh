#!/usr/bin/env bash
# doc/parameters.md must be what scripts/make_parameter_doc.sh makes from the
# program now: every parameter documented, none stale.
# Usage: parameter_doc.sh IMPM SOURCE_DIRECTORY
set -u
expected=$(bash "$2/scripts/make_parameter_doc.sh" "$1")
if [ "$expected" != "$(cat "$2/doc/parameters.md")" ]; then
  echo "doc/parameters.md differs from the program's parameters; remake it with"
  echo "  scripts/make_parameter_doc.sh build/impm > doc/parameters.md"
  diff <(echo "$expected") "$2/doc/parameters.md" | head -20
  exit 1
fi
echo "doc/parameters.md matches --print-parameters"
