#!/usr/bin/env bash
# outoftree.sh BUILD_DIR SOURCE_DIR WORKDIR
# Installs granpipe, builds example_plugin/ against it with find_package(granpipe),
# loads it through GRANPIPE_PLUGIN_PATH and runs it in a pipeline whose frames.h5 must
# hold the column the plugin publishes.
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/outoftree/example_plugin" -B "$work/plugin-build" -G Ninja \
      -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/plugin-build" >/dev/null
export GRANPIPE_PLUGIN_PATH="$work/plugin-build"
"$work/prefix/bin/granpipe" describe radius_stats
cat >"$work/pipeline.json" <<JSON
{"source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [3, 3, 3], "radius": 0.25}},
 "analyzers": [{"plugin": "radius_stats", "params": {"scale": 2.0, "r_max": 1.0, "bins": 4}}],
 "output": {"dir": "$work/out"}}
JSON
"$work/prefix/bin/granpipe" "$work/pipeline.json" --quiet
csv="$work/out/radius_stats.scalars.csv"
grep -q "^mean_radius,0.5," "$csv" || { echo "FAIL: mean_radius is not 2 x 0.25:"; cat "$csv"; exit 1; }
grep -q "^particles,27," "$csv" || { echo "FAIL: expected 27 particles:"; cat "$csv"; exit 1; }
# 27 particles x 1 frame of scaled radius 0.5: all in the third of 4 bins of [0, 1).
grep -q "^0.5,0.75,27," "$work/out/radius_stats.radii.csv" ||
  { echo "FAIL: the histogram of radii:"; cat "$work/out/radius_stats.radii.csv"; exit 1; }
# The README shows this plugin's code as it is.
python3 - "$src/README.md" "$src/tests/outoftree/example_plugin/radius_stats.cpp" <<'PY' ||
import sys
readme, code = (open(p).read() for p in sys.argv[1:])
sys.exit(0 if "```cpp\n" + code + "```" in readme else 1)
PY
  { echo "FAIL: README.md does not show tests/outoftree/example_plugin/radius_stats.cpp as it is"; exit 1; }
# The published column is in frames.h5, with its type, unit and description.
"$work/prefix/bin/granpipe" inspect "$work/out/frames.h5" >"$work/inspect.txt"
grep -Eq "^  scaled_radius +real +length +particle radius times scale$" "$work/inspect.txt" ||
  { echo "FAIL: frames.h5 lacks the published column scaled_radius:"; cat "$work/inspect.txt"; exit 1; }
echo "out-of-tree plugin built with find_package(granpipe), loaded and run"
