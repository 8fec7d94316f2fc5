#!/usr/bin/env bash
# interrupted_run.sh GRANPIPE WORKDIR
# Before/after of a run killed with SIGKILL: every frame written before the kill reads
# back, the file is marked incomplete, and it can be reprocessed by a pipeline.
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
[ ! -e "$work/run/results.h5" ] || { echo "FAIL: a killed run left results.h5"; exit 1; }

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
