#!/usr/bin/env bash
# dem_start_files.sh GRANPIPE EXPECT PYTHON PROJECT WORKDIR
# What a dem run takes from its start file, or refuses: a file without radii (once read as
# spheres of radius 0.5), one without species for a table of two (once all species 0), a
# frame saved mid-cycle (once put back at rest, its bed then floating above the base); the
# start's particle ids kept in every frame (once renumbered 0..N-1).
set -eu
exe=$1 expect=$2 python=$3 project=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
PYTHONPATH=$here "$python" - "$work" <<'PY'
import sys

import h5py
import numpy as np
from foreign_h5md import write_h5md

work = sys.argv[1]
centres = np.array([[3.0, 5.0, 0.5], [7.0, 5.0, 0.5]])
write_h5md(f"{work}/no_radius.h5", centres, [10.0] * 3, "none", "dem_start_files.sh")
write_h5md(f"{work}/no_species.h5", centres, [10.0] * 3, "none", "dem_start_files.sh",
           radius=np.array([0.5, 0.5]))
with h5py.File(f"{work}/no_species.h5", "r+") as f:
    f["particles/all"].copy("radius", "id")
    f["particles/all/id/value"][...] = 0
    del f["particles/all/id/value"]
    f["particles/all/id"].create_dataset("value", data=np.array([[17, 42]], dtype="i8"))
PY
# A short dem run from a file, frames saved: "${run[@]}" NAME FILE [--set ...].
run=("$BASH" "$here/dem_start_run.sh" "$exe" "$project" "$work")
"$expect" 2 "no_radius\.h5: frame 0: expected radii \(a radius element of its particles\), got none$" \
  -- "${run[@]}" no_radius "$work/no_radius.h5"
two_species=(--set 'source.params.species=[{"name": "a", "density": 1.91}, {"name": "b", "density": 1.91}]')
"$expect" 2 "no_species\.h5: frame 0: expected species \(a species element of its particles\) for a table of 2 species, got none$" \
  -- "${run[@]}" no_species_two "$work/no_species.h5" "${two_species[@]}"
"$expect" 2 "bnp_t10\.h5: frame 0: expected its walls where the drive puts them at t = 0 \(offset \(0, 0, 0\), velocity \(0, 0, 0\); the run starts them there and its clock at 0\), got offset \(0, 0, 9\.1[0-9]*\) and velocity \(0, 0, 4\.9[0-9]*\)$" \
  -- "${run[@]}" moving "$project/data-samples/bnp_t10.h5" "${two_species[@]}"
# A sine drive stopped after whole periods leaves its walls A sin(2 pi n) off, 1e-18 and not
# 0: rounding, and the run's last frame a start like any other.
cat >"$work/sine.json" <<JSON
{"name": "sine", "source": {"plugin": "dem", "params": {"bed": {"small": 40},
 "drive": {"form": "sine", "amplitude": 0.01, "frequency": 50, "periods": 1},
 "dt": 2e-4, "duration": 0.03, "save_every": 50}}, "output": {"dir": "$work/sine"}}
JSON
"$exe" "$work/sine.json" --quiet --no-report
"${run[@]}" after_sine "$work/sine/frames.h5"
# A container at rest starts any drive, a sine drive's too (its walls set off at A w).
"${run[@]}" rest_then_sine "$work/no_species.h5" \
  --set 'source.params.drive={"form": "sine", "amplitude": 0.001, "frequency": 5}'
"${run[@]}" ids "$work/no_species.h5"
"$python" - "$work/ids/frames.h5" <<'PY'
import sys

import h5py

with h5py.File(sys.argv[1], "r") as f:
    ids = f["particles/all/id/value"][...]
if ids.shape[0] < 2 or not (ids == [17, 42]).all():
    sys.exit(f"FAIL: the start's ids 17, 42 not kept in every frame: {ids.tolist()}")
PY
echo "dem start files: radii and species required, a moving container refused, ids kept"
