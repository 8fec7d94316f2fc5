#!/usr/bin/env bash
# The README's quick start.
#   scripts/quickstart.sh          install what is missing, build (Release), run the main pipeline
#   scripts/quickstart.sh --test   the same, then the whole test suite (ctest)
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-run}
case "$mode" in run|--test) ;; *) echo "usage: scripts/quickstart.sh [--test]" >&2; exit 2 ;; esac

if [ "$mode" = "--test" ]; then scripts/install-deps.sh --test; else scripts/install-deps.sh; fi
jobs=$(nproc)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"

if [ "$mode" = "--test" ]; then
  ctest --test-dir build --output-on-failure -j "$jobs"
else
  # The main job: the Brazil-nut DEM to cycle 10.5, force networks and the multipass MST.
  exec build/bin/granpipe pipelines/bnp_mst.json --out out/bnp_mst --overwrite --threads "$jobs"
fi
