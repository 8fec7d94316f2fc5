#!/usr/bin/env bash
# bad_particles.sh GRANPIPE EXPECT PYTHON WORKDIR
# Another tool's H5MD files with overlapping and with NaN particles, reprocessed and
# inspected: exit 2 and one line naming the file, the frame and the particles.
set -eu
exe=$1 expect=$2 python=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
"$python" "$here/make_bad_particles.py" "$work"
for kind in overlapping nan nan_first; do
  cat >"$work/$kind.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/$kind.h5", "radius": 0.5}},
 "analyzers": [{"plugin": "packing"}], "output": {"dir": "$work/out_$kind"}}
JSON
done
"$expect" 2 "overlapping\.h5: frame 0: particles 0 and 1 \(ids 0, 1\) overlap by 1 of the smaller radius" \
  -- "$exe" "$work/overlapping.json"
"$expect" 2 "nan\.h5: frame 0: particle 1 \(id 1\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" "$work/nan.json"
# Walls are placed from the particle centres: the NaN is still the frame check's to name.
"$expect" 2 "nan_first\.h5: frame 0: particle 0 \(id 0\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" "$work/nan_first.json"
"$expect" 2 "^granpipe: $work/nan_first\.h5: frame 0: particle 0 \(id 0\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" inspect "$work/nan_first.h5"
[ ! -e "$work/out_nan/results.h5" ] || { echo "FAIL: a refused run left results.h5"; exit 1; }
echo "overlapping and NaN particles refused"
