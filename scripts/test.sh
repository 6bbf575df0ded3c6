#!/usr/bin/env bash
# The test command. Installs what is missing, builds in Release and runs the whole CTest suite,
# then prints how long each step took.
#
#   scripts/test.sh          the Release build and every test (a newcomer's command)
#   scripts/test.sh --deep   every test under AddressSanitizer + UndefinedBehaviorSanitizer instead
#                            (one sanitized tree, no Release one), and each reader's libFuzzer
#                            target for FUZZ_SECONDS (15) s (.ci/run asks for this)
#
# SANITIZE=1|0 and FUZZ=1|0 turn either deep step on or off whatever the flag says; JOBS (2) is
# the build's parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
deep=0
for arg in "$@"; do
  case "$arg" in
    --deep) deep=1 ;;
    *) echo "usage: scripts/test.sh [--deep]" >&2; exit 2 ;;
  esac
done
sanitize=${SANITIZE:-$deep}
fuzz=${FUZZ:-$deep}
jobs=${JOBS:-2}

began=$SECONDS
timings=()
step() {  # step NAME COMMAND...: runs the command and keeps its time for the summary
  local name=$1 from=$SECONDS
  shift
  "$@"
  timings+=("$name $((SECONDS - from)) s")
}

# Every part and family on, whatever an earlier scripts/demo.sh or scripts/python.sh left in the
# tree's cache.
release="-DCMAKE_BUILD_TYPE=Release -DPOLYPLAN_FAMILIES=all -DPOLYPLAN_BUILD_TESTS=ON -DPOLYPLAN_BUILD_EXAMPLES=ON \
  -DPOLYPLAN_PYTHON=ON"
step setup scripts/setup.sh
# The style first: it takes seconds, and a file clang-format would change fails the run.
step format scripts/check_format.sh
if [ "$sanitize" = 1 ]; then
  # One tree, sanitized, builds and runs everything: the C++ tests, the examples, and the Python
  # module, whose tests preload AddressSanitizer's runtime into the interpreter
  # (python/CMakeLists.txt). No Release tree: it built the whole library a second time.
  # g++: the Python tests preload g++'s AddressSanitizer runtime (python/CMakeLists.txt).
  step sanitizer-build bash -c "CXX=g++ scripts/configure.sh build-sanitize $release -DPOLYPLAN_SANITIZE=ON && \
    cmake --build build-sanitize -j$jobs"
  step sanitizer-tests env ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-sanitize --output-on-failure -j"$jobs"
else
  step build bash -c "scripts/configure.sh build $release && cmake --build build -j$jobs"
  step tests ctest --test-dir build --output-on-failure -j"$jobs"
fi
if [ "$fuzz" = 1 ]; then
  step fuzz scripts/fuzz.sh "${FUZZ_SECONDS:-15}"
fi
summary=$(IFS=,; echo "${timings[*]}")
echo "test: passed in $((SECONDS - began)) s (${summary//,/, })"
