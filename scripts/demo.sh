#!/usr/bin/env bash
# The main job on a shipped world: installs what is missing, builds the polyplan program, plans
# the exact shortest path of the course's C-space and visibility-graph problem set's two-part robot and draws it in seed004-plan.svg.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh program
# The program with the polygon roadmaps alone (what `polyplan plan` needs here, a third of the
# compile time of every family), and no tests, examples or Python module, which need packages the
# demo does not install; scripts/test.sh turns everything on again in the same tree.
scripts/configure.sh build -DCMAKE_BUILD_TYPE=Release -DPOLYPLAN_FAMILIES=roadmaps \
  -DPOLYPLAN_BUILD_TESTS=OFF -DPOLYPLAN_BUILD_EXAMPLES=OFF -DPOLYPLAN_PYTHON=OFF
cmake --build build -j"${JOBS:-2}" --target polyplan_cli
build/cli/polyplan plan data/worlds/seed004.json --svg seed004-plan.svg
