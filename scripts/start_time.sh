#!/usr/bin/env bash
# The start of a small run, by parts (issue 32): the median wall time of
# REPEATS interleaved runs of each of
#   help:        impm --help (the launcher alone, no library loaded)
#   parameters:  impm --print-parameters (the library and the ~200 libraries
#                deal.II links loaded, the parameters declared and printed;
#                no MPI)
#   mpi:         impm with a scene file that does not exist (the library
#                loaded, MPI started, the error found, MPI finalised)
#   default:     impm (the built-in default scene: the column, 50 load
#                steps, its files written)
# and the parts by difference.
# Usage: scripts/start_time.sh IMPM [REPEATS]
set -u
impm=$(realpath "$1")
repeats=${2:-11}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
declare -A times
for ((r = 0; r < repeats; ++r)); do
  for part in help parameters mpi default; do
    case $part in
      help) command=("$impm" --help) ;;
      parameters) command=("$impm" --print-parameters) ;;
      mpi) command=("$impm" no_such_scene.prm) ;;
      default) command=("$impm" --overwrite) ;;
    esac
    start=$(date +%s.%N)
    "${command[@]}" > /dev/null 2>&1
    end=$(date +%s.%N)
    times[$part]="${times[$part]:-} $(echo "$end - $start" | bc)"
  done
done
median() { echo "$@" | tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
help=$(median ${times[help]})
parameters=$(median ${times[parameters]})
mpi=$(median ${times[mpi]})
default=$(median ${times[default]})
printf "median of %d runs each (s): help %.3f, parameters %.3f, mpi %.3f, default scene %.3f\n" \
  "$repeats" "$help" "$parameters" "$mpi" "$default"
printf "parts (s): launcher %.3f; loading the library %.3f; starting and ending MPI %.3f; the default scene's run %.3f\n" \
  "$help" "$(echo "$parameters - $help" | bc)" "$(echo "$mpi - $parameters" | bc)" \
  "$(echo "$default - $mpi" | bc)"
