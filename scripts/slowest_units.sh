#!/usr/bin/env bash
# The slowest units of the last build of a tree, from the compile times the build wrote
# (cmake/time_compile.sh): seconds and object, slowest first, and the sum over every unit.
#
#   scripts/slowest_units.sh [BUILD_DIR (build)] [HOW_MANY (10)]
set -euo pipefail
tree=${1:-build}
count=${2:-10}
times="$tree/compile_times.tsv"
[ -f "$times" ] || { echo "slowest_units: no $times (configure with -DPOLYPLAN_TIME_UNITS=ON and build)" >&2; exit 2; }
# A unit compiled again counts with its last time.
awk -F'\t' '{ last[$2] = $1 } END { for (o in last) printf "%.1f\t%s\n", last[o] / 1000, o }' "$times" |
  sort -rn >"$times.sorted"
head -n "$count" "$times.sorted"
awk -F'\t' '{ sum += $1; n++ } END { printf "%d units, %.0f s of compiling in all\n", n, sum }' "$times.sorted"
rm -f "$times.sorted"
