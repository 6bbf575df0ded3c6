#!/usr/bin/env bash
# Configures a build tree the way every script does:
#
#   scripts/configure.sh BUILD_DIR [CMAKE_OPTION...]
#
# A new tree gets clang++, which compiles CGAL's templates in three fifths of g++'s time, and
# Ninja, which compiles a library's units while the libraries it links are still linking, so that
# both jobs stay busy (docs/test_time.md). CXX and CMAKE_GENERATOR choose others; a tree configured
# before keeps its compiler and generator, whatever they say.
set -euo pipefail
cd "$(dirname "$0")/.."
tree=$1
shift
generator=${CMAKE_GENERATOR:-Ninja}
if [ "$generator" = Ninja ] && ! command -v ninja >/dev/null; then generator="Unix Makefiles"; fi
CXX=${CXX:-clang++} CMAKE_GENERATOR=$generator cmake -S . -B "$tree" "$@" >/dev/null
