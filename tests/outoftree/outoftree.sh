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
 "analyzers": [{"plugin": "radius_stats", "params": {"scale": 2.0, "r_max": 1.0, "bins": 4}},
               {"plugin": "height_fit"}],
 "output": {"dir": "$work/out"}}
JSON
"$work/prefix/bin/granpipe" "$work/pipeline.json" --quiet
csv="$work/out/radius_stats.scalars.csv"
grep -q "^mean_radius,0.5," "$csv" || { echo "FAIL: mean_radius is not 2 x 0.25:"; cat "$csv"; exit 1; }
grep -q "^particles,27," "$csv" || { echo "FAIL: expected 27 particles:"; cat "$csv"; exit 1; }
# 27 particles x 1 frame of scaled radius 0.5: all in the third of 4 bins of [0, 1).
grep -q "^0.5,0.75,27," "$work/out/radius_stats.radii.csv" ||
  { echo "FAIL: the histogram of radii:"; cat "$work/out/radius_stats.radii.csv"; exit 1; }
# A radius a rounding below r_max is counted in the last bin (r / width rounds up to the bin
# count there: the example wrote past its histogram and the run died in free()).
cat >"$work/edge.json" <<JSON
{"source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [3, 3, 3], "radius": 0.49999999999999994}},
 "analyzers": [{"plugin": "radius_stats", "params": {"scale": 2.0, "r_max": 1.0, "bins": 3}}],
 "output": {"dir": "$work/edge", "save_frames": false}}
JSON
"$work/prefix/bin/granpipe" "$work/edge.json" --quiet
python3 - "$work/edge/radius_stats.radii.csv" <<'PY' || { echo "FAIL: the radius just below r_max"; exit 1; }
import csv, sys
rows = [r for r in csv.reader(l for l in open(sys.argv[1]) if not l.startswith("#"))][1:]
assert [float(r[2]) for r in rows] == [0, 0, 27], rows
PY
# The core's curve fitter, linked by DEPENDS GSL: equal radii are a line of slope 0.
python3 - "$work/out/height_fit.radius_line.csv" <<'PY' || { echo "FAIL: the fit of height_fit"; exit 1; }
import csv, sys
rows = {r[0]: r for r in csv.reader(l for l in open(sys.argv[1]) if not l.startswith("#"))}
assert abs(float(rows["a"][1]) - 0.25) < 1e-9 and abs(float(rows["b"][1])) < 1e-9, rows
PY
# The README shows the plugins' code as it is.
for example in radius_stats contact_forces; do
  python3 - "$src/README.md" "$src/tests/outoftree/example_plugin/$example.cpp" <<'PY' ||
import sys
readme, code = (open(p).read() for p in sys.argv[1:])
sys.exit(0 if "```cpp\n" + code + "```" in readme else 1)
PY
    { echo "FAIL: README.md does not show tests/outoftree/example_plugin/$example.cpp as it is"; exit 1; }
done
# The contact example on saved DEM frames: normal forces read, the fabric tensor's trace 1.
cat >"$work/contacts.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$src/data-samples/bnp_t10.h5", "max_overlap": 0.05}},
 "analyzers": [{"plugin": "contact_forces"}], "output": {"dir": "$work/contacts", "save_frames": false}}
JSON
"$work/prefix/bin/granpipe" "$work/contacts.json" --quiet
python3 - "$work/contacts" <<'PY' || { echo "FAIL: the contact example's results"; exit 1; }
import csv, sys
out = sys.argv[1]
scalars = {r[0]: r for r in csv.reader(l for l in open(f"{out}/contact_forces.scalars.csv") if not l.startswith("#"))}
assert float(scalars["contacts"][1]) > 1000 and float(scalars["normal_force"][1]) > 0, scalars
rows = [r for r in csv.reader(l for l in open(f"{out}/contact_forces.fabric.csv") if not l.startswith("#"))][1:]
trace = sum(float(rows[a][1 + a]) for a in range(3))
assert abs(trace - 1) < 1e-9, f"fabric tensor trace {trace}"
print(f"contact_forces: {scalars['contacts'][1]} contacts, fabric trace {trace}")
PY
# The published column is in frames.h5, with its type, unit and description.
"$work/prefix/bin/granpipe" inspect "$work/out/frames.h5" >"$work/inspect.txt"
grep -Eq "^  scaled_radius +real +length +particle radius times scale$" "$work/inspect.txt" ||
  { echo "FAIL: frames.h5 lacks the published column scaled_radius:"; cat "$work/inspect.txt"; exit 1; }
echo "out-of-tree plugin built with find_package(granpipe), loaded and run"
