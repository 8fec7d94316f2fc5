#!/usr/bin/env bash
# interrupted_run.sh GRANPIPE WORKDIR
# Before/after of a run killed with SIGKILL: every frame written before the kill reads
# back, the file is marked incomplete, and it can be reprocessed by a pipeline; results.h5
# holds the per-frame rows streamed before the kill (results.partial.h5, marked incomplete).
set -eu
exe=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
"$exe" "$here/long_lattice.json" --out "$work/run" --quiet &
pid=$!
partial="$work/run/frames.partial.h5"
frames=0
for _ in $(seq 1 600); do
  sleep 0.1
  if [ -f "$partial" ]; then
    frames=$("$exe" inspect "$partial" --rows 0 2>/dev/null | sed -n 's/.*: \([0-9]*\) frame(s).*/\1/p' || true)
    [ "${frames:-0}" -ge 5 ] && break
  fi
done
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
echo "before the kill: $frames frames were readable while the run was going"
[ "${frames:-0}" -ge 5 ] || { echo "FAIL: the run never wrote 5 frames"; exit 1; }
[ ! -e "$work/run/frames.h5" ] || { echo "FAIL: a killed run left a frames.h5 that looks complete"; exit 1; }
[ ! -e "$work/run/results.h5" ] || { echo "FAIL: a killed run left a results.h5 that looks complete"; exit 1; }
/usr/bin/python3 - "$work/run/results.partial.h5" "$frames" <<'PY' || { echo "FAIL: results.partial.h5 of the killed run"; exit 1; }
import sys, h5py, numpy as np
path, frames_before = sys.argv[1], int(sys.argv[2])
with h5py.File(path, "r", swmr=True) as f:  # the writer died in SWMR mode
    assert int(f.attrs["complete"]) == 0, "results.h5 of a killed run must say it is incomplete"
    rows = f["packing/per_frame/frame"][:]
    phi = f["packing/per_frame/phi"][:]
    n = min(len(rows), len(phi))  # a row is whole when every column holds it
    assert n >= frames_before - 1, f"{n} rows streamed, {frames_before} frames written"
    assert np.array_equal(rows[:n], np.arange(n)), "rows are frames 0, 1, 2, ... in order"
    assert np.all((phi[:n] > 0.6) & (phi[:n] < 0.75)), "each row holds a jittered fcc packing fraction"
    print(f"results.partial.h5 of the killed run: {n} per-frame rows, marked incomplete")
PY

echo "after the kill:"
"$exe" inspect "$partial" --rows 3 | tee "$work/inspect.txt"
grep -q "INCOMPLETE" "$work/inspect.txt" || { echo "FAIL: not marked incomplete"; exit 1; }
after=$(sed -n 's/.*: \([0-9]*\) frame(s).*/\1/p' "$work/inspect.txt")
[ "$after" -ge "$frames" ] || { echo "FAIL: $after frames after the kill, $frames before"; exit 1; }

cat >"$work/reprocess.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$partial"}}, "analyzers": [{"plugin": "packing"}],
 "output": {"dir": "$work/reprocessed", "save_frames": false}}
JSON
"$exe" "$work/reprocess.json" --quiet
[ -f "$work/reprocessed/results.h5" ] || { echo "FAIL: reprocessing the partial file gave no results"; exit 1; }
echo "reprocessed all $after frames of the interrupted run"
