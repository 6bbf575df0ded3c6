#!/usr/bin/env bash
# Installs the Debian packages of the sets named, those missing only; does nothing when none is.
#
#   scripts/setup.sh program          what the library and the polyplan program build with (the demo)
#   scripts/setup.sh program python   ... and the Python module (scripts/python.sh)
#   scripts/setup.sh                  every set: what scripts/test.sh needs
#   scripts/setup.sh --list SET...    print the packages of the sets, one per line, install nothing
#
# The sets are listed here and nowhere else; each script asks for its own
# (tests/scripts/package_sets_test.sh checks that the demo's stays the program's).
set -euo pipefail

packages_of() {
  case "$1" in
    program)  # the library and the program (clang and ninja: scripts/configure.sh says why)
      echo cmake clang ninja-build make pkg-config \
        libcgal-dev libgmp-dev libmpfr-dev \
        libboost-dev libboost-graph-dev \
        libeigen3-dev \
        nlohmann-json3-dev libcli11-dev \
        libnanoflann-dev ;;
    python)  # the module, its arrays, its plots and its tests
      echo python3 python3-dev python3-pybind11 pybind11-dev \
        python3-numpy python3-matplotlib python3-pytest python3-pil python3-nbclient python3-ipykernel python3-nbformat \
        python3-distributed ;;
    tests)  # the C++ tests, the style check, and rsvg-convert to look at the pictures as PNGs
      echo libgtest-dev clang-format librsvg2-bin ;;
    fuzz)  # the deep run (scripts/test.sh --deep): g++ for the sanitized tree, libFuzzer for the readers'
      echo g++ libclang-rt-14-dev ;;
    bench)  # the Google Benchmark programs (-DPOLYPLAN_BUILD_BENCH=ON)
      echo libbenchmark-dev ;;
    *)
      echo "setup: unknown package set '$1' (program, python, tests, fuzz, bench)" >&2
      return 2 ;;
  esac
}

list=0
if [ "${1:-}" = "--list" ]; then
  list=1
  shift
fi
sets=("$@")
[ ${#sets[@]} -gt 0 ] || sets=(program python tests fuzz bench)
packages=()
for set in "${sets[@]}"; do
  listed=$(packages_of "$set") || exit 2
  read -r -a more <<<"$listed"
  packages+=("${more[@]}")
done
if [ "$list" = 1 ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
