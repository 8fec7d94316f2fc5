#!/usr/bin/env bash
# dem_blow_up.sh GRANPIPE PYTHON SOURCE_DIR WORKDIR
# A dem run that blows up (two spheres started half a diameter into each other: the spring
# throws them apart far faster than the scene allows) stops with exit 2 and one line naming
# the step, the energy and what to change, and keeps the last good frame it emitted (the
# start) in frames.partial.h5.
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
cp "$src/data-samples/two_spheres.h5" "$work/start.h5"
"$python" - "$work/start.h5" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    x[0, 0, 0], x[0, 1, 0] = 4.75, 5.25
    f["particles/all/velocity/value"][...] = 0.0
PY
cat >"$work/blow_up.json" <<JSON
{"source": {"plugin": "dem", "params": {"initial_file": "start.h5", "duration": 1.0, "save_every": 500}},
 "output": {"save_frames": true}}
JSON
fail() { echo "FAIL: $*"; exit 1; }
status=0
"$exe" "$work/blow_up.json" --quiet --threads 1 --out "$work/out" 2>"$work/stderr" || status=$?
[ "$status" = 2 ] || fail "expected exit 2, got $status"
[ "$(wc -l <"$work/stderr")" = 1 ] || fail "expected one line on stderr, got: $(cat "$work/stderr")"
grep -Eq '^granpipe: .*/blow_up\.json: source: dem: step 500 \(t = 0\.1\): kinetic energy [0-9.e+]+ exceeds [0-9.e+]+: the run blew up; reduce dt \(now 0\.0002\) against the shortest contact time, or the initial overlaps$' "$work/stderr" ||
  fail "unexpected message: $(cat "$work/stderr")"
"$exe" inspect "$work/out/frames.partial.h5" | grep -q '1 frame(s), N = 2' ||
  fail "the last good frame is not in frames.partial.h5: $("$exe" inspect "$work/out/frames.partial.h5" | head -1)"
echo "the blow-up stopped the run with exit 2 and kept the start frame"
