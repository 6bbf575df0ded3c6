#!/usr/bin/env bash
# The main job on a shipped world: installs what is missing, builds the polyplan program, builds
# the exact C-space of the seed 004 world and writes its picture to seed004-cspace.svg.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"${JOBS:-2}" --target polyplan_cli
build/cli/polyplan cspace data/worlds/seed004.json --svg seed004-cspace.svg
