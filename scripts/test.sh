#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite through CTest; then the same
# suite once more under AddressSanitizer + UndefinedBehaviorSanitizer (skip with SANITIZE=0), less
# the runs that only repeat sampling planners to their time limits on every world and arm (their
# code runs under the sanitizers in the sampling tests kept); then each reader's libFuzzer target
# for FUZZ_SECONDS seconds (default 15; skip with FUZZ=0).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=${JOBS:-2}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"
if [ "${SANITIZE:-1}" = 1 ]; then
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DPOLYPLAN_SANITIZE=ON -DPOLYPLAN_BUILD_EXAMPLES=OFF
  cmake --build build-sanitize -j"$jobs"
  repeats='(Registry/EveryPlannerOnEveryWorld|ArmRegistry/EveryArmPlannerOnEveryArm)\..*/(prm|lazyprm|rrt|rrtstar|rrtconnect)(_on|$)'
  repeats+='|ArmSampling/SamplingPlannerOnArm\.ThreeSeeds|RrtStarConverges|RotationPlanner\.AFinerStep'
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-sanitize --output-on-failure -j"$jobs" -E "$repeats"
fi
if [ "${FUZZ:-1}" = 1 ]; then
  scripts/fuzz.sh "${FUZZ_SECONDS:-15}"
fi
