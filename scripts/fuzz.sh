#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) and runs each for SECONDS
# seconds (default 30) on a seed corpus from data/ and tests/data/. A crash, a sanitizer report,
# an input slower than 10 s or one needing more than 2 GB fails the run; libFuzzer prints the
# input, and it is kept under build-fuzz/findings/. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(world arm path wkt map scenario graph car_path)
jobs=${JOBS:-2}
CXX=clang++ scripts/configure.sh build-fuzz -DCMAKE_BUILD_TYPE=Release -DPOLYPLAN_FUZZ=ON -DPOLYPLAN_BUILD_TESTS=OFF \
  -DPOLYPLAN_BUILD_EXAMPLES=OFF
cmake --build build-fuzz -j"$jobs" --target polyplan_fuzzers

# Seeds: the shipped files each reader reads (small maps only: mutating a megabyte map is slow)
# and the inputs that made a target fail before (tests/data/fuzz/, each also a regression test).
seeds() {
  case "$1" in
    world) ls data/worlds/*.json data/changing_worlds/*.json tests/data/bad/*.json ;;
    arm) ls data/arms/*.json ;;
    path) ls tests/data/paths/*.json ;;
    wkt) ls data/worlds/*.wkt tests/data/bad/*.wkt ;;
    map) ls data/movingai/maps/arena.map data/movingai/maps/den312d.map tests/data/fuzz/*.map ;;
    scenario) ls data/movingai/scenarios/arena.map.scen ;;
    graph) ls data/graphs/small.json ;;
    car_path) ls tests/data/paths/car_*.json ;;
  esac
}

status=0
for target in "${targets[@]}"; do
  work="build-fuzz/runs/$target"
  rm -rf "$work" && mkdir -p "$work/corpus" "$work/seeds" build-fuzz/findings
  seeds "$target" | while read -r f; do cp "$f" "$work/seeds/"; done
  echo "fuzz: $target for ${seconds} s" >&2
  # The new corpus first (libFuzzer writes there), the seeds after it.
  if ! "build-fuzz/fuzz/${target}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
       -print_final_stats=1 -artifact_prefix="build-fuzz/findings/${target}-" "$work/corpus" "$work/seeds" \
       >"$work/log" 2>&1; then
    echo "fuzz: $target FAILED; its log: $work/log" >&2
    grep -E "ERROR|SUMMARY|Test unit written|==ABORTING|#[0-9]+ 0x.* in polyplan::" "$work/log" | cut -c1-300 | head -30 >&2
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/log" | sed "s/^/fuzz: $target /" >&2 || true
done
exit $status
