#!/usr/bin/env bash
# Makes `import polyplan` work for Debian's python3: installs the Debian packages that are missing
# (scripts/setup.sh: pybind11, numpy, matplotlib, pytest and the C++ ones), builds the module and
# the program in build/ (Release) and installs the package, with the polyplan libraries it links
# and the program (python3 -m polyplan), into python3's site folder (Debian:
# /usr/local/lib/python3.X/dist-packages/polyplan).
#
#   scripts/python.sh            PYTHON (/usr/bin/python3) names another interpreter
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-/usr/bin/python3}
scripts/setup.sh program python
# Every planner family, whatever scripts/demo.sh left in the tree's cache.
scripts/configure.sh build -DCMAKE_BUILD_TYPE=Release -DPOLYPLAN_FAMILIES=all -DPOLYPLAN_PYTHON=ON \
  -DPOLYPLAN_BUILD_TESTS=OFF -DPython_EXECUTABLE="$python"
cmake --build build -j"${JOBS:-2}" --target _polyplan polyplan_cli
target=$(grep '^POLYPLAN_PYTHON_DIR:' build/CMakeCache.txt | cut -d= -f2-)
sudo=""
if [ ! -w "$(dirname "$target")" ] && [ ! -w "$target" ] && [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo mkdir -p "$target"
$sudo cmake --install build --component python
cd /  # not the source tree: the installed package, not python/polyplan
"$python" -c 'import polyplan; print("python: import polyplan works:", polyplan.__file__)'
