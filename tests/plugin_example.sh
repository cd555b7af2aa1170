#!/usr/bin/env bash
# Plugins from shared libraries, end to end: IMPM installed into a prefix
# under the build directory (cmake --install), the plugin project of
# tests/plugin_example/ configured against it with find_package(impm) and
# built, and its scene (column.prm: the column under its own weight with the
# plugin's material "plugin elastic", loaded by 'Additional shared
# libraries') run by the installed program. Checked: the installed layout,
# a launcher that links no deal.II and finds its library when the prefix is
# moved; the plugin run's test summary equals
# that of the same scene with the built-in "Hencky elastic", and its step-1
# error, mass and base reaction equal the hand-checked expected.txt (see
# column.prm); --print-parameters lists the plugin; a library that does not
# exist, a file that is not a library and a second copy of the plugin (its
# name registered twice) are each one error line.
# Usage: plugin_example.sh IMPM EXAMPLE_FOLDER [MPIEXEC N]
example=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
build=$(cd "$(dirname "$impm")" && pwd)
prefix=$(mktemp -d "$build/plugin_example_prefix.XXXXXX")
trap 'rm -rf "$work" "$prefix"' EXIT

cmake --install "$build" --prefix "$prefix" > log.txt 2>&1 || fail "cmake --install"
for file in bin/impm lib/libimpm_core.so include/impm/mechanics/material.h \
  lib/cmake/impm/impmConfig.cmake lib/cmake/impm/impmConfigVersion.cmake \
  lib/cmake/impm/impmTargets.cmake \
  share/impm/prm/column_compaction.prm share/impm/doc/plugins.md \
  share/impm/README.md; do
  [ -f "$prefix/$file" ] || fail "the install has no $file"
done
# The installed program names its version (the one find_package asks for).
"$prefix/bin/impm" --version | grep -qE "^IMPM 0\.1\.[0-9]+ \(revision [^)]+\), built against deal\.II 9\.[0-9.]+$" ||
  fail "the installed program's --version"
# The program is a launcher that links no deal.II and finds the library
# relative to itself: the prefix moved elsewhere still runs.
readelf -d "$prefix/bin/impm" | grep NEEDED | grep -q deal &&
  fail "the installed launcher links deal.II"
mv "$prefix" "$prefix.moved" && mkdir "$prefix"
"$prefix.moved/bin/impm" --print-parameters > moved.txt 2> log.txt ||
  fail "the installed program, moved, did not find its library"
grep -q "^subsection Grid" moved.txt || fail "the moved program printed no parameters"
rmdir "$prefix" && mv "$prefix.moved" "$prefix"

cmake -S "$example" -B plugin_build -DCMAKE_PREFIX_PATH="$prefix" \
  > log.txt 2>&1 || fail "configuring the plugin with find_package(impm)"
cmake --build plugin_build > log.txt 2>&1 || fail "building the plugin"
cp "$example/column.prm" scene.prm

installed=("${launcher[@]}" "$prefix/bin/impm")
"${installed[@]}" scene.prm > plugin.txt 2> log.txt || fail "the plugin's scene"
"${installed[@]}" scene.prm --set "Body 1/Material/Model=Hencky elastic" \
  --set "Body 1/Material/Hencky elastic/Young's modulus=1e6" \
  > built_in.txt 2> log.txt || fail "the scene with Hencky elastic"
compare plugin.txt built_in.txt "the plugin's material differs from Hencky elastic"
{ grep '^step   1 ' plugin.txt | sed 's/^step   1 .* error /step 1: error /'
  grep -E '^total mass|^final reaction on face y-' plugin.txt; } > checked.txt
compare checked.txt "$example/expected.txt" "the hand-checked numbers differ"

"$prefix/bin/impm" --print-parameters \
  --set "Additional shared libraries=plugin_build/libplugin_elastic.so" \
  > parameters.txt 2> log.txt || fail "--print-parameters with the plugin"
grep -q "subsection plugin elastic" parameters.txt ||
  fail "--print-parameters does not list the plugin's subsection"

# bad LIBRARIES REGEX: the scene with those libraries is one error line
# matching REGEX.
bad() {
  "${installed[@]}" scene.prm --set "Additional shared libraries=$1" \
    > out.txt 2>&1 && fail "'$1' was accepted"
  [ "$(grep -c '^Error: ' out.txt)" -eq 1 ] || { cat out.txt; fail "'$1': not one error line"; }
  grep -qE "^Error: 'Additional shared libraries': $2" out.txt ||
    { cat out.txt; fail "'$1': not the expected error"; }
  if [ ${#launcher[@]} -eq 0 ]; then
    [ "$(wc -l < out.txt)" -eq 1 ] || { cat out.txt; fail "'$1': more than one line"; }
  fi
}
bad /nonexistent/libnothing.so \
  "cannot load '/nonexistent/libnothing.so': .*No such file"
bad "$work/scene.prm" \
  "cannot load '.*scene.prm': .*(invalid ELF header|file too short)"
# A copy of the plugin (another file) registers its name a second time.
mkdir copy && cp plugin_build/libplugin_elastic.so copy/
bad "$work/plugin_build/libplugin_elastic.so, $work/copy/libplugin_elastic.so" \
  "the library '.*copy/libplugin_elastic.so': two plugins are registered as 'plugin elastic'\.$"
echo "installed, the plugin built and run: the same numbers as Hencky elastic"
