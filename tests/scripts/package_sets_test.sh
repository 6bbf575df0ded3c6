#!/usr/bin/env bash
# The scripts install only what they need: the demo asks scripts/setup.sh for the program's set
# alone, and that set holds nothing of Python, the tests, fuzzing or benchmarks; Python's script
# adds the Python set; each package is in one set.
set -euo pipefail
cd "$(dirname "$0")/../.."
fail() { echo "package_sets: $*" >&2; exit 1; }

asked() {  # the sets a script passes to scripts/setup.sh
  grep -E '^[^#]*scripts/setup\.sh' "$1" | sed -E 's/.*scripts\/setup\.sh//; s/[;&|].*//' | xargs
}
[ "$(asked scripts/demo.sh)" = "program" ] || fail "scripts/demo.sh asks for '$(asked scripts/demo.sh)', not 'program'"
[ "$(asked scripts/python.sh)" = "program python" ] ||
  fail "scripts/python.sh asks for '$(asked scripts/python.sh)', not 'program python'"
[ -z "$(asked scripts/test.sh)" ] || fail "scripts/test.sh asks for '$(asked scripts/test.sh)', not every set"

program=$(scripts/setup.sh --list program)
for unneeded in python3 python3-dev python3-matplotlib python3-numpy python3-pytest pybind11-dev \
  libgtest-dev libbenchmark-dev g++ libclang-rt-14-dev clang-format librsvg2-bin; do
  ! grep -qx -- "$unneeded" <<<"$program" || fail "the program's set holds $unneeded, which the demo does not need"
done
for needed in clang libcgal-dev libboost-graph-dev libcli11-dev nlohmann-json3-dev libeigen3-dev; do
  grep -qx -- "$needed" <<<"$program" || fail "the program's set lacks $needed"
done
grep -qx python3-matplotlib <<<"$(scripts/setup.sh --list python)" || fail "the Python set lacks matplotlib"

duplicates=$(scripts/setup.sh --list | sort | uniq -d)
[ -z "$duplicates" ] || fail "in two sets: $duplicates"
! scripts/setup.sh --list nonsense 2>/dev/null || fail "an unknown set is accepted"
echo "package_sets: the demo installs the program's $(wc -l <<<"$program") packages and nothing else"
