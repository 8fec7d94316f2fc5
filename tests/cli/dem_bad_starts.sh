#!/usr/bin/env bash
# dem_bad_starts.sh GRANPIPE PYTHON SOURCE_DIR WORKDIR
# dem start files the run could not treat soundly are refused with exit 2 and one line
# naming the file, the frame, the particle and what is wrong: a sphere reaching through
# its box's wall by 60 % of its radius (a centre outside the box the reader refuses), two
# spheres overlapping by 70 % of their radius, a frame without particles.
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
expect=$(dirname "$0")/expect_error.sh
rm -rf "$work"
mkdir -p "$work"

# $1.h5 from two_spheres.h5 (a 10-wide box) with sphere 1 at x = $2, or no sphere at all.
make_start() {
  cp "$src/data-samples/two_spheres.h5" "$work/$1.h5"
  "$python" - "$work/$1.h5" "$2" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    if sys.argv[2] == "none":
        for name in ("position", "radius", "species", "velocity"):
            old = f[f"particles/all/{name}/value"]
            shape, dtype = (1, 0) + old.shape[2:], old.dtype
            del f[f"particles/all/{name}/value"]
            f.create_dataset(f"particles/all/{name}/value", shape=shape, dtype=dtype)
    else:
        f["particles/all/position/value"][0, 1, 0] = float(sys.argv[2])
PY
  cat >"$work/$1.json" <<JSON
{"source": {"plugin": "dem", "params": {"initial_file": "$1.h5", "duration": 0.01}}}
JSON
}

make_start outside 9.8
"$expect" 2 '^granpipe: .*/outside\.json: source\.params\.initial_file: .*/outside\.h5: frame 0: particle 1 \(id 1\) at \(9\.8, 5, 5\) reaches 0\.3 past wall x_high \(60 % of its radius\): expected particles inside the container, touching its walls by at most 30 % of their radius$' \
  -- "$exe" validate "$work/outside.json"
make_start overlapping 5.14
"$expect" 2 '^granpipe: .*/overlapping\.json: source\.params\.initial_file: .*/overlapping\.h5: frame 0: particles 0 and 1 \(ids 0 and 1\) overlap by 70 % of the smaller radius: expected overlaps of at most 30 %$' \
  -- "$exe" validate "$work/overlapping.json"
make_start empty none
"$expect" 2 '^granpipe: .*/empty\.json: source\.params\.initial_file: .*/empty\.h5: frame 0: expected at least one particle, got none$' \
  -- "$exe" validate "$work/empty.json"

# A start file that is no H5MD file, or whose box is periodic, is refused naming
# initial_file; initial_frame without initial_file (a bed start) would change nothing.
make_start periodic 5.5
"$python" - "$work/periodic.h5" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["particles/all/box"].attrs["boundary"] = [b"periodic", b"none", b"none"]
PY
"$expect" 2 '^granpipe: .*/periodic\.json: source\.params\.initial_file: .*/periodic\.h5: frame 0: container: x_low: expected a wall or an open side, got a periodic side \(the DEM engine has no periodic boundaries\)$' \
  -- "$exe" validate "$work/periodic.json"
make_start text 5.5
echo "x,y,z" >"$work/text.h5"
"$expect" 2 '^granpipe: .*/text\.json: source\.params\.initial_file: .*/text\.h5: not an HDF5 file \(no HDF5 signature\)$' \
  -- "$exe" validate "$work/text.json"
cat >"$work/bed.json" <<JSON
{"source": {"plugin": "dem", "params": {"bed": {"small": 20}, "initial_frame": 0, "duration": 0.01}}}
JSON
"$expect" 2 '^granpipe: .*/bed\.json: source\.params\.initial_frame: expected it only with initial_file \(a frame of that file\), got 0 without one$' \
  -- "$exe" validate "$work/bed.json"
# A start file without frames (its writer killed before the first) is refused naming
# initial_file, not initial_frame.
make_start no_frames 5.5
"$python" - "$work/no_frames.h5" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    for n in f["particles/all"]:
        g = f["particles/all"][n]
        for k in [k for k in g if k in ("value", "step", "time")]:
            shape, dtype = g[k].shape[1:], g[k].dtype
            del g[k]
            g.create_dataset(k, shape=(0,) + shape, dtype=dtype, maxshape=(None,) + shape)
PY
"$expect" 2 '^granpipe: .*/no_frames\.json: source\.params\.initial_file: .*/no_frames\.h5: expected a file with frames, got none$' \
  -- "$exe" validate "$work/no_frames.json"
