#!/usr/bin/env bash
# dem_blow_up.sh GRANPIPE PYTHON SOURCE_DIR WORKDIR
# dem runs that go unsound stop with exit 2 and one line naming the step and what to change,
# and keep the last good frame they emitted (the start) in frames.partial.h5: a
# pass-through, two spheres meeting at a relative speed of 1e3, far faster than their
# stiffness can stop, stopped in the step their overlap passes 30 % of the radius. (Two
# spheres started 0.1 into each other spring apart with the energy of their start: no
# blow-up, tests/plugins/test_dem_source.cpp.)
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# start.h5 from two_spheres.h5 with the spheres at x0, x1 moving at vx0, vx1.
make_start() {
  cp "$src/data-samples/two_spheres.h5" "$work/$1.h5"
  "$python" - "$work/$1.h5" "$2" "$3" "$4" "$5" <<'PY'
import sys
import h5py
x0, x1, v0, v1 = map(float, sys.argv[2:6])
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    x[0, 0, 0], x[0, 1, 0] = x0, x1
    v = f["particles/all/velocity/value"]
    v[...] = 0.0
    v[0, 0, 0], v[0, 1, 0] = v0, v1
PY
  cat >"$work/$1.json" <<JSON
{"source": {"plugin": "dem", "params": {"initial_file": "$1.h5", "duration": 1.0, "save_every": 500,
                                        "gravity": [0, 0, 0]}},
 "output": {"save_frames": true}}
JSON
}

# Runs case $1 and checks exit 2, one line matching $2, and the start kept.
expect_stop() {
  local status=0
  "$exe" "$work/$1.json" --quiet --threads 1 --out "$work/out_$1" 2>"$work/$1.stderr" || status=$?
  [ "$status" = 2 ] || fail "$1: expected exit 2, got $status"
  [ "$(wc -l <"$work/$1.stderr")" = 1 ] || fail "$1: expected one line on stderr, got: $(cat "$work/$1.stderr")"
  grep -Eq "$2" "$work/$1.stderr" || fail "$1: unexpected message: $(cat "$work/$1.stderr")"
  "$exe" inspect "$work/out_$1/frames.partial.h5" | grep -q '1 frame(s), N = 2' ||
    fail "$1: the last good frame is not in frames.partial.h5: $("$exe" inspect "$work/out_$1/frames.partial.h5" | head -1)"
}

make_start pass_through 2 8 500 -500
expect_stop pass_through '^granpipe: .*/pass_through\.json: source: dem: step 26 \(t = 0\.0052\): particles 0 and 1 overlap by [0-9.]+ % of the smaller radius \(a sound run stays within 30 %\): the contacts are too soft for the speed of impact, or dt too long; raise k_n, lower the speeds or reduce dt \(now 0\.0002\)$'
echo "the pass-through stopped its run with exit 2 and kept the start frame"
