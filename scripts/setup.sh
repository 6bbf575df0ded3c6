#!/usr/bin/env bash
# Installs the Debian packages polyplan builds with, if any is missing; does nothing otherwise.
set -euo pipefail
packages=(
  cmake g++ make pkg-config
  libcgal-dev libgmp-dev libmpfr-dev      # exact geometry and its numbers
  libboost-dev libboost-graph-dev         # graph search
  libeigen3-dev                           # arm kinematics
  nlohmann-json3-dev libcli11-dev         # files and command line
  libnanoflann-dev                        # nearest neighbours
  libgtest-dev libbenchmark-dev           # tests and benchmarks
  clang libclang-rt-14-dev                # libFuzzer, for the readers' fuzz targets
  clang-format                            # the style check (scripts/check_format.sh, .clang-format)
  librsvg2-bin                            # rsvg-convert: look at the SVGs as PNGs
  python3 python3-dev python3-pybind11 pybind11-dev   # the Python module
  python3-numpy python3-matplotlib python3-pytest     # its arrays, plots and tests
)
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
