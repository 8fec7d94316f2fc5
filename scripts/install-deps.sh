#!/usr/bin/env bash
# Installs the Debian 12 packages granpipe needs that are missing (and nothing else);
# with --test also what only the test suite uses (Chromium, LIGGGHTS, LAMMPS).
set -euo pipefail
packages=(
  g++ cmake ninja-build ccache git pkg-config clang-format
  libeigen3-dev libcgal-dev libboost-graph-dev libhdf5-dev hdf5-tools libgsl-dev zlib1g-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev libtbb-dev
  python3 python3-h5py python3-numpy python3-matplotlib python3-scipy python3-vtk9 voro++ voro++-dev
)
# The test suite also opens report.html in Chromium, and runs tests/lammps_runs with
# LIGGGHTS and LAMMPS again (data_samples_lammps_runs_unchanged); each test skips, saying
# so, without them.
if [ "${1:-}" = "--test" ]; then
  packages+=(chromium liggghts lammps)
elif [ -n "${1:-}" ]; then
  echo "usage: scripts/install-deps.sh [--test]" >&2
  exit 2
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
